#include "libquadmesh/cones/cut_graph.h"

#include <map>
#include <set>

namespace qm {

namespace {

using Edge = std::pair<int, int>;  // (smaller, larger) vertex

Edge undirected(int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; }

/// Inner edges the tree does not cross.
std::set<Edge> untree_edges(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const CrossField& field) {
  std::set<Edge> cut;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Triangle& t = soup.triangles[f];
      if (field.tree_side[f][static_cast<std::size_t>(k)]) continue;
      if (adjacency.find(t[(k + 1) % 3], t[k]).face < 0) continue;
      cut.insert(undirected(t[k], t[(k + 1) % 3]));
    }
  return cut;
}

/// Removes, again and again, the cut edges at a regular interior vertex met by
/// only one of them: a cut there separates nothing.
void prune(std::set<Edge>& cut, const SurfaceAdjacency& adjacency, const std::vector<int>& quads) {
  std::map<int, std::set<Edge>> at;
  for (const Edge& e : cut) {
    at[e.first].insert(e);
    at[e.second].insert(e);
  }
  auto dangling = [&](int v) {
    const auto sv = static_cast<std::size_t>(v);
    return !adjacency.boundary_vertex[sv] && quads[sv] == 4 && at[v].size() == 1;
  };
  std::vector<int> stack;
  for (const auto& [v, edges] : at)
    if (dangling(v)) stack.push_back(v);
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if (!dangling(v)) continue;
    const Edge e = *at[v].begin();
    const int w = e.first == v ? e.second : e.first;
    cut.erase(e);
    at[v].erase(e);
    at[w].erase(e);
    if (dangling(w)) stack.push_back(w);
  }
}

/// The wedges of v's triangles: a new wedge after every cut edge of its ring.
void assign_wedges(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::set<Edge>& cut, int v,
                   CutGraph& graph) {
  const VertexRing ring = vertex_ring(soup, adjacency, v);
  const std::size_t n = ring.faces.size();
  // the edge between faces[k - 1] and faces[k] is (v, neighbours[k])
  auto cut_before = [&](std::size_t k) { return cut.count(undirected(v, ring.neighbours[k])) > 0; };
  std::size_t start = 0;
  if (!ring.boundary)
    for (std::size_t k = 0; k < n; ++k)
      if (cut_before(k)) {
        start = k;
        break;
      }
  int wedge = graph.wedge_count++;
  for (std::size_t s = 0; s < n; ++s) {
    const std::size_t k = (start + s) % n;
    if (s > 0 && cut_before(k)) wedge = graph.wedge_count++;
    const auto f = static_cast<std::size_t>(ring.faces[k]);
    const Triangle& t = soup.triangles[f];
    for (int c = 0; c < 3; ++c)
      if (t[c] == v) graph.wedge[f][static_cast<std::size_t>(c)] = wedge;
  }
}

}  // namespace

CutGraph cut_graph(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const CrossField& field,
                   const std::vector<int>& quads) {
  std::set<Edge> cut = untree_edges(soup, adjacency, field);
  prune(cut, adjacency, quads);
  CutGraph graph;
  graph.cut_edges = cut.size();
  graph.cut_side.assign(soup.triangles.size(), {0, 0, 0});
  graph.wedge.assign(soup.triangles.size(), {-1, -1, -1});
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const Triangle& t = soup.triangles[f];
      graph.cut_side[f][static_cast<std::size_t>(k)] = cut.count(undirected(t[k], t[(k + 1) % 3])) > 0;
    }
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (!adjacency.vertex_faces[v].empty()) assign_wedges(soup, adjacency, cut, static_cast<int>(v), graph);
  return graph;
}

}  // namespace qm
