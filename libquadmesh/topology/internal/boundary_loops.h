// Boundary loops as ordered cycles of points.
//
// A boundary edge has one triangle. Each open fan of a point holds exactly two
// boundary edges, so walking "into a point through one boundary edge, out
// through the other boundary edge of the same fan" follows a loop even where
// two loops touch at a pinched point. On a consistently oriented soup the loops
// are listed in the direction of their triangles' halfedges (the surface on the
// left).
#pragma once

#include "libquadmesh/topology/internal/vertex_fans.h"

#include <vector>

namespace qm {

struct BoundaryLoops {
  std::vector<std::vector<int>> loops;  ///< points of each loop, in order
  std::vector<std::vector<int>> edges;  ///< edge ids of each loop: edges[l][i] joins loops[l][i], loops[l][i+1]
  bool well_formed = true;              ///< every open fan had exactly two boundary edges
  /// Loops that share a point (only at non-manifold points) form one connected
  /// component of the boundary; loop_component[l] numbers them 0..component_count-1.
  /// On a manifold surface every loop is its own component.
  std::vector<int> loop_component;
  int component_count = 0;
};

BoundaryLoops boundary_loops(const TriangleSoup& soup, const EdgeIncidence& inc,
                             const VertexFans& fans);

}  // namespace qm
