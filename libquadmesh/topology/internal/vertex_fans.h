// Vertex fans: the triangles around a point, grouped into the pieces that are
// connected through manifold edges at that point.
//
// A point is vertex-manifold when all its triangles form one fan. A fan is closed
// (interior point) or open (boundary point, two boundary edges). Pinched
// boundaries and bow-ties show up as points with two or more fans.
#pragma once

#include "libquadmesh/topology/internal/edge_incidence.h"

#include <vector>

namespace qm {

struct VertexFans {
  std::vector<int> corner_fan;  ///< fan of corner c = 3 f + k (the corner of f at triangles[f][k])
  std::vector<int> fan_point;   ///< point of each fan
  std::vector<int> fans_per_point;

  int fan_count() const { return static_cast<int>(fan_point.size()); }
};

/// Groups the corners of every point into fans. Only edges with exactly two
/// triangles join corners, so the triangles beyond the second on a
/// non-manifold edge start fans of their own.
VertexFans vertex_fans(const TriangleSoup& soup, const EdgeIncidence& inc);

}  // namespace qm
