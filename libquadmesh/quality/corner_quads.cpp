#include "libquadmesh/quality/corner_quads.h"

#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace qm {

namespace {

/// Per point of `mesh`: the faces around it, and the length of its shortest
/// boundary edge (infinity for a point not on the boundary).
struct BoundaryPoints {
  std::vector<int> faces;
  std::vector<double> shortest_boundary_edge;
};

BoundaryPoints boundary_points(const PolygonMesh& mesh) {
  BoundaryPoints b;
  b.faces.assign(mesh.points.size(), 0);
  b.shortest_boundary_edge.assign(mesh.points.size(), std::numeric_limits<double>::infinity());
  std::map<std::pair<int, int>, int> uses;
  for (const std::vector<int>& face : mesh.faces)
    for (std::size_t k = 0; k < face.size(); ++k) {
      ++b.faces[static_cast<std::size_t>(face[k])];
      const int a = face[k], c = face[(k + 1) % face.size()];
      ++uses[{std::min(a, c), std::max(a, c)}];
    }
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    const double length = (mesh.points[static_cast<std::size_t>(edge.first)] -
                           mesh.points[static_cast<std::size_t>(edge.second)]).norm();
    for (int v : {edge.first, edge.second}) {
      double& shortest = b.shortest_boundary_edge[static_cast<std::size_t>(v)];
      shortest = std::min(shortest, length);
    }
  }
  return b;
}

bool within(double x, double low, double high) { return x >= low && x <= high; }

/// The point `distance` along the closed polyline `loop` from its vertex `i`,
/// forwards (direction +1) or backwards (-1); `length` per edge k -> k + 1.
Vec3 along_loop(const TriangleSoup& soup, const std::vector<int>& loop, const std::vector<double>& length,
                std::size_t i, int direction, double distance) {
  const std::size_t n = loop.size();
  std::size_t at = i;
  for (std::size_t steps = 0; steps < n; ++steps) {
    const std::size_t next = direction > 0 ? (at + 1) % n : (at + n - 1) % n;
    const double edge = length[direction > 0 ? at : next];
    const Vec3& a = soup.points[static_cast<std::size_t>(loop[at])];
    const Vec3& b = soup.points[static_cast<std::size_t>(loop[next])];
    if (edge >= distance) return a + (b - a) * (edge > 0 ? distance / edge : 0.0);
    distance -= edge;
    at = next;
  }
  return soup.points[static_cast<std::size_t>(loop[at])];
}

double angle_deg(const Vec3& a, const Vec3& b) {
  return angle_between(a, b) * 180 / M_PI;
}

}  // namespace

