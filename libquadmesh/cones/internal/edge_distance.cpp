#include "libquadmesh/cones/internal/edge_distance.h"

#include <algorithm>
#include <limits>
#include <queue>

namespace qm {

namespace {

using Item = std::pair<double, int>;
using Queue = std::priority_queue<Item, std::vector<Item>, std::greater<Item>>;

/// Dijkstra from the vertices already in `queue` (at their `distance`), visiting
/// each vertex once, nearest first: `visit(v, d)` returns false to end the search.
/// Only paths shorter than a vertex's entry in `distance` are followed.
template <class Visit>
void expand(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, Queue& queue, std::vector<double>& distance,
            Visit visit) {
  std::vector<char> done(soup.points.size(), 0);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    const auto sv = static_cast<std::size_t>(v);
    if (done[sv] || d > distance[sv]) continue;
    done[sv] = 1;
    if (!visit(v, d)) return;
    for (int f : adjacency.vertex_faces[sv])
      for (int w : soup.triangles[static_cast<std::size_t>(f)]) {
        const auto sw = static_cast<std::size_t>(w);
        const double dw = d + (soup.points[sw] - soup.points[sv]).norm();
        if (!done[sw] && dw < distance[sw]) {
          distance[sw] = dw;
          queue.push({dw, w});
        }
      }
  }
}

}  // namespace

std::vector<double> distance_from(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                  const std::vector<char>& sources) {
  std::vector<double> distance(soup.points.size(), std::numeric_limits<double>::infinity());
  Queue queue;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (sources[v]) {
      distance[v] = 0;
      queue.push({0.0, static_cast<int>(v)});
    }
  expand(soup, adjacency, queue, distance, [](int, double) { return true; });
  return distance;
}

std::vector<std::pair<int, double>> vertices_within(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                                    int source, double& radius,
                                                    const std::function<bool(int)>& stop) {
  std::vector<std::pair<int, double>> out;
  std::vector<double> distance(soup.points.size(), radius);
  Queue queue;
  distance[static_cast<std::size_t>(source)] = 0;
  queue.push({0.0, source});
  expand(soup, adjacency, queue, distance, [&](int v, double d) {
    if (v != source && stop(v)) {
      radius = d;
      return false;
    }
    out.push_back({v, d});
    return true;
  });
  out.erase(std::remove_if(out.begin(), out.end(), [&](const auto& p) { return p.second >= radius; }), out.end());
  return out;
}

}  // namespace qm
