#include "libquadmesh/extract/quadratic_quads.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <algorithm>
#include <map>

namespace qm {

namespace {

/// S's boundary edges (used by one triangle) as a segment tree.
SegmentTree boundary_segments(const TriangleSoup& surface) {
  std::map<std::pair<int, int>, int> uses;
  for (const Triangle& t : surface.triangles)
    for (std::size_t i = 0; i < 3; ++i) ++uses[{std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3])}];
  SegmentTree tree;
  int id = 0;
  for (const auto& [edge, count] : uses)
    if (count == 1)
      tree.add(surface.points[static_cast<std::size_t>(edge.first)],
               surface.points[static_cast<std::size_t>(edge.second)], id++);
  tree.build();
  return tree;
}

}  // namespace

QuadraticQuads quadratic_quads(const std::vector<Vec3>& points, const std::vector<std::array<int, 4>>& quads,
                               const TriangleSoup& surface, const QuadraticQuadsOptions& options) {
  QuadraticQuads out;
  out.points = points;
  out.first_edge_node = static_cast<int>(points.size());
  // every edge once, with the quads using it in that direction
  std::map<std::pair<int, int>, int> node_of_edge;
  std::map<std::pair<int, int>, int> uses;
  for (const auto& q : quads)
    for (std::size_t i = 0; i < 4; ++i) ++uses[{std::min(q[i], q[(i + 1) % 4]), std::max(q[i], q[(i + 1) % 4])}];

  const TriangleTree triangles(surface.points, surface.triangles);
  const SegmentTree boundary = boundary_segments(surface);
  const auto place = [&](const Vec3& guess) { return triangles.empty() ? guess : triangles.closest(guess).first; };

  for (const auto& q : quads) {
    std::vector<int> element(q.begin(), q.end());
    for (std::size_t i = 0; i < 4; ++i) {
      const int a = q[i], b = q[(i + 1) % 4];
      const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
      auto it = node_of_edge.find(key);
      if (it == node_of_edge.end()) {
        const Vec3 mid = (points[static_cast<std::size_t>(a)] + points[static_cast<std::size_t>(b)]) / 2;
        Vec3 node = mid;
        if (uses[key] == 1) {
          out.boundary_nodes.push_back(static_cast<int>(out.points.size()));
          node = boundary.empty() ? place(mid) : boundary.closest(mid).first;
        } else {
          node = place(mid);
        }
        out.max_move = std::max(out.max_move, (node - mid).norm());
        it = node_of_edge.emplace(key, static_cast<int>(out.points.size())).first;
        out.points.push_back(node);
        out.edge_of_node.push_back({key.first, key.second});
      }
      element.push_back(it->second);
    }
    out.elements.push_back(std::move(element));
  }
  if (options.complete)
    for (auto& e : out.elements) {
      Vec3 centre = Vec3::Zero();
      for (std::size_t i = 0; i < 4; ++i)
        centre += out.points[static_cast<std::size_t>(e[4 + i])] / 2 - out.points[static_cast<std::size_t>(e[i])] / 4;
      e.push_back(static_cast<int>(out.points.size()));
      out.points.push_back(place(centre));
    }
  return out;
}

}  // namespace qm
