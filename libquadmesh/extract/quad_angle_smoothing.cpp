#include "libquadmesh/extract/quad_angle_smoothing.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/internal/quad_star.h"
#include "libquadmesh/extract/deviation_refinement.h"
#include "libquadmesh/extract/quad_smoothing.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "libquadmesh/quality/size_band.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace qm {

namespace {

/// Both sides of the deviation between the quads and S: for the vertices of S in
/// `watched` (all when it is null) their distance to the quads and the quad
/// nearest to them; per quad the largest distance from its samples to S
/// (quad_to_surface).
struct Distances {
  std::vector<double> vertex;
  std::vector<int> nearest;
  std::vector<double> quad;
};

Distances distances(const TriangleSoup& surface, const TriangleTree& tree, const LatticeQuads& quads,
                    const std::vector<int>* watched) {
  Distances d;
  const TriangleTree quad_tree = quad_triangle_tree(quads);
  if (quad_tree.empty()) return d;
  std::vector<Vec3> watched_points;
  if (watched)
    for (int v : *watched) watched_points.push_back(surface.points[static_cast<std::size_t>(v)]);
  const std::vector<Vec3>& points = watched ? watched_points : surface.points;
  const std::vector<std::pair<Vec3, int>> nearest = quad_tree.closest_to_each(points);
  for (std::size_t i = 0; i < points.size(); ++i) {
    d.vertex.push_back((nearest[i].first - points[i]).norm());
    d.nearest.push_back(nearest[i].second);
  }
  d.quad = quads_to_surface(tree, quads);
  return d;
}

double mean_angle_deviation(const LatticeQuads& quads) {
  const std::vector<double> d = quad_shape_samples(polygon_mesh(quads)).angle_deviation_deg;
  return d.empty() ? 0.0 : std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
}

/// S's side of the deviation is watched where S is already this fraction of
/// max_deviation away from the quads (tips, protrusions): where the quads hug S,
/// a corner sliding along it shows on the quads' side first.
constexpr double watched_fraction = 0.25;
/// The gradient's central differences step, as a fraction of the shortest edge at the point.
constexpr double gradient_step = 1e-4;
/// The backtracking line search: from this fraction of the shortest edge, halved
/// while above 1/smallest_step_divisor of it (so down to 1/640 of the edge).
constexpr double first_step = 0.2;
constexpr double smallest_step_divisor = 128;
/// Passes that put back the corners around the quads that came out worse.
constexpr int put_back_passes = 3;

/// The vertices of S already farther than watched_fraction * max_deviation from the quads.
std::vector<int> watched_vertices(const Distances& before, double max_deviation) {
  std::vector<int> watched;
  for (std::size_t v = 0; v < before.vertex.size(); ++v)
    if (before.vertex[v] > watched_fraction * max_deviation) watched.push_back(static_cast<int>(v));
  return watched;
}

/// The angle deviations |angle - 90| (degrees) of the corners of the quads
/// around v, with v at p: their sum and the largest.
struct AngleDeviations {
  double sum = 0;
  double largest = 0;
};

AngleDeviations angle_deviations(const QuadStar& star, int v, const Vec3& p) {
  AngleDeviations d;
  for (int q : star.quads_at[static_cast<std::size_t>(v)]) {
    const std::array<Vec3, 4> c = quad_corners(star.quads, static_cast<std::size_t>(q), v, p);
    for (std::size_t k = 0; k < 4; ++k) {
      const double deviation = std::abs(corner_angle_deg(c[(k + 3) % 4], c[k], c[(k + 1) % 4]) - 90.0);
      d.sum += deviation;
      d.largest = std::max(d.largest, deviation);
    }
  }
  return d;
}

double angle_deviation_sum(const QuadStar& star, int v, const Vec3& p) { return angle_deviations(star, v, p).sum; }

/// The move of the regular point v: a step down the numerical gradient of
/// angle_deviation_sum in the plane normal to normals[v], backtracking until the
/// sum goes down with the smallest scaled Jacobian of v's quads at least
/// min(its value now, keep_jacobian) and the point within max_move of where it
/// started. Nothing when no step does.
std::optional<std::pair<Vec3, SurfaceLocation>> angle_move(const TriangleSoup& surface, const TriangleTree& tree,
                                                           const QuadStar& star, const PointMoves& moves,
                                                           const std::vector<Vec3>& normals,
                                                           const QuadAngleSmoothingOptions& options, int v) {
  const LatticeQuads& quads = star.quads;
  const std::size_t vi = static_cast<std::size_t>(v);
  const AngleDeviations at_start = angle_deviations(star, v, quads.points[vi]);
  if (at_start.largest < options.min_corner_deviation_deg) return std::nullopt;
  const auto worst = [&](const Vec3& p) { return worst_corner_jacobian(quads, star.quads_at[vi], v, p, normals); };
  const Vec3 here = quads.points[vi];
  double edge = std::numeric_limits<double>::infinity();
  for (int q : star.quads_at[vi])
    for (int u : quads.quads[static_cast<std::size_t>(q)])
      if (u != v) edge = std::min(edge, (quads.points[static_cast<std::size_t>(u)] - here).norm());
  if (!(edge > 0) || !std::isfinite(edge)) return std::nullopt;
  const double now = at_start.sum;
  // the gradient in the tangent plane, by central differences
  const Vec3& n = normals[vi];
  if (n.squaredNorm() == 0) return std::nullopt;
  const Vec3 x = n.unitOrthogonal(), y = n.cross(x);
  const double h = gradient_step * edge;
  const double gx = (angle_deviation_sum(star, v, here + h * x) - angle_deviation_sum(star, v, here - h * x)) / (2 * h);
  const double gy = (angle_deviation_sum(star, v, here + h * y) - angle_deviation_sum(star, v, here - h * y)) / (2 * h);
  const double g = std::hypot(gx, gy);
  if (!(g > 0)) return std::nullopt;
  const Vec3 down = -(gx * x + gy * y) / g;
  const double floor = std::min(worst(here), options.keep_jacobian);
  for (double step = first_step * edge; step > first_step * edge / smallest_step_divisor; step *= 0.5) {
    const auto candidate = closest_location(surface, tree, here + step * down);
    const Vec3& p = candidate.first;
    if (options.max_move > 0 && (p - moves.original().points[vi]).norm() > options.max_move) continue;
    if (angle_deviation_sum(star, v, p) < now && worst(p) >= floor) return candidate;
  }
  return std::nullopt;
}

/// One sweep over the movable points, each judged with its neighbours where they
/// are and the normals of the sweep's start. Returns the moves made.
std::size_t angle_round(const TriangleSoup& surface, const TriangleTree& tree, const QuadStar& star,
                        const std::vector<char>& movable, PointMoves& moves,
                        const QuadAngleSmoothingOptions& options) {
  const std::vector<Vec3> normals = vertex_normals(polygon_mesh(star.quads));
  std::size_t made = 0;
  for (std::size_t v = 0; v < movable.size(); ++v) {
    if (!movable[v]) continue;
    if (const auto to = angle_move(surface, tree, star, moves, normals, options, static_cast<int>(v))) {
      moves.move(v, *to);
      ++made;
    }
  }
  return made;
}

/// What the quads must not come out worse in, measured before the moves.
struct Before {
  std::vector<double> jacobian;  ///< per quad, sound_scaled_jacobian
  Distances distances;           ///< empty when max_deviation is 0
  std::vector<int> watched;      ///< the vertices of S whose distance is watched
  std::vector<double> mean_edge;  ///< per quad (quad_size_ratios at 1); empty when max_mean_edge is 0
};

/// The quads worse for the moves (see below; a quad may be listed more than once).
std::vector<std::size_t> worse_quads(const TriangleSoup& surface, const TriangleTree& tree, const LatticeQuads& quads,
                                     const Before& before, const QuadAngleSmoothingOptions& options) {
  std::vector<std::size_t> out;
  const PolygonMesh mesh = polygon_mesh(quads);
  const std::vector<double> jacobian = sound_scaled_jacobians(mesh);
  for (std::size_t q = 0; q < jacobian.size(); ++q)
    if (jacobian[q] < std::min(before.jacobian[q], options.keep_jacobian)) out.push_back(q);
  if (options.max_mean_edge > 0) {
    const std::vector<double> mean_edge = quad_size_ratios(mesh, 1.0);
    for (std::size_t q = 0; q < mean_edge.size(); ++q)
      if (before.mean_edge[q] <= options.max_mean_edge && mean_edge[q] > options.max_mean_edge) out.push_back(q);
  }
  if (options.max_deviation <= 0 || before.distances.quad.empty()) return out;
  const Distances after = distances(surface, tree, quads, &before.watched);
  for (std::size_t q = 0; q < after.quad.size(); ++q)
    if (after.quad[q] > std::max(before.distances.quad[q], options.max_deviation)) out.push_back(q);
  for (std::size_t i = 0; i < after.vertex.size(); ++i) {  // after.vertex: one per watched vertex
    const std::size_t v = static_cast<std::size_t>(before.watched[i]);
    if (after.vertex[i] > std::max(before.distances.vertex[v], options.max_deviation)) {
      out.push_back(static_cast<std::size_t>(before.distances.nearest[v]));
      out.push_back(static_cast<std::size_t>(after.nearest[i]));
    }
  }
  return out;
}

/// The moved corners of the quads `bad` and of the quads sharing a point with them go back.
void put_back_around(const std::vector<std::size_t>& bad, const QuadStar& star, PointMoves& moves) {
  std::vector<char> back(star.quads.points.size(), 0);
  for (std::size_t q : bad)
    for (int v : star.quads.quads[q])
      for (int q2 : star.quads_at[static_cast<std::size_t>(v)])
        for (int u : star.quads.quads[static_cast<std::size_t>(q2)]) back[static_cast<std::size_t>(u)] = 1;
  for (std::size_t v = 0; v < back.size(); ++v)
    if (back[v] && moves.moved(v)) moves.put_back(v);
}

}  // namespace

