// Untangling by a regularized barrier (method.md section 9: flipped triangles
// "must not produce broken output: detect, repair or refine locally").
//
// Near a zero the quantized map is compressed (|h| -> 0), so the least-squares
// solve leaves folds a few rings away from the cone, where moving one vertex at a
// time (untangle.h) finds no position that unfolds its star. Here every free
// vertex of a region around the folds moves at once: the region's map minimizes
// the conformal (MIPS) energy relative to each triangle's 3D shape,
//   sum_t area_t |J_t|_F^2 / chi(det J_t, eps),
//   chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2,
// a barrier that is finite for folded triangles while eps > 0 and tends to
// |J|^2 / det J as eps -> 0 (the idea of Garanzha et al., "Foldover-free maps in
// 50 lines of code", 2021). eps shrinks after each minimization until every
// determinant is positive. The region (the folds grown by a few rings, more when
// that is not enough) keeps its outer ring fixed; boundary vertices of S move only
// along their boundary line (U), the cones not at all. As in untangle.h, a move
// shifts every chart copy of a vertex by the same vector, so the seams stay
// integer translations.
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/param/untangle.h"

namespace qm {

/// The image triangle is positive with a margin that survives the extraction's
/// rounding of every image point to 2^-30 lattice units (extract/lattice_quads.h).
bool safely_positive(const CornerValues& c);

/// Untangles every triangle that is not safely positive. `pinned[v]` != 1: v may move (1: a cone, fixed). Modifies `param` in place;
/// a region whose folds remain is left as it was. `moved_vertices` counts the free
/// vertices of the regions, `rounds` the region sizes tried.
UntangleReport untangle_by_barrier(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                                   const std::vector<char>& pinned);

}  // namespace qm
