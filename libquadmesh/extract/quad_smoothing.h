// Smoothing of the worst quads (method.md section 10 measures Verdict's scaled
// Jacobian; this improves it, as sound_scaled_jacobian of quad_quality.h, without
// touching the grid's structure).
//
// Beside an interior zero on a curved part, the 4(m + 1) quads around the
// valence-4(m + 1) vertex are large and lean away from its normal; the lattice
// puts their other corners where the map is compressed. Moving those corners,
// on the surface, towards the mean of their neighbours raises the worst corners.
// Only regular interior points move (boundary points and the singular vertices,
// which sit on lattice points at the zeros, stay), each move is kept only if it
// raises the smallest scaled Jacobian of the quads around the point, and every
// moved point is put back on S by closest point.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"

#include <vector>

namespace qm {

struct QuadSmoothingOptions {
  double below = 0.5;  ///< quads whose scaled Jacobian is below this have their points moved
  int rounds = 20;     ///< at most; a round that moves nothing ends it
  /// No point ends farther than this from where the extraction put it (0: no
  /// limit): large quads (a protrusion) would otherwise slide along S and cut
  /// across it more.
  double max_move = 0;
};

struct QuadSmoothingReport {
  std::size_t moved_points = 0;  ///< distinct points moved
  double min_before = 0;         ///< smallest sound_scaled_jacobian (quad_quality.h), before
  double min_after = 0;          ///< and after
};

/// The smallest sound_scaled_jacobian (quad_quality.h: Verdict's scaled Jacobian
/// capped by the normal consistency against `normals`, one per point) of the quads
/// `around` (their indices) with point v at p: how a trial move of v is judged
/// here and by the angle smoothing.
double worst_corner_jacobian(const LatticeQuads& quads, const std::vector<int>& around, int v, const Vec3& p,
                             const std::vector<Vec3>& normals);

/// Precondition: `boundary_loop_of_point` has one entry per point (-1: interior).
/// Points move on `surface`; their `locations` become face locations there.
QuadSmoothingReport smooth_worst_quads(const TriangleSoup& surface, LatticeQuads& quads,
                                       const std::vector<int>& boundary_loop_of_point,
                                       const QuadSmoothingOptions& options = {});

}  // namespace qm
