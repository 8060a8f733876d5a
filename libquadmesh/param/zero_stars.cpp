#include "libquadmesh/param/zero_stars.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/internal/union_find.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Geometry>
#include <cmath>
#include <algorithm>
#include <functional>
#include <queue>
#include <set>
#include <unordered_map>

namespace qm {

void split_edge(TriangleSoup& soup, std::vector<FaceMap*>& maps, int a, int b) {
  const int m = static_cast<int>(soup.points.size());
  soup.points.push_back(0.5 * (soup.points[static_cast<std::size_t>(a)] +
                               soup.points[static_cast<std::size_t>(b)]));
  if (!soup.point_labels.empty()) soup.point_labels.push_back(-1);
  const std::size_t nF = soup.triangles.size();
  for (std::size_t f = 0; f < nF; ++f) {
    Triangle t = soup.triangles[f];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const bool ab = t[i] == a && t[j] == b, ba = t[i] == b && t[j] == a;
      if (!ab && !ba) continue;
      // (t_i, t_j, t_k) -> (t_i, m, t_k) and (m, t_j, t_k)
      soup.triangles[f] = {t[i], m, t[k]};
      soup.triangles.push_back({m, t[j], t[k]});
      if (!soup.triangle_labels.empty()) soup.triangle_labels.push_back(soup.triangle_labels[f]);
      for (FaceMap* map : maps) {
        const CornerValues c = map->corners[f];
        const Complex mid = 0.5 * (c[i] + c[j]);
        map->corners[f] = {c[i], mid, c[k]};
        map->corners.push_back({mid, c[j], c[k]});
      }
      break;
    }
  }
  std::vector<CurveEdge> split;
  for (CurveEdge& e : soup.cad.edges)
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) {
      split.push_back({m, e.b, e.curve});
      e.b = m;
    }
  soup.cad.edges.insert(soup.cad.edges.end(), split.begin(), split.end());
}

std::unordered_map<int, double> image_ball(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                           const FaceMap& map, int source, double radius) {
  return image_ball(soup, adjacency, map, source, radius, [](int) { return false; });
}

std::unordered_map<int, double> image_ball(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                           const FaceMap& map, int source, double radius,
                                           const std::function<bool(int)>& stop_at) {
  std::unordered_map<int, double> distance{{source, 0.0}};
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > distance[u]) continue;
    if (u != source && stop_at(u)) break;
    for (int f : adjacency.vertex_faces[static_cast<std::size_t>(u)]) {
      const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
      int k = 0;
      while (t[k] != u) ++k;
      for (int step : {1, 2}) {
        const int w = t[(k + step) % 3];
        const double nd = d + std::abs(map.corners[static_cast<std::size_t>(f)][(k + step) % 3] -
                                       map.corners[static_cast<std::size_t>(f)][k]);
        if (nd > radius) continue;
        const auto it = distance.find(w);
        if (it != distance.end() && it->second <= nd) continue;
        distance[w] = nd;
        queue.push({nd, w});
      }
    }
  }
  return distance;
}

/// An interior zero within this fraction of the merge radius (image distance)
/// of the boundary becomes a boundary zero of twice its order there.
constexpr double boundary_merge_fraction = 0.75;
/// Two zeros of one boundary loop merge only nearer than this fraction of the
/// radius (a tenth of a cell at radius 1).
constexpr double boundary_pair_fraction = 0.1;

