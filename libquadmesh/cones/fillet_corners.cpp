#include "libquadmesh/cones/fillet_corners.h"

#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <algorithm>
#include <cmath>

namespace qm {

namespace {

constexpr double fillet_min_turn_deg = 60.0;
constexpr double fillet_max_turn_deg = 120.0;

/// A boundary loop's edge lengths and perimeter, and `between`: the boundary's
/// turning (radians, positive where the surface is convex) at the vertices of
/// `loop` whose distance along it from vertex i lies in (from, to] (negative:
/// before i).
struct LoopTurning {
  const std::vector<int>& loop;
  const std::vector<double>& curvature;  ///< per vertex of the surface
  std::vector<double> length;            ///< of the edge from loop[k] to loop[k + 1]
  double perimeter = 0;

  double between(std::size_t i, double from, double to) const {
    const std::size_t n = loop.size();
    double turn = 0;
    if (from < 0 && 0 <= to) turn += curvature[static_cast<std::size_t>(loop[i])];
    double travelled = 0;  // forwards: (0, to]
    for (std::size_t at = i, steps = 0; to > 0 && steps + 1 < n; ++steps) {
      travelled += length[at];
      at = (at + 1) % n;
      if (travelled > to) break;
      if (travelled > from) turn += curvature[static_cast<std::size_t>(loop[at])];
    }
    travelled = 0;  // backwards: [from, 0)
    for (std::size_t at = i, steps = 0; from < 0 && steps + 1 < n; ++steps) {
      const std::size_t before = (at + n - 1) % n;
      travelled += length[before];
      at = before;
      if (-travelled <= from) break;
      if (-travelled <= to) turn += curvature[static_cast<std::size_t>(loop[at])];
    }
    return turn;
  }
};

}  // namespace

std::vector<BoundaryCorner> fillet_corners(const TriangleSoup& surface, double size) {
  QM_ASSERT(size > 0);
  const SurfaceAdjacency adjacency = surface_adjacency(surface);
  const std::vector<double> curvature = vertex_curvature(surface, adjacency);
  const double w = fillet_window_quads * size;
  std::vector<char> near_corner(surface.points.size(), 0);
  const std::vector<BoundaryCorner> sharp = boundary_corners(surface, corner_window_quads * size);
  for (const BoundaryCorner& c : sharp)
    near_corner[static_cast<std::size_t>(c.vertex)] = 1;
  std::vector<BoundaryCorner> out;
  for (const std::vector<int>& loop : adjacency.boundary_loops) {
    const std::size_t n = loop.size();
    LoopTurning turning{loop, curvature, std::vector<double>(n), 0};
    for (std::size_t k = 0; k < n; ++k) {
      turning.length[k] = (surface.points[static_cast<std::size_t>(loop[(k + 1) % n])] -
                           surface.points[static_cast<std::size_t>(loop[k])])
                              .norm();
      turning.perimeter += turning.length[k];
    }
    if (turning.perimeter < 4 * w) continue;  // window and flanks would overlap: a hole's circle
    // a corner at the quad scale within the window: the arc is its, not a fillet
    std::vector<char> blocked(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (!near_corner[static_cast<std::size_t>(loop[i])]) continue;
      double travelled = 0;
      blocked[i] = 1;
      for (std::size_t at = i; travelled <= w;) {
        travelled += turning.length[at];
        at = (at + 1) % n;
        blocked[at] = 1;
      }
      travelled = 0;
      for (std::size_t at = i; travelled <= w;) {
        const std::size_t before = (at + n - 1) % n;
        travelled += turning.length[before];
        at = before;
        blocked[at] = 1;
      }
    }
    // candidates: the window turns by 60-120 degrees, its flanks little
    std::vector<double> turn(n, 0), imbalance(n, 0);
    std::vector<char> candidate(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (blocked[i]) continue;
      turn[i] = turning.between(i, -w, w);
      const double degrees = std::abs(turn[i]) * 180 / M_PI;
      if (degrees < fillet_min_turn_deg || degrees > fillet_max_turn_deg) continue;
      const double flank = fillet_flank_deg * M_PI / 180;
      if (std::abs(turning.between(i, -2 * w, -w)) >= flank ||
          std::abs(turning.between(i, w, 2 * w)) >= flank)
        continue;
      imbalance[i] = std::abs(turning.between(i, -w, 0) - turning.between(i, -1e-12, w));
      candidate[i] = 1;
    }
    // per run of candidates turning one way, the vertex at the middle of the turn
    for (std::size_t i = 0; i < n; ++i) {
      if (!candidate[i]) continue;
      const std::size_t before = (i + n - 1) % n;
      if (candidate[before] && (turn[before] > 0) == (turn[i] > 0) && before != i)
        continue;  // not a run's start
      std::size_t best = i;
      for (std::size_t at = i, steps = 0;
           steps < n && candidate[at] && (turn[at] > 0) == (turn[i] > 0);
           ++steps, at = (at + 1) % n)
        if (imbalance[at] < imbalance[best]) best = at;
      out.push_back({loop[best], 180 - turn[best] * 180 / M_PI});
    }
  }
  std::sort(out.begin(), out.end(),
            [](const BoundaryCorner& a, const BoundaryCorner& b) { return a.vertex < b.vertex; });
  return out;
}

}  // namespace qm
