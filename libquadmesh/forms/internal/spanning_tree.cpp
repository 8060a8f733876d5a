#include "libquadmesh/forms/internal/spanning_tree.h"

#include <queue>

namespace qm {

VertexTree vertex_spanning_tree(const Mesh& m) {
  VertexTree tree;
  tree.parent.assign(m.number_of_vertices(), -1);
  tree.depth.assign(m.number_of_vertices(), -1);
  tree.edge_used.assign(m.number_of_edges(), 0);
  std::queue<int> queue;
  queue.push(0);
  tree.depth[0] = 0;
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (Mesh::Halfedge_index h : m.halfedges_around_target(m.halfedge(Mesh::Vertex_index(v)))) {
      const int u = static_cast<int>(m.source(h));
      if (tree.depth[u] >= 0) continue;
      tree.depth[u] = tree.depth[v] + 1;
      tree.parent[u] = v;
      tree.edge_used[m.edge(h)] = 1;
      queue.push(u);
    }
  }
  return tree;
}

}  // namespace qm
