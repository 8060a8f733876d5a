#include "libquadmesh/extract/quad_angle_smoothing.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/deviation_refinement.h"
#include "libquadmesh/extract/quad_smoothing.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

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
  auto add = [&](const Vec3& s) {
    const auto [p, k] = quad_tree.closest(s);
    d.vertex.push_back((p - s).norm());
    d.nearest.push_back(k);
  };
  if (!watched)
    for (const Vec3& s : surface.points) add(s);
  else
    for (int v : *watched) add(surface.points[static_cast<std::size_t>(v)]);
  for (std::size_t k = 0; k < quads.quads.size(); ++k) d.quad.push_back(quad_to_surface(tree, quad_corners(quads, k)));
  return d;
}

double mean_angle_deviation(const LatticeQuads& quads) {
  const std::vector<double> d = quad_shape_samples(polygon_mesh(quads)).angle_deviation_deg;
  return d.empty() ? 0.0 : std::accumulate(d.begin(), d.end(), 0.0) / static_cast<double>(d.size());
}

}  // namespace

QuadAngleSmoothingReport smooth_quad_angles(const TriangleSoup& surface, LatticeQuads& quads,
                                            const std::vector<int>& boundary_loop_of_point,
                                            const std::vector<char>& fixed,
                                            const QuadAngleSmoothingOptions& options) {
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  QM_ASSERT(fixed.empty() || fixed.size() == quads.points.size());
  QuadAngleSmoothingReport report;
  const std::size_t nP = quads.points.size();
  std::vector<std::vector<int>> quads_at(nP);
  for (std::size_t q = 0; q < quads.quads.size(); ++q)
    for (int v : quads.quads[q]) quads_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(q));
  report.angle_dev_before = mean_angle_deviation(quads);
  report.angle_dev_after = report.angle_dev_before;
  if (quads.quads.empty()) return report;

  const TriangleTree tree(surface.points, surface.triangles);
  const std::vector<double> jacobian_before = sound_scaled_jacobians(polygon_mesh(quads));
  const LatticeQuads original = quads;
  const Distances before = options.max_deviation > 0 ? distances(surface, tree, quads, nullptr) : Distances{};
  // S's side is watched where S is already a quarter of the tolerance away from
  // the quads (tips, protrusions): where the quads hug S, a corner sliding along
  // it shows on the quads' side first
  std::vector<int> watched;
  for (std::size_t v = 0; v < before.vertex.size(); ++v)
    if (before.vertex[v] > 0.25 * options.max_deviation) watched.push_back(static_cast<int>(v));
  std::vector<char> moved(nP, 0);
  for (int round = 0; round < options.rounds; ++round) {
    const std::vector<Vec3> normals = vertex_normals(polygon_mesh(quads));
    // the sum of the angle deviations (degrees) of the corners of the quads around
    // v with v at p; and their smallest scaled Jacobian
    auto angle_sum = [&](int v, const Vec3& p) {
      double sum = 0;
      for (int q : quads_at[static_cast<std::size_t>(v)]) {
        const std::array<Vec3, 4> c = quad_corners(quads, static_cast<std::size_t>(q), v, p);
        for (std::size_t k = 0; k < 4; ++k) sum += std::abs(corner_angle_deg(c[(k + 3) % 4], c[k], c[(k + 1) % 4]) - 90.0);
      }
      return sum;
    };
    auto worst = [&](int v, const Vec3& p) {
      return worst_corner_jacobian(quads, quads_at[static_cast<std::size_t>(v)], v, p, normals);
    };
    std::size_t moves = 0;
    for (std::size_t vi = 0; vi < nP; ++vi) {
      const int v = static_cast<int>(vi);
      if (boundary_loop_of_point[vi] >= 0 || quads_at[vi].size() != 4 || (!fixed.empty() && fixed[vi])) continue;
      const Vec3 here = quads.points[vi];
      double edge = std::numeric_limits<double>::infinity();
      for (int q : quads_at[vi])
        for (int u : quads.quads[static_cast<std::size_t>(q)])
          if (u != v) edge = std::min(edge, (quads.points[static_cast<std::size_t>(u)] - here).norm());
      if (!(edge > 0) || !std::isfinite(edge)) continue;
      const double now = angle_sum(v, here);
      // the gradient in the tangent plane, by central differences
      const Vec3& n = normals[vi];
      if (n.squaredNorm() == 0) continue;
      const Vec3 x = n.unitOrthogonal(), y = n.cross(x);
      const double h = 1e-4 * edge;
      const double gx = (angle_sum(v, here + h * x) - angle_sum(v, here - h * x)) / (2 * h);
      const double gy = (angle_sum(v, here + h * y) - angle_sum(v, here - h * y)) / (2 * h);
      const double g = std::hypot(gx, gy);
      if (!(g > 0)) continue;
      const Vec3 down = -(gx * x + gy * y) / g;
      const double floor = std::min(worst(v, here), options.keep_jacobian);
      // a backtracking step, from a fifth of the shortest edge down to 1/640 of it
      for (double step = 0.2 * edge; step > 0.2 * edge / 128; step *= 0.5) {
        const auto candidate = closest_location(surface, tree, here + step * down);
        const Vec3& p = candidate.first;
        if (options.max_move > 0 && (p - original.points[vi]).norm() > options.max_move) continue;
        if (angle_sum(v, p) < now && worst(v, p) >= floor) {
          quads.points[vi] = p;
          quads.locations[vi] = candidate.second;
          moved[vi] = 1;
          ++moves;
          break;
        }
      }
    }
    if (moves == 0) break;
  }
  // Moves were judged with the normals of the start of their round, and each with
  // its neighbours where they were then; a point sliding along a curved part makes
  // its quads cut across S, or leaves a tip of S farther from them. The quads
  // worse for it: a scaled Jacobian below min(before, keep_jacobian) (the quality
  // module's, with the final normals); a side of the deviation grown past
  // max(before, max_deviation), or the quads nearest (before and after) to a vertex
  // of S now that much farther. Their corners and those of the quads sharing a
  // point with them go back (three times at most); should one still be worse,
  // every point goes back.
  auto worse = [&] {
    std::vector<std::size_t> out;
    const std::vector<double> jacobian = sound_scaled_jacobians(polygon_mesh(quads));
    for (std::size_t q = 0; q < jacobian.size(); ++q)
      if (jacobian[q] < std::min(jacobian_before[q], options.keep_jacobian)) out.push_back(q);
    if (options.max_deviation <= 0 || before.quad.empty()) return out;
    const Distances after = distances(surface, tree, quads, &watched);
    for (std::size_t q = 0; q < after.quad.size(); ++q)
      if (after.quad[q] > std::max(before.quad[q], options.max_deviation)) out.push_back(q);
    for (std::size_t i = 0; i < after.vertex.size(); ++i) {  // after.vertex: one per watched vertex
      const std::size_t v = static_cast<std::size_t>(watched[i]);
      if (after.vertex[i] > std::max(before.vertex[v], options.max_deviation)) {
        out.push_back(static_cast<std::size_t>(before.nearest[v]));
        out.push_back(static_cast<std::size_t>(after.nearest[i]));
      }
    }
    return out;
  };
  std::vector<std::size_t> bad = worse();
  for (int pass = 0; pass < 3 && !bad.empty(); ++pass) {
    std::vector<char> back(nP, 0);
    for (std::size_t q : bad)
      for (int v : quads.quads[q])
        for (int q2 : quads_at[static_cast<std::size_t>(v)])
          for (int u : quads.quads[static_cast<std::size_t>(q2)]) back[static_cast<std::size_t>(u)] = 1;
    for (std::size_t v = 0; v < nP; ++v)
      if (back[v] && moved[v]) {
        quads.points[v] = original.points[v];
        quads.locations[v] = original.locations[v];
        moved[v] = 0;
      }
    bad = worse();
  }
  if (!bad.empty()) {
    quads = original;
    std::fill(moved.begin(), moved.end(), 0);
  }
  report.angle_dev_after = mean_angle_deviation(quads);
  if (!(report.angle_dev_after < report.angle_dev_before)) {
    quads = original;
    report.angle_dev_after = report.angle_dev_before;
    return report;
  }
  report.moved_points = static_cast<std::size_t>(std::count(moved.begin(), moved.end(), 1));
  return report;
}

}  // namespace qm
