// Quad size against the requested size (issue 18; method.md section 11): the share
// of quads whose size lies within [0.5, 2] x the target, and the largest ratio. A
// quad's size is the mean of its edge lengths. Gmsh's meshes keep every quad in
// the band; the Abel differential's quad size 1/(s|h|) does not on arms, shafts
// and at CAD corners.
#pragma once

#include "libquadmesh/quality/quad_quality.h"

#include <vector>

namespace qm {

/// The band's ends, as multiples of the target size.
constexpr double size_band_low = 0.5;
constexpr double size_band_high = 2.0;
/// The largest quad issue 18's acceptance allows, as a multiple of the target size.
constexpr double size_ratio_limit = 3.0;
/// The share of quads within [size_band_low, size_band_high] x the target issue
/// 18's acceptance asks for (below it, `auto` tries cones).
constexpr double size_band_goal = 0.9;

struct SizeBand {
  std::size_t quads = 0;       ///< faces with 4 corners measured
  double share_in_band = 0;    ///< of those, the share within [low, high] x target (NaN without quads)
  double max_ratio = 0;        ///< largest size / target
  double min_ratio = 0;        ///< smallest size / target
};

/// Precondition: target > 0.
SizeBand quad_size_band(const PolygonMesh& mesh, double target);

/// Whether quads of this size band meet issue 18's acceptance: size_band_goal of
/// them in the band and none above size_ratio_limit x the target.
bool in_size_band(const SizeBand& band);

/// Each quad's size / target, in face order (faces with 4 corners only).
/// Precondition: target > 0.
std::vector<double> quad_size_ratios(const PolygonMesh& mesh, double target);

/// The share of `ratios` within [low, high] once each is multiplied by `factor`
/// (quads on a lattice `factor` times coarser), and the largest: what a lattice
/// of another scale would give, were the quads the same otherwise. NaN share
/// without ratios.
SizeBand scaled_size_band(const std::vector<double>& ratios, double factor);

}  // namespace qm
