#include "libquadmesh/forms/named_loops.h"

#include "libquadmesh/forms/internal/spanning_tree.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>

namespace qm {

namespace {

double length(const Mesh& m, Mesh::Halfedge_index h) {
  return std::sqrt(CGAL::squared_distance(m.point(m.source(h)), m.point(m.target(h))));
}

std::vector<std::vector<int>> border_loops(const Mesh& m, std::vector<int>& loop_of_halfedge) {
  std::vector<std::vector<int>> loops;
  loop_of_halfedge.assign(m.number_of_halfedges(), -1);
  for (Mesh::Halfedge_index h : m.halfedges()) {
    if (!m.is_border(h) || loop_of_halfedge[h] >= 0) continue;
    std::vector<int> loop;
    for (Mesh::Halfedge_index g : m.halfedges_around_face(h)) {
      loop_of_halfedge[g] = static_cast<int>(loops.size());
      loop.push_back(static_cast<int>(m.source(g)));
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

std::vector<std::vector<int>> bridge_paths(const Mesh& m, const std::vector<std::vector<int>>& loops) {
  std::vector<std::vector<int>> bridges;
  if (loops.size() < 2) return bridges;
  const std::size_t n = m.number_of_vertices();
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> parent(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int v : loops[0]) {
    dist[v] = 0;
    queue.push({0.0, v});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[v]) continue;
    for (Mesh::Halfedge_index h : m.halfedges_around_target(m.halfedge(Mesh::Vertex_index(v)))) {
      const int u = static_cast<int>(m.source(h));
      const double du = d + length(m, h);
      if (du < dist[u]) {
        dist[u] = du;
        parent[u] = v;
        queue.push({du, u});
      }
    }
  }
  for (std::size_t k = 1; k < loops.size(); ++k) {
    const int end = *std::min_element(loops[k].begin(), loops[k].end(),
                                      [&](int a, int b) { return dist[a] < dist[b]; });
    std::vector<int> path;
    for (int v = end; v >= 0; v = parent[v]) path.push_back(v);
    std::reverse(path.begin(), path.end());  // from boundary 0 to boundary k
    bridges.push_back(std::move(path));
  }
  return bridges;
}

std::vector<std::vector<int>> handle_loops(const Mesh& m, const std::vector<int>& loop_of_halfedge,
                                           std::size_t loop_count) {
  const std::size_t nF = m.number_of_faces();
  const VertexTree tree = vertex_spanning_tree(m);
  const std::vector<int>& parent = tree.parent;
  const std::vector<int>& depth = tree.depth;
  const std::vector<char>& in_tree = tree.edge_used;
  // dual spanning tree over faces and one virtual face per hole, avoiding the tree
  auto node_of = [&](Mesh::Halfedge_index h) {
    return m.is_border(h) ? static_cast<int>(nF) + loop_of_halfedge[h] : static_cast<int>(m.face(h));
  };
  const std::size_t nodes = nF + loop_count;
  std::vector<char> reached(nodes, 0), crossed(m.number_of_edges(), 0);
  std::queue<Mesh::Halfedge_index> hq;  // a halfedge of each reached node
  auto visit = [&](Mesh::Halfedge_index h) {
    reached[node_of(h)] = 1;
    hq.push(h);
  };
  visit(m.halfedge(Mesh::Face_index(0)));
  while (!hq.empty()) {
    const Mesh::Halfedge_index start = hq.front();
    hq.pop();
    for (Mesh::Halfedge_index h : m.halfedges_around_face(start)) {
      if (in_tree[m.edge(h)]) continue;
      const Mesh::Halfedge_index o = m.opposite(h);
      if (reached[node_of(o)]) continue;
      crossed[m.edge(h)] = 1;
      visit(o);
    }
  }
  std::vector<std::vector<int>> loops;
  for (Mesh::Edge_index e : m.edges()) {
    if (in_tree[e] || crossed[e]) continue;
    // tree path from a up to the common ancestor, then down to b; the edge b-a closes it
    int a = static_cast<int>(m.source(m.halfedge(e, 0)));
    int b = static_cast<int>(m.target(m.halfedge(e, 0)));
    std::vector<int> up, down;
    while (a != b) {
      if (depth[a] >= depth[b]) {
        up.push_back(a);
        a = parent[a];
      } else {
        down.push_back(b);
        b = parent[b];
      }
    }
    up.push_back(a);
    up.insert(up.end(), down.rbegin(), down.rend());
    loops.push_back(std::move(up));
  }
  return loops;
}

}  // namespace

NamedLoops named_loops(const Mesh& m) {
  NamedLoops out;
  std::vector<int> loop_of_halfedge;
  out.boundaries = border_loops(m, loop_of_halfedge);
  out.bridges = bridge_paths(m, out.boundaries);
  out.handles = handle_loops(m, loop_of_halfedge, out.boundaries.size());
  return out;
}

std::vector<int> boundary_loop_of_vertex(const NamedLoops& loops, std::size_t vertex_count) {
  std::vector<int> loop_of(vertex_count, -1);
  for (std::size_t k = 0; k < loops.boundaries.size(); ++k)
    for (int v : loops.boundaries[k]) loop_of[static_cast<std::size_t>(v)] = static_cast<int>(k);
  return loop_of;
}

}  // namespace qm
