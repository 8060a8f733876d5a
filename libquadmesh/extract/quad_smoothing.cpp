#include "libquadmesh/extract/quad_smoothing.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/internal/quad_star.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <iterator>
#include <optional>
#include <set>

namespace qm {

double worst_corner_jacobian(const LatticeQuads& quads, const std::vector<int>& around, int v, const Vec3& p,
                             const std::vector<Vec3>& normals) {
  double worst = std::numeric_limits<double>::infinity();
  for (int q : around) {
    const std::array<Vec3, 4> c = quad_corners(quads, static_cast<std::size_t>(q), v, p);
    std::array<Vec3, 4> n;
    for (std::size_t k = 0; k < 4; ++k)
      n[k] = normals[static_cast<std::size_t>(quads.quads[static_cast<std::size_t>(q)][k])];
    worst = std::min(worst, sound_scaled_jacobian(c, n));
  }
  return worst;
}

namespace {

/// The first tries of a point: this much of the way to the mean of its neighbours.
constexpr double mean_steps[] = {1.0, 0.5, 0.25};
constexpr std::size_t mean_tries = std::size(mean_steps);
/// Then a pattern search in the tangent plane: steps of these fractions of the
/// mean edge length, in eight directions 45 degrees apart.
constexpr double search_steps[] = {0.2, 0.1, 0.05};
constexpr int search_directions = 8;
/// A move must raise the worst corner's scaled Jacobian by more than this.
constexpr double min_jacobian_gain = 1e-9;

double smallest(const std::vector<double>& jacobian) {
  return jacobian.empty() ? 1.0 : *std::min_element(jacobian.begin(), jacobian.end());
}

/// The movable points of the quads whose scaled Jacobian is below `below`.
std::set<int> smoothing_candidates(const LatticeQuads& quads, const std::vector<double>& jacobian,
                                   const std::vector<char>& movable, double below) {
  std::set<int> candidates;
  for (std::size_t q = 0; q < quads.quads.size(); ++q)
    if (jacobian[q] < below)
      for (int v : quads.quads[q])
        if (movable[static_cast<std::size_t>(v)]) candidates.insert(v);
  return candidates;
}

/// The trial positions of the regular point v (off S, put back on S by the
/// caller): towards the mean of its edge neighbours (one per quad, valence 4),
/// then a pattern search in the plane normal to `normal`, scaled by the mean edge.
std::vector<Vec3> smoothing_tries(const LatticeQuads& quads, const QuadStar& star, int v, const Vec3& normal) {
  const Vec3 here = quads.points[static_cast<std::size_t>(v)];
  Vec3 mean = Vec3::Zero();
  double edge = 0;
  for (int q : star.quads_at[static_cast<std::size_t>(v)]) {
    const auto& quad = quads.quads[static_cast<std::size_t>(q)];
    const int k = static_cast<int>(std::find(quad.begin(), quad.end(), v) - quad.begin());
    const Vec3& next = quads.points[static_cast<std::size_t>(quad[static_cast<std::size_t>((k + 1) % 4)])];
    mean += next;
    edge += (next - here).norm() / 4;
  }
  mean /= 4;
  std::vector<Vec3> tries;
  for (double step : mean_steps) tries.push_back(here + step * (mean - here));
  Vec3 x = normal.unitOrthogonal();
  const Vec3 y = normal.cross(x);
  for (double step : search_steps)
    for (int d = 0; d < search_directions; ++d)
      tries.push_back(here + step * edge * (std::cos(d * M_PI / 4) * x + std::sin(d * M_PI / 4) * y));
  return tries;
}

/// The try (on S) that raises the smallest scaled Jacobian of v's quads the most
/// above `now`; the first of the mean's tries that raises it ends the search.
/// Nothing when no try raises it, or every one that does is farther than
/// options.max_move from v's original place.
std::optional<std::pair<Vec3, SurfaceLocation>> best_smoothing_move(
    const TriangleSoup& surface, const TriangleTree& tree, const LatticeQuads& quads, const QuadStar& star,
    const PointMoves& moves, const std::vector<Vec3>& normals, const QuadSmoothingOptions& options, int v) {
  const auto local_min = [&](const Vec3& p) {
    return worst_corner_jacobian(quads, star.quads_at[static_cast<std::size_t>(v)], v, p, normals);
  };
  const Vec3 here = quads.points[static_cast<std::size_t>(v)];
  const std::vector<Vec3> tries = smoothing_tries(quads, star, v, normals[static_cast<std::size_t>(v)]);
  double best = local_min(here) + min_jacobian_gain;
  std::optional<std::pair<Vec3, SurfaceLocation>> chosen;
  for (std::size_t t = 0; t < tries.size(); ++t) {
    if (t == mean_tries && chosen) break;  // the mean helped: no search
    const auto candidate = closest_location(surface, tree, tries[t]);
    const Vec3& p = candidate.first;
    if (options.max_move > 0 && (p - moves.original().points[static_cast<std::size_t>(v)]).norm() > options.max_move)
      continue;
    if (const double m = local_min(p); m > best) {
      best = m;
      chosen = candidate;
      if (t < mean_tries) break;
    }
  }
  return chosen;
}

}  // namespace

QuadSmoothingReport smooth_worst_quads(const TriangleSoup& surface, LatticeQuads& quads,
                                       const std::vector<int>& boundary_loop_of_point,
                                       const QuadSmoothingOptions& options) {
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  QuadSmoothingReport report;
  const QuadStar star(quads);
  std::vector<char> movable(quads.points.size(), 0);
  for (std::size_t v = 0; v < movable.size(); ++v) movable[v] = star.regular_interior(v, boundary_loop_of_point);

  const TriangleTree tree(surface.points, surface.triangles);
  std::vector<double> jacobian = sound_scaled_jacobians(polygon_mesh(quads));
  report.min_before = smallest(jacobian);
  report.min_after = report.min_before;
  PointMoves moves(quads);
  for (int round = 0; round < options.rounds; ++round) {
    // each candidate, in turn, to the try that raises its quads' worst corner the
    // most (the neighbours where they are, the normals of the round's start)
    const std::vector<Vec3> normals = vertex_normals(polygon_mesh(quads));
    std::size_t moved = 0;
    for (int v : smoothing_candidates(quads, jacobian, movable, options.below))
      if (const auto to = best_smoothing_move(surface, tree, quads, star, moves, normals, options, v)) {
        moves.move(static_cast<std::size_t>(v), *to);
        ++moved;
      }
    jacobian = sound_scaled_jacobians(polygon_mesh(quads));
    if (moved == 0) break;
  }
  report.min_after = smallest(jacobian);
  // each move raised its own quads' worst corner, with the neighbours' normals of
  // before it; should the whole have come out worse, it is undone
  if (report.min_after < report.min_before) {
    moves.undo_all();
    report.min_after = report.min_before;
  }
  report.moved_points = moves.count();
  return report;
}

}  // namespace qm