std::vector<BoundaryCorner> boundary_corners(const TriangleSoup& reference, double window) {
  QM_ASSERT(window > 0);
  const SurfaceAdjacency adjacency = surface_adjacency(reference);
  const std::vector<double> curvature = vertex_curvature(reference, adjacency);
  std::vector<BoundaryCorner> corners;
  for (const std::vector<int>& loop : adjacency.boundary_loops) {
    const std::size_t n = loop.size();
    std::vector<double> length(n);
    double perimeter = 0;
    for (std::size_t k = 0; k < n; ++k) {
      length[k] = (reference.points[static_cast<std::size_t>(loop[(k + 1) % n])] -
                   reference.points[static_cast<std::size_t>(loop[k])]).norm();
      perimeter += length[k];
    }
    const double w = std::min(window, perimeter / 4);
    // the turning within the window and the chord angle, per vertex of the loop
    std::vector<double> angle(n, 180.0);
    std::vector<char> candidate(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      double turning = curvature[static_cast<std::size_t>(loop[i])];
      for (int direction : {1, -1}) {
        double travelled = 0;
        for (std::size_t at = i, steps = 0; steps + 1 < n; ++steps) {
          const std::size_t next = direction > 0 ? (at + 1) % n : (at + n - 1) % n;
          travelled += length[direction > 0 ? at : next];
          if (travelled > w) break;
          turning += curvature[static_cast<std::size_t>(loop[next])];
          at = next;
        }
      }
      const Vec3& p = reference.points[static_cast<std::size_t>(loop[i])];
      const double chord = angle_deg(along_loop(reference, loop, length, i, -1, w) - p,
                                     along_loop(reference, loop, length, i, 1, w) - p);
      angle[i] = 180 - turning * 180 / M_PI;
      candidate[i] = std::abs(chord - 180) > corner_angle_tolerance_deg &&
                     std::abs(angle[i] - 180) > corner_angle_tolerance_deg;
    }
    // the corner is where the boundary turns: of the vertices nearer than the
    // window along the loop, the one whose own turning is the largest
    const auto own = [&](std::size_t k) { return std::abs(curvature[static_cast<std::size_t>(loop[k])]); };
    for (std::size_t i = 0; i < n; ++i) {
      if (!candidate[i]) continue;
      bool sharpest = true;
      for (int direction : {1, -1}) {
        double travelled = 0;
        for (std::size_t at = i, steps = 0; sharpest && steps + 1 < n; ++steps) {
          const std::size_t next = direction > 0 ? (at + 1) % n : (at + n - 1) % n;
          travelled += length[direction > 0 ? at : next];
          if (travelled > w) break;
          if (own(next) > own(i) || (own(next) == own(i) && next < i)) sharpest = false;
          at = next;
        }
      }
      if (sharpest) corners.push_back({loop[i], angle[i]});
    }
  }
  std::sort(corners.begin(), corners.end(),
            [](const BoundaryCorner& a, const BoundaryCorner& b) { return a.vertex < b.vertex; });
  return corners;
}

CornerQuads corner_quads(const PolygonMesh& mesh, const TriangleSoup& reference) {
  const BoundaryPoints boundary = boundary_points(mesh);
  std::vector<std::size_t> on_boundary;
  for (std::size_t p = 0; p < mesh.points.size(); ++p)
    if (std::isfinite(boundary.shortest_boundary_edge[p])) on_boundary.push_back(p);
  // the window: half the mesh's mean edge
  double edges = 0, total = 0;
  for (const std::vector<int>& face : mesh.faces)
    for (std::size_t k = 0; k < face.size(); ++k, ++edges)
      total += (mesh.points[static_cast<std::size_t>(face[(k + 1) % face.size()])] -
                mesh.points[static_cast<std::size_t>(face[k])]).norm();
  CornerQuads result;
  if (edges == 0 || !(total > 0)) return result;
  for (const BoundaryCorner& corner : boundary_corners(reference, 0.5 * total / edges)) {
    const double angle = corner.angle_deg;
    CornerCount c;
    c.position = reference.points[static_cast<std::size_t>(corner.vertex)];
    c.angle_deg = angle;
    c.quads_wanted = std::max(1, static_cast<int>(std::lround(angle / 90)));
    double nearest = std::numeric_limits<double>::infinity();
    int at = -1;
    for (std::size_t p : on_boundary) {
      const double d = (mesh.points[p] - c.position).norm();
      if (d < nearest) nearest = d, at = static_cast<int>(p);
    }
    if (at >= 0 && nearest <= corner_match_share * boundary.shortest_boundary_edge[static_cast<std::size_t>(at)])
      c.quads = boundary.faces[static_cast<std::size_t>(at)];
    const bool wrong = c.quads != c.quads_wanted;
    if (within(angle, convex_corner_low_deg, convex_corner_high_deg)) {
      ++result.convex;
      result.convex_wrong += wrong;
    } else if (within(angle, concave_corner_low_deg, concave_corner_high_deg)) {
      ++result.concave;
      result.concave_wrong += wrong;
    } else {
      ++result.other;
      result.other_wrong += wrong;
    }
    result.corners.push_back(c);
  }
  return result;
}

}  // namespace qm
