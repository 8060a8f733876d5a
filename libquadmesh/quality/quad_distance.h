// The two-sided Hausdorff distance of a polygon mesh (the quads) from the surface
// it meshes, as the quality report gives it and as the pipeline judges candidates
// by it: one measure for both, so that what was judged within the criterion is
// what the report reads.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/quality/hausdorff.h"

#include <vector>

namespace qm {

struct PolygonMesh;

struct QuadDistance {
  HausdorffDistance distance;   ///< forward: from the quads to S; backward: from S to the quads
  Vec3 farthest = Vec3::Zero();  ///< where the larger of the two is reached
};

/// The polygons split into fans from their first corner (quads along the diagonal
/// 0-2), sampled with surface_samples() and with each polygon's centroid; S sampled
/// with surface_samples(), or its points alone where its mean edge is at most a
/// quarter of the fans' (a scan far finer than the quads: its points are then as
/// dense as the quads' own samples, and the distance is 1-Lipschitz; a
/// million-triangle input had 10 million samples otherwise). NaN distances
/// without polygons or triangles.
QuadDistance quad_distance(const PolygonMesh& mesh, const TriangleSoup& surface);

}  // namespace qm
