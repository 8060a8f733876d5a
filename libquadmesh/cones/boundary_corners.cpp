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

/// A staircase's low steps in a row: two steps, four corners (staircase_step_quads).
constexpr std::size_t min_staircase_links = 3;

/// A corner found on a loop: its index along the loop and its angle.
struct LoopCorner {
  std::size_t index = 0;
  double angle_deg = 0;
  double own_turn = 0;  ///< the vertex's own geodesic turning (radians), signed
};

/// The corners of one loop (in loop order, `position` the arc length at each loop
/// vertex, `perimeter` the loop's length) less its staircases (staircase_step_quads).
std::vector<LoopCorner> without_staircases(const std::vector<LoopCorner>& corners,
                                           const std::vector<double>& position, double perimeter, double quad) {
  const std::size_t m = corners.size();
  if (m < 3) return corners;
  // low[k]: corners k and k + 1 turn opposite ways less than a step apart
  std::vector<char> low(m);
  for (std::size_t k = 0; k < m; ++k) {
    const LoopCorner& a = corners[k];
    const LoopCorner& b = corners[(k + 1) % m];
    double gap = position[b.index] - position[a.index];
    if (gap <= 0) gap += perimeter;
    low[k] = (a.angle_deg < 180) != (b.angle_deg < 180) && gap < staircase_step_quads * quad;
  }
  // a loop that is one staircase all round has no corner: its turn is spread
  if (std::all_of(low.begin(), low.end(), [](char c) { return c != 0; })) return {};
  std::vector<char> keep(m, 1);
  // the runs of low steps, started after a link that is not one
  const std::size_t start = static_cast<std::size_t>(std::find(low.begin(), low.end(), 0) - low.begin()) + 1;
  for (std::size_t offset = 0; offset < m;) {
    const std::size_t first = (start + offset) % m;
    std::size_t links = 0;
    while (offset + links < m && low[(first + links) % m]) ++links;
    if (links >= min_staircase_links) {
      // corners first .. first + links: a staircase; with an odd count its net
      // quarter turn stays, at its sharpest corner turning that way
      const std::size_t count = links + 1;
      for (std::size_t k = 0; k < count; ++k) keep[(first + k) % m] = 0;
      if (count % 2 == 1) {
        const bool convex = corners[first].angle_deg < 180;
        std::size_t best = first;
        for (std::size_t k = 0; k < count; k += 2) {
          const std::size_t at = (first + k) % m;
          if ((convex ? 1 : -1) * corners[at].own_turn > (convex ? 1 : -1) * corners[best].own_turn) best = at;
        }
        keep[best] = 1;
      }
    }
    offset += std::max<std::size_t>(links, 1);
  }
  std::vector<LoopCorner> kept;
  for (std::size_t k = 0; k < m; ++k)
    if (keep[k]) kept.push_back(corners[k]);
  return kept;
}

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
    std::vector<double> position(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) position[k] = position[k - 1] + length[k - 1];
    std::vector<LoopCorner> found;
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
      if (sharpest && own(i) >= min_corner_share * window_turn)
        found.push_back({i, angle[i], curvature[static_cast<std::size_t>(loop[i])]});
    }
    for (const LoopCorner& c : without_staircases(found, position, perimeter, window / corner_window_quads))
      corners.push_back({loop[c.index], c.angle_deg});
  }
  std::sort(corners.begin(), corners.end(),
            [](const BoundaryCorner& a, const BoundaryCorner& b) { return a.vertex < b.vertex; });
  return corners;
}

int corner_quads_wanted(double angle_deg) { return std::max(1, static_cast<int>(std::lround(angle_deg / 90))); }

}  // namespace qm
