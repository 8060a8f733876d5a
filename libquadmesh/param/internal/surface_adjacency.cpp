#include "libquadmesh/param/internal/surface_adjacency.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <cmath>

namespace qm {

int euler_characteristic(const SurfaceAdjacency& adjacency) {
  const TriangleSoup& soup = *adjacency.soup;
  std::size_t boundary_edges = 0;
  for (const auto& loop : adjacency.boundary_loops) boundary_edges += loop.size();
  const std::size_t edges = (3 * soup.triangles.size() + boundary_edges) / 2;
  std::size_t vertices = 0;
  for (const auto& faces : adjacency.vertex_faces) vertices += faces.empty() ? 0 : 1;
  return static_cast<int>(vertices) - static_cast<int>(edges) + static_cast<int>(soup.triangles.size());
}

bool has_handles(const SurfaceAdjacency& adjacency) {
  return 2 - euler_characteristic(adjacency) - static_cast<int>(adjacency.boundary_loops.size()) > 0;
}

SurfaceAdjacency surface_adjacency(const TriangleSoup& soup) {
  SurfaceAdjacency a;
  a.soup = &soup;
  const std::size_t nV = soup.points.size();
  a.vertex_faces.assign(nV, {});
  a.boundary_vertex.assign(nV, 0);
  a.loop_of_vertex.assign(nV, -1);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int v : soup.triangles[f]) a.vertex_faces[static_cast<std::size_t>(v)].push_back(static_cast<int>(f));
  // boundary edges u->w: no triangle holds w->u; the next boundary vertex after u is unique
  std::vector<int> next(nV, -1);
  for (const Triangle& t : soup.triangles)
    for (int i = 0; i < 3; ++i) {
      const int u = t[i], w = t[(i + 1) % 3];
      if (a.find(w, u).face < 0) {
        next[static_cast<std::size_t>(u)] = w;
        a.boundary_vertex[static_cast<std::size_t>(u)] = a.boundary_vertex[static_cast<std::size_t>(w)] = 1;
      }
    }
  for (std::size_t v = 0; v < nV; ++v) {
    if (next[v] < 0 || a.loop_of_vertex[v] >= 0) continue;
    std::vector<int> loop;
    int u = static_cast<int>(v);
    while (a.loop_of_vertex[static_cast<std::size_t>(u)] < 0) {
      a.loop_of_vertex[static_cast<std::size_t>(u)] = static_cast<int>(a.boundary_loops.size());
      loop.push_back(u);
      u = next[static_cast<std::size_t>(u)];
      QM_ASSERT(u >= 0);
    }
    a.boundary_loops.push_back(std::move(loop));
  }
  return a;
}

VertexRing vertex_ring(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, int v) {
  VertexRing ring;
  // around v, triangle (v, b, c) in CCW order goes from neighbour b to neighbour c
  std::unordered_map<int, std::pair<int, int>> step;  // b -> (c, face)
  std::unordered_map<int, int> incoming;
  for (int f : adjacency.vertex_faces[static_cast<std::size_t>(v)]) {
    const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
    int k = 0;
    while (t[k] != v) ++k;
    const int b = t[(k + 1) % 3], c = t[(k + 2) % 3];
    step[b] = {c, f};
    ++incoming[c];
  }
  int start = step.begin()->first;
  for (const auto& [b, cf] : step)
    if (!incoming.count(b)) {
      start = b;
      ring.boundary = true;
    }
  int b = start;
  for (std::size_t guard = 0; guard <= step.size(); ++guard) {
    ring.neighbours.push_back(b);
    const auto it = step.find(b);
    if (it == step.end()) break;
    ring.faces.push_back(it->second.second);
    b = it->second.first;
    if (b == start) break;
  }
  return ring;
}

std::vector<double> ring_angles(const TriangleSoup& soup, const VertexRing& ring, int v) {
  const Vec3& p = soup.points[static_cast<std::size_t>(v)];
  const std::size_t n = ring.neighbours.size();
  std::vector<double> angles;
  for (std::size_t k = 0; k < ring.faces.size(); ++k) {
    const Vec3 a = soup.points[static_cast<std::size_t>(ring.neighbours[k])] - p;
    const Vec3 b = soup.points[static_cast<std::size_t>(ring.neighbours[(k + 1) % n])] - p;
    angles.push_back(angle_between(a, b));
  }
  return angles;
}

Complex edge_value(const SurfaceAdjacency& adjacency, const FaceMap& form, int a, int b) {
  EdgeCorner e = adjacency.find(a, b);
  if (e.face >= 0) {
    const CornerValues& c = form.corners[static_cast<std::size_t>(e.face)];
    return c[e.j] - c[e.i];
  }
  e = adjacency.find(b, a);
  QM_ASSERT_MSG(e.face >= 0, "edge_value: not an edge");
  const CornerValues& c = form.corners[static_cast<std::size_t>(e.face)];
  return c[e.i] - c[e.j];
}

}  // namespace qm
