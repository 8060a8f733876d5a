// The scale s of the grid, chosen where the periods round best (method.md
// section 7, "beyond the paper").
//
// The requested size fixes s only roughly (issue 4 allows the quad count 15% of
// play), while the rounding of the periods of s h to integers (constraints 1 and
// 2) is what adds the distortion: a period p rounded by r adds a correction form
// of period r, whose energy grows with r^2. Every period scales with s, so over a
// small window of scales the sum of squared rounding residuals
//   E(s) = sum_k (s p_k - round(s p_k))^2
// changes from near its worst to near 0 (a plate whose bridges round by 0.46 cell
// shears every quad by a few degrees). The periods p_k are those of h on the loops
// of H_1(S) that quantize() rounds: the U- and V-periods of the handle loops, the
// U-periods of boundaries 1..n-1 and the V-integrals of the bridges.
#pragma once

#include "libquadmesh/param/quantization.h"

#include <vector>

namespace qm {

/// The periods of `h` that the quantization rounds (order: handle U, handle V,
/// boundary U, bridge V). Precondition: the loops lie on `adjacency`'s surface,
/// the one `h` is defined on.
std::vector<double> rounded_periods(const SurfaceAdjacency& adjacency, const FaceMap& h, const NamedLoops& loops);

/// E(s) above, with round_nonzero (quantization.h) as the rounding.
double rounding_residual(const std::vector<double>& periods, double s);

/// The s in [s0 (1 - window), s0 (1 + window)] with the smallest E(s), sampled
/// finely enough to resolve the fastest-turning period; among equal residuals the
/// one nearest s0. Returns s0 when there is no period.
double rounding_scale(const std::vector<double>& periods, double s0, double window);

}  // namespace qm
