// A point of S nearest to a guess, with where it lies on S: what the refinement
// and the smoothing give every quad point they place or move.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <utility>

namespace qm {

/// Barycentric coordinates of p in the triangle (a, b, c), from the projection of
/// p onto its plane; (1, 0, 0) for a degenerate triangle.
std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// The closest point of S (`tree` built on `surface`'s triangles, ids = triangle
/// indices) to `guess`, as a face location of `surface`.
std::pair<Vec3, SurfaceLocation> closest_location(const TriangleSoup& surface, const TriangleTree& tree,
                                                  const Vec3& guess);

}  // namespace qm