std::vector<ZeroVertex> merge_close_zeros(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                          const FaceMap& map, std::vector<ZeroVertex> zeros, double radius) {
  // an interior zero this close to the boundary would round onto the boundary's
  // level: it meets its mirror there, a boundary zero of twice its order
  for (ZeroVertex& z : zeros) {
    if (z.on_boundary) continue;
    int nearest = -1;
    double best = boundary_merge_fraction * radius;
    for (const auto& [v, d] : image_ball(soup, adjacency, map, z.vertex, best))
      if (adjacency.boundary_vertex[static_cast<std::size_t>(v)] && d <= best) {
        best = d;
        nearest = v;
      }
    if (nearest >= 0) z = ZeroVertex{nearest, 2 * z.order, true};
  }
  std::unordered_map<int, int> zero_at;
  for (std::size_t i = 0; i < zeros.size(); ++i) zero_at[zeros[i].vertex] = static_cast<int>(i);
  UnionFind groups(zeros.size());
  for (std::size_t i = 0; i < zeros.size(); ++i)
    for (const auto& [v, d] : image_ball(soup, adjacency, map, zeros[i].vertex, radius)) {
      const auto hit = zero_at.find(v);
      if (hit == zero_at.end()) continue;
      const ZeroVertex& other = zeros[static_cast<std::size_t>(hit->second)];
      // two zeros of one boundary loop need only distinct integers U, which the
      // quantization gives consecutive zeros: the arc between them stretches to a
      // cell. Merged, that arc collapses to a point, and the map, folded along it,
      // is untangled into two branch points again, now at one lattice U (the quads
      // then leave a gap there): only an arc under a tenth of a cell (a stretch of
      // more than 10, e.g. a one-triangle hole) is collapsed
      if (zeros[i].on_boundary && other.on_boundary) {
        const bool same_loop = adjacency.loop_of_vertex[static_cast<std::size_t>(zeros[i].vertex)] ==
                               adjacency.loop_of_vertex[static_cast<std::size_t>(other.vertex)];
        // zeros of two loops cannot share a vertex: each loop turns by its own zeros
        if (!same_loop || d >= boundary_pair_fraction * radius) continue;
      }
      groups.unite(static_cast<int>(i), hit->second);
    }
  std::unordered_map<int, std::vector<int>> members;
  for (std::size_t i = 0; i < zeros.size(); ++i) members[groups.find(static_cast<int>(i))].push_back(static_cast<int>(i));
  std::vector<ZeroVertex> merged;
  for (std::size_t i = 0; i < zeros.size(); ++i) {
    const auto it = members.find(static_cast<int>(i));
    if (it == members.end()) continue;  // not a root
    const std::vector<int>& list = it->second;
    if (list.size() == 1) {
      merged.push_back(zeros[static_cast<std::size_t>(list[0])]);
      continue;
    }
    bool boundary = false;
    for (int k : list) boundary |= zeros[static_cast<std::size_t>(k)].on_boundary;
    ZeroVertex z;
    z.on_boundary = boundary;
    int best = -1;
    for (int k : list) {
      const ZeroVertex& y = zeros[static_cast<std::size_t>(k)];
      // orders on the double: interior zeros count twice (they have a mirror)
      z.order += boundary ? (y.on_boundary ? y.order : 2 * y.order) : y.order;
      if (y.on_boundary != boundary) continue;
      if (best < 0 || y.order > zeros[static_cast<std::size_t>(best)].order) best = k;
    }
    z.vertex = zeros[static_cast<std::size_t>(best)].vertex;
    merged.push_back(z);
  }
  return merged;
}

std::vector<ZeroVertex> add_corners(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& map,
                                    std::vector<ZeroVertex> zeros, const std::vector<ZeroVertex>& corners,
                                    double radius) {
  for (const ZeroVertex& c : corners) {
    int nearest = -1;
    double best = radius;
    const std::unordered_map<int, double> ball = image_ball(soup, adjacency, map, c.vertex, radius);
    for (std::size_t i = 0; i < zeros.size(); ++i) {
      if (!zeros[i].on_boundary || zeros[i].corner) continue;
      const auto it = ball.find(zeros[i].vertex);
      if (it != ball.end() && it->second < best) {
        best = it->second;
        nearest = static_cast<int>(i);
      }
    }
    if (nearest >= 0) zeros[static_cast<std::size_t>(nearest)].vertex = c.vertex;
    else zeros.push_back(c);
  }
  return zeros;
}

// A boundary vertex is a sharp corner (boundary_corners) when the loop's turning
// over arc length `scale` each way there is more than typical_turning_factor times
// the loop's median turning and more than corner_angle_deg, and at least
// min_local_turning_share of it happens within local_turning_fraction of `scale`
// (a smooth bend turns in proportion to the distance).
constexpr double typical_turning_factor = 2.5;
constexpr double local_turning_fraction = 0.25;
constexpr double min_local_turning_share = 0.6;