QuadAngleSmoothingReport smooth_quad_angles(const TriangleSoup& surface, LatticeQuads& quads,
                                            const std::vector<int>& boundary_loop_of_point,
                                            const std::vector<char>& fixed,
                                            const QuadAngleSmoothingOptions& options) {
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  QM_ASSERT(fixed.empty() || fixed.size() == quads.points.size());
  QuadAngleSmoothingReport report;
  const QuadStar star(quads);
  report.angle_dev_before = mean_angle_deviation(quads);
  report.angle_dev_after = report.angle_dev_before;
  if (quads.quads.empty()) return report;

  const TriangleTree tree(surface.points, surface.triangles);
  std::vector<char> movable(quads.points.size(), 0);
  for (std::size_t v = 0; v < movable.size(); ++v)
    movable[v] = star.regular_interior(v, boundary_loop_of_point) && (fixed.empty() || !fixed[v]);
  PointMoves moves(quads);
  bool moving = true;
  for (int round = 0; moving && round < options.rounds; ++round)
    moving = angle_round(surface, tree, star, movable, moves, options) > 0;
  for (int round = 0; moving && options.target_mean_deg > 0 && round < options.extra_rounds &&
                      mean_angle_deviation(quads) > options.target_mean_deg;
       ++round)
    moving = angle_round(surface, tree, star, movable, moves, options) > 0;
  if (moves.count() == 0) return report;
  // what the moved quads must not come out worse in, measured on the quads as they were
  Before before;
  const PolygonMesh original = polygon_mesh(moves.original());
  before.jacobian = sound_scaled_jacobians(original);
  if (options.max_deviation > 0) before.distances = distances(surface, tree, moves.original(), nullptr);
  before.watched = watched_vertices(before.distances, options.max_deviation);
  if (options.max_mean_edge > 0) before.mean_edge = quad_size_ratios(original, 1.0);
  // Moves were judged with the normals of the start of their round, and each with
  // its neighbours where they were then; a point sliding along a curved part makes
  // its quads cut across S, or leaves a tip of S farther from them. The quads
  // worse for it: a scaled Jacobian below min(before, keep_jacobian) (the quality
  // module's, with the final normals); a side of the deviation grown past
  // max(before, max_deviation), or the quads nearest (before and after) to a vertex
  // of S now that much farther; a mean edge grown past max_mean_edge. Their corners and those of the quads sharing a
  // point with them go back (put_back_passes times at most); should one still be
  // worse, every point goes back.
  std::vector<std::size_t> bad = worse_quads(surface, tree, quads, before, options);
  for (int pass = 0; pass < put_back_passes && !bad.empty(); ++pass) {
    put_back_around(bad, star, moves);
    bad = worse_quads(surface, tree, quads, before, options);
  }
  if (!bad.empty()) moves.undo_all();
  report.angle_dev_after = mean_angle_deviation(quads);
  if (!(report.angle_dev_after < report.angle_dev_before)) {
    moves.undo_all();
    report.angle_dev_after = report.angle_dev_before;
    return report;
  }
  report.moved_points = moves.count();
  return report;
}

}  // namespace qm
