#include "libquadmesh/cones/boundary_corners.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/cones/cone_set.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace qm {

namespace {

/// The least share of its window's turn a corner's own vertex turns.
constexpr double min_corner_share = 0.5;

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

std::vector<BoundaryCorner> boundary_corners(const TriangleSoup& surface, double window, double tolerance_deg) {
  QM_ASSERT(window > 0);
  const SurfaceAdjacency adjacency = surface_adjacency(surface);
  const std::vector<double> curvature = vertex_curvature(surface, adjacency);
  std::vector<BoundaryCorner> corners;
  for (const std::vector<int>& loop : adjacency.boundary_loops) {
    const std::size_t n = loop.size();
    std::vector<double> length(n);
    double perimeter = 0;
    for (std::size_t k = 0; k < n; ++k) {
      length[k] = (surface.points[static_cast<std::size_t>(loop[(k + 1) % n])] -
                   surface.points[static_cast<std::size_t>(loop[k])]).norm();
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
      const Vec3& p = surface.points[static_cast<std::size_t>(loop[i])];
      const double chord = angle_deg(along_loop(surface, loop, length, i, -1, w) - p,
                                     along_loop(surface, loop, length, i, 1, w) - p);
      angle[i] = 180 - turning * 180 / M_PI;
      candidate[i] = std::abs(chord - 180) > tolerance_deg && std::abs(angle[i] - 180) > tolerance_deg;
    }
    // the corner is where the boundary turns: of the vertices nearer than the
    // window along the loop, the one whose own turning is the largest the way the
    // window turns
    for (std::size_t i = 0; i < n; ++i) {
      if (!candidate[i]) continue;
      const double way = angle[i] < 180 ? 1.0 : -1.0;
      const auto own = [&](std::size_t k) { return way * curvature[static_cast<std::size_t>(loop[k])]; };
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
      // and that turns at least half of the window's turn itself: a curve whose
      // turn is spread over the window (a hole a few quads round, a fillet) has
      // no corner, nor a place to put one
      const double window_turn = std::abs(180 - angle[i]) * M_PI / 180;
      if (sharpest && own(i) >= min_corner_share * window_turn) corners.push_back({loop[i], angle[i]});
    }
  }
  std::sort(corners.begin(), corners.end(),
            [](const BoundaryCorner& a, const BoundaryCorner& b) { return a.vertex < b.vertex; });
  return corners;
}

int corner_quads_wanted(double angle_deg) { return std::max(1, static_cast<int>(std::lround(angle_deg / 90))); }

}  // namespace qm