std::vector<ZeroVertex> boundary_corners(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                         double corner_angle_deg, double scale,
                                         const std::vector<ZeroVertex>& taken) {
  std::vector<char> used(soup.points.size(), 0);
  for (const ZeroVertex& z : taken) used[static_cast<std::size_t>(z.vertex)] = 1;
  std::vector<ZeroVertex> corners;
  const double limit = corner_angle_deg * M_PI / 180.0;
  for (const auto& loop : adjacency.boundary_loops) {
    const std::size_t n = loop.size();
    auto point = [&](std::size_t i) { return soup.points[static_cast<std::size_t>(loop[i % n])]; };
    // the point at arc length `scale` from vertex i, walking by `step` (+1 or n - 1)
    auto reach = [&](std::size_t i, std::size_t step, double distance) {
      double left = distance;
      std::size_t j = i;
      for (std::size_t guard = 0; guard + 1 < n; ++guard) {
        const std::size_t k = (j + step) % n;
        const double length = (point(k) - point(j)).norm();
        if (length >= left) return Vec3(point(j) + (point(k) - point(j)) * (left / length));
        left -= length;
        j = k;
      }
      return point(j);
    };
    auto turning_at = [&](std::size_t i, double distance) {
      const Vec3 a = reach(i, n - 1, distance) - point(i), b = reach(i, 1, distance) - point(i);
      return M_PI - angle_between(a, b);
    };
    std::vector<double> turning(n), local(n);
    for (std::size_t i = 0; i < n; ++i) {
      turning[i] = turning_at(i, scale);
      local[i] = turning_at(i, local_turning_fraction * scale);
    }
    // a polygon approximating a smooth curve turns at every vertex: a corner must
    // stand out from the loop's typical turning
    std::vector<double> sorted = turning;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(n / 2), sorted.end());
    const double typical = std::abs(sorted[n / 2]);
    for (std::size_t i = 0; i < n; ++i) {
      if (turning[i] <= typical_turning_factor * typical) continue;
      // a corner turns within a short distance: a smooth bend (a small hole) turns
      // in proportion to the distance and is no corner
      if (used[static_cast<std::size_t>(loop[i])] || turning[i] <= limit || local[i] < min_local_turning_share * turning[i]) continue;
      // the sharpest vertex within `scale` along the loop
      bool sharpest = true;
      for (std::size_t step : {std::size_t(1), n - 1}) {
        double walked = 0;
        for (std::size_t j = i, guard = 0; guard + 1 < n && sharpest; ++guard) {
          const std::size_t k = (j + step) % n;
          walked += (point(k) - point(j)).norm();
          if (walked > scale) break;
          if (turning[k] > turning[i] || (turning[k] == turning[i] && k < i)) sharpest = false;
          j = k;
        }
      }
      if (sharpest) corners.push_back({loop[i], 0, true, true});
    }
  }
  return corners;
}

std::size_t refine_zero_stars(TriangleSoup& soup, std::vector<FaceMap*> maps,
                              const std::vector<ZeroVertex>& zeros) {
  std::size_t splits = 0;
  for (int round = 0; round < 12; ++round) {
    const SurfaceAdjacency adjacency = surface_adjacency(soup);
    std::set<std::pair<int, int>> wide;
    for (const ZeroVertex& z : zeros) {
      const VertexRing ring = vertex_ring(soup, adjacency, z.vertex);
      const std::vector<double> angles = ring_angles(soup, ring, z.vertex);
      double total = 0;
      for (double a : angles) total += a;
      for (std::size_t k = 0; k < angles.size(); ++k)
        if (angles[k] * z.image_angle() / total > max_model_corner_angle) {
          const int b = ring.neighbours[k], c = ring.neighbours[(k + 1) % ring.neighbours.size()];
          wide.insert({std::min(b, c), std::max(b, c)});
        }
    }
    if (wide.empty()) break;
    for (const auto& [b, c] : wide) {
      split_edge(soup, maps, b, c);
      ++splits;
    }
  }
  return splits;
}

}  // namespace qm
