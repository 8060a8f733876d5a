#include "libquadmesh/param/map_zeros.h"

#include "libquadmesh/core/internal/union_find.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

namespace qm {

MapZeros map_zeros(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& map) {
  const std::size_t nV = soup.points.size(), nF = soup.triangles.size();
  MapZeros z;
  z.flipped.assign(nF, 0);
  std::vector<double> angle(nV, 0.0), size_sum(nV, 0.0);
  std::vector<int> valence(nV, 0);
  for (std::size_t f = 0; f < nF; ++f) {
    const CornerValues& c = map.corners[f];
    if (image_area2(c) <= 0) {
      z.flipped[f] = 1;
      ++z.flipped_count;
    }
    const Triangle& t = soup.triangles[f];
    const double magnitude = (std::abs(c[1] - c[0]) + std::abs(c[2] - c[1]) + std::abs(c[0] - c[2])) /
                             (3 * std::max(1e-300, ((soup.points[t[1]] - soup.points[t[0]]).norm() +
                                                    (soup.points[t[2]] - soup.points[t[1]]).norm() +
                                                    (soup.points[t[0]] - soup.points[t[2]]).norm()) / 3));
    for (int i = 0; i < 3; ++i) {
      const Complex out = c[(i + 1) % 3] - c[i], back = c[(i + 2) % 3] - c[i];
      const auto v = static_cast<std::size_t>(t[i]);
      angle[v] += std::arg(back / out);
      size_sum[v] += magnitude;
      ++valence[v];
    }
  }
  z.vertex_order.resize(nV);
  for (std::size_t v = 0; v < nV; ++v) {
    const double unit = adjacency.boundary_vertex[v] ? M_PI : 2 * M_PI;
    z.vertex_order[v] = valence[v] ? static_cast<int>(std::lround(angle[v] / unit)) - 1 : 0;
  }
  UnionFind sets(nV);
  std::vector<char> in_fold(nV, 0);
  for (std::size_t f = 0; f < nF; ++f) {
    if (!z.flipped[f]) continue;
    const Triangle& t = soup.triangles[f];
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
    for (int v : t) in_fold[static_cast<std::size_t>(v)] = 1;
  }
  std::vector<int> cluster_of(nV, -1);
  auto cluster_for = [&](int v) -> MapZero& {
    const int root = sets.find(v);
    if (cluster_of[static_cast<std::size_t>(root)] < 0) {
      cluster_of[static_cast<std::size_t>(root)] = static_cast<int>(z.zeros.size());
      z.zeros.emplace_back();
    }
    return z.zeros[static_cast<std::size_t>(cluster_of[static_cast<std::size_t>(root)])];
  };
  for (std::size_t v = 0; v < nV; ++v) {
    if (z.vertex_order[v] == 0 && !in_fold[v]) continue;
    MapZero& c = cluster_for(static_cast<int>(v));
    c.vertices.push_back(static_cast<int>(v));
    if (adjacency.boundary_vertex[v]) c.on_boundary = true;
  }
  for (std::size_t f = 0; f < nF; ++f)
    if (z.flipped[f]) ++cluster_for(soup.triangles[f][0]).flipped_triangles;
  for (MapZero& c : z.zeros) {
    // counted on the double: interior parts twice (they have a mirror), boundary once
    int doubled = 2 * c.flipped_triangles;
    for (int v : c.vertices)
      doubled += (adjacency.boundary_vertex[static_cast<std::size_t>(v)] ? 1 : 2) *
                 z.vertex_order[static_cast<std::size_t>(v)];
    c.order = c.on_boundary ? doubled : doubled / 2;
    z.doubled_order_sum += doubled;
    double best = std::numeric_limits<double>::infinity();
    for (int v : c.vertices) {
      const auto vi = static_cast<std::size_t>(v);
      if (c.on_boundary && !adjacency.boundary_vertex[vi]) continue;
      const double mean = size_sum[vi] / std::max(1, valence[vi]);
      if (mean < best) {
        best = mean;
        c.representative = v;
      }
    }
  }
  return z;
}

}  // namespace qm
