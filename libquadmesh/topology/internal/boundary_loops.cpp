#include "libquadmesh/topology/internal/boundary_loops.h"

#include "libquadmesh/core/internal/union_find.h"

#include <array>

namespace qm {

BoundaryLoops boundary_loops(const TriangleSoup& soup, const EdgeIncidence& inc,
                             const VertexFans& fans) {
  BoundaryLoops result;
  // For each fan, its (up to two) boundary edges.
  std::vector<std::array<int, 2>> fan_edges(static_cast<std::size_t>(fans.fan_count()),
                                            std::array<int, 2>{-1, -1});
  auto add = [&](int fan, int e) {
    auto& slot = fan_edges[fan];
    if (slot[0] < 0) {
      slot[0] = e;
    } else if (slot[1] < 0) {
      slot[1] = e;
    } else {
      result.well_formed = false;
    }
  };
  // The boundary halfedge of each boundary edge.
  std::vector<int> boundary_halfedge(inc.edge_count(), -1);
  for (std::size_t e = 0; e < inc.edge_count(); ++e) {
    if (!inc.is_boundary(static_cast<int>(e))) continue;
    const int h = inc.halfedges[inc.offsets[e]];
    boundary_halfedge[e] = h;
    const int f = h / 3, k = h % 3;
    add(fans.corner_fan[3 * f + k], static_cast<int>(e));            // corner at the source
    add(fans.corner_fan[3 * f + (k + 1) % 3], static_cast<int>(e));  // corner at the target
  }
  auto fan_of_edge_end = [&](int e, int p) {
    const int h = boundary_halfedge[e];
    const int f = h / 3, k = h % 3;
    return soup.triangles[f][k] == p ? fans.corner_fan[3 * f + k]
                                     : fans.corner_fan[3 * f + (k + 1) % 3];
  };

  std::vector<char> used(inc.edge_count(), 0);
  for (std::size_t start = 0; start < inc.edge_count(); ++start) {
    if (boundary_halfedge[start] < 0 || used[start]) continue;
    std::vector<int> points, edges;
    int e = static_cast<int>(start);
    int p = halfedge_source(soup, boundary_halfedge[e]);
    while (e >= 0 && !used[e]) {
      used[e] = 1;
      points.push_back(p);
      edges.push_back(e);
      const int q = inc.edges[e][0] == p ? inc.edges[e][1] : inc.edges[e][0];
      const auto& pair = fan_edges[fan_of_edge_end(e, q)];
      const int next = pair[0] == e ? pair[1] : pair[0];
      if (next < 0) result.well_formed = false;
      if (next == static_cast<int>(start)) break;
      p = q;
      e = next;
    }
    result.loops.push_back(std::move(points));
    result.edges.push_back(std::move(edges));
  }
  UnionFind touching(result.loops.size());
  std::vector<int> loop_at(soup.points.size(), -1);
  for (std::size_t l = 0; l < result.loops.size(); ++l)
    for (int p : result.loops[l]) {
      if (loop_at[p] >= 0) touching.unite(loop_at[p], static_cast<int>(l));
      loop_at[p] = static_cast<int>(l);
    }
  result.component_count = touching.labels(result.loop_component);
  return result;
}

}  // namespace qm
