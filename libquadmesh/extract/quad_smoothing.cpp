#include "libquadmesh/extract/quad_smoothing.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
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

QuadSmoothingReport smooth_worst_quads(const TriangleSoup& surface, LatticeQuads& quads,
                                       const std::vector<int>& boundary_loop_of_point,
                                       const QuadSmoothingOptions& options) {
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  QuadSmoothingReport report;
  const std::size_t nP = quads.points.size();
  std::vector<std::vector<int>> quads_at(nP);
  for (std::size_t q = 0; q < quads.quads.size(); ++q)
    for (int v : quads.quads[q]) quads_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(q));
  // regular interior points only
  std::vector<char> movable(nP, 0);
  for (std::size_t v = 0; v < nP; ++v) movable[v] = boundary_loop_of_point[v] < 0 && quads_at[v].size() == 4;

  const TriangleTree tree(surface.points, surface.triangles);
  std::vector<double> jacobian = sound_scaled_jacobians(polygon_mesh(quads));
  report.min_before = jacobian.empty() ? 1.0 : *std::min_element(jacobian.begin(), jacobian.end());
  report.min_after = report.min_before;
  const LatticeQuads original = quads;
  std::set<int> moved;
  for (int round = 0; round < options.rounds; ++round) {
    const std::vector<Vec3> normals = vertex_normals(polygon_mesh(quads));
    auto local_min = [&](int v, const Vec3& p) {
      return worst_corner_jacobian(quads, quads_at[static_cast<std::size_t>(v)], v, p, normals);
    };
    std::set<int> candidates;
    for (std::size_t q = 0; q < quads.quads.size(); ++q)
      if (jacobian[q] < options.below)
        for (int v : quads.quads[q])
          if (movable[static_cast<std::size_t>(v)]) candidates.insert(v);
    std::size_t moves = 0;
    for (int v : candidates) {
      // the mean of the edge neighbours (one per quad, valence 4) and of the edges
      const Vec3 here = quads.points[static_cast<std::size_t>(v)];
      Vec3 mean = Vec3::Zero();
      double edge = 0;
      for (int q : quads_at[static_cast<std::size_t>(v)]) {
        const auto& quad = quads.quads[static_cast<std::size_t>(q)];
        const int k = static_cast<int>(std::find(quad.begin(), quad.end(), v) - quad.begin());
        const Vec3& next = quads.points[static_cast<std::size_t>(quad[static_cast<std::size_t>((k + 1) % 4)])];
        mean += next;
        edge += (next - here).norm() / 4;
      }
      mean /= 4;
      const double now = local_min(v, here);
      // candidates: towards the mean, then (when that does not help, e.g. beside a
      // singular vertex) a pattern search in the tangent plane; the best one that
      // raises the worst corner is taken
      std::vector<Vec3> tries;
      for (double step : {1.0, 0.5, 0.25}) tries.push_back(here + step * (mean - here));
      {
        const Vec3& n = normals[static_cast<std::size_t>(v)];
        Vec3 x = n.unitOrthogonal();
        const Vec3 y = n.cross(x);
        for (double step : {0.2, 0.1, 0.05})
          for (int d = 0; d < 8; ++d)
            tries.push_back(here + step * edge * (std::cos(d * M_PI / 4) * x + std::sin(d * M_PI / 4) * y));
      }
      double best = now + 1e-9;
      bool found = false;
      std::pair<Vec3, SurfaceLocation> chosen{here, SurfaceLocation{}};
      for (std::size_t t = 0; t < tries.size(); ++t) {
        if (t == 3 && found) break;  // the mean helped: no search
        const auto candidate = closest_location(surface, tree, tries[t]);
        const Vec3& p = candidate.first;
        if (options.max_move > 0 && (p - original.points[static_cast<std::size_t>(v)]).norm() > options.max_move)
          continue;
        if (const double m = local_min(v, p); m > best) {
          best = m;
          chosen = candidate;
          found = true;
          if (t < 3) break;
        }
      }
      if (found) {
        quads.points[static_cast<std::size_t>(v)] = chosen.first;
        quads.locations[static_cast<std::size_t>(v)] = chosen.second;
        moved.insert(v);
        ++moves;
      }
    }
    jacobian = sound_scaled_jacobians(polygon_mesh(quads));
    if (moves == 0) break;
  }
  report.min_after = jacobian.empty() ? 1.0 : *std::min_element(jacobian.begin(), jacobian.end());
  // each move raised its own quads' worst corner, with the neighbours' normals of
  // before it; should the whole have come out worse, it is undone
  if (report.min_after < report.min_before) {
    quads = original;
    report.min_after = report.min_before;
    moved.clear();
  }
  report.moved_points = moved.size();
  return report;
}

}  // namespace qm
