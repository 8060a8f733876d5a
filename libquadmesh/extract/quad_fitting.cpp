#include "libquadmesh/extract/quad_fitting.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/deviation_refinement.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace qm {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 cgal_point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

/// The quads as a structure with per-point quads, for local changes.
struct QuadStar {
  const LatticeQuads& quads;
  std::vector<std::vector<int>> quads_at;

  explicit QuadStar(const LatticeQuads& q) : quads(q), quads_at(q.points.size()) {
    for (std::size_t k = 0; k < q.quads.size(); ++k)
      for (int v : q.quads[k]) quads_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(k));
  }

  /// The quads sharing a point with a quad at v (those at v included).
  std::vector<int> ring(int v) const {
    std::set<int> out;
    for (int a : quads_at[static_cast<std::size_t>(v)])
      for (int u : quads.quads[static_cast<std::size_t>(a)])
        out.insert(quads_at[static_cast<std::size_t>(u)].begin(), quads_at[static_cast<std::size_t>(u)].end());
    return {out.begin(), out.end()};
  }

  /// The smallest sound_scaled_jacobian (quad_quality.h) of the quads `ring` with
  /// point v at p, as the quality module computes it (vertex normals from the
  /// vector areas of the quads at each corner). With ring = ring(v), these are
  /// all the quads whose value depends on where v is.
  double min_scaled_jacobian(const std::vector<int>& ring, int v, const Vec3& p) const {
    double worst = std::numeric_limits<double>::infinity();
    for (int k : ring) {
      const auto c = corners(k, v, p);
      const Vec3 own = (c[2] - c[0]).cross(c[3] - c[1]);
      std::array<Vec3, 4> normals;
      for (std::size_t i = 0; i < 4; ++i) {
        Vec3 n = Vec3::Zero();
        for (int a : quads_at[static_cast<std::size_t>(quads.quads[static_cast<std::size_t>(k)][i])]) {
          const auto d = corners(a, v, p);
          n += (d[2] - d[0]).cross(d[3] - d[1]);
        }
        if (n.squaredNorm() == 0) n = own;
        if (n.squaredNorm() > 0) n.normalize();
        normals[i] = n;
      }
      worst = std::min(worst, sound_scaled_jacobian(c, normals));
    }
    return worst;
  }

  /// The corners of quad k with point v at p.
  std::array<Vec3, 4> corners(int k, int v, const Vec3& p) const {
    std::array<Vec3, 4> c = quad_corners(quads, static_cast<std::size_t>(k));
    for (std::size_t i = 0; i < 4; ++i)
      if (quads.quads[static_cast<std::size_t>(k)][i] == v) c[i] = p;
    return c;
  }
};

/// The squared distance from x to the quad's triangles v0v1v2 and v0v2v3 (the
/// degenerate ones left out; infinity when both are).
double squared_distance_to_quad(const Vec3& x, const std::array<Vec3, 4>& c) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : {Kernel::Triangle_3(cgal_point(c[0]), cgal_point(c[1]), cgal_point(c[2])),
                        Kernel::Triangle_3(cgal_point(c[0]), cgal_point(c[2]), cgal_point(c[3]))})
    if (!t.is_degenerate()) best = std::min(best, CGAL::squared_distance(cgal_point(x), t));
  return best;
}

/// What a position of one point gives locally.
struct LocalFit {
  double deviation = 0;          ///< largest distance between the quads at the point and S, both ways (see evaluate)
  double min_jacobian = 1;       ///< smallest corner scaled Jacobian of the ring's quads
  std::vector<int> nearest;      ///< per local sample, its nearest quad of the ring
  std::vector<double> distance;  ///< and its distance to it
};

}  // namespace

QuadFittingReport fit_quads_to_surface(const TriangleSoup& surface, LatticeQuads& quads,
                                       const std::vector<int>& boundary_loop_of_point,
                                       const QuadFittingOptions& options) {
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  QM_ASSERT(options.tolerance > 0);
  QuadFittingReport report;
  if (quads.quads.empty() || surface.triangles.empty()) return report;
  const QuadStar star(quads);
  const TriangleTree surface_tree(surface.points, surface.triangles);
  const TriangleTree index = quad_triangle_tree(quads);
  if (surface_tree.empty() || index.empty()) return report;  // all degenerate: nothing to measure
  // the deviation of quad_deviation(), in two parts: per quad, its side
  // (quad_to_surface); per sample of S, its nearest quad and the distance to it
  std::vector<double> quad_side(quads.quads.size());
  for (std::size_t k = 0; k < quads.quads.size(); ++k) quad_side[k] = quad_to_surface(surface_tree, quad_corners(quads, k));
  const std::vector<Vec3> samples = deviation_samples(surface, options.tolerance);
  std::vector<double> distance(samples.size());
  std::vector<int> nearest(samples.size());
  std::vector<std::vector<int>> samples_of(quads.quads.size());
  for (std::size_t s = 0; s < samples.size(); ++s) {
    const auto [p, k] = index.closest(samples[s]);
    distance[s] = (p - samples[s]).norm();
    nearest[s] = k;
    samples_of[static_cast<std::size_t>(k)].push_back(static_cast<int>(s));
  }
  // each sample's distance is to the quad it is assigned to, so after moves this
  // is an upper bound of quad_deviation()'s largest value (equal unless a sample
  // came nearer to a quad outside the ring it was measured against)
  const auto deviation_now = [&] {
    return std::max(*std::max_element(quad_side.begin(), quad_side.end()),
                    samples.empty() ? 0.0 : *std::max_element(distance.begin(), distance.end()));
  };
  report.deviation_before = deviation_now();
  report.deviation_after = report.deviation_before;
  if (report.deviation_before <= options.tolerance) return report;
  const auto min_jacobian_now = [&] {
    const std::vector<double> j = sound_scaled_jacobians(polygon_mesh(quads));
    return j.empty() ? 1.0 : *std::min_element(j.begin(), j.end());
  };
  const double jacobian_before = min_jacobian_now();
  std::vector<char> movable(quads.points.size(), 0);  // regular interior points only
  for (std::size_t v = 0; v < movable.size(); ++v)
    movable[v] = boundary_loop_of_point[v] < 0 && star.quads_at[v].size() == 4;

  // v at p: the quads at v measured against S, and the S samples assigned to them
  // against v's ring (a sample assigned to another quad keeps its distance or gets
  // nearer). The evaluation stops as soon as the ring's scaled Jacobian is below
  // `floor` or the deviation reaches `bound` (the move would not be kept), leaving
  // `nearest` and `distance` incomplete; `local` starts with its farthest samples.
  const auto evaluate = [&](int v, const Vec3& p, const std::vector<int>& ring, const std::vector<int>& local,
                            double floor, double bound) {
    LocalFit fit;
    fit.min_jacobian = star.min_scaled_jacobian(ring, v, p);
    if (fit.min_jacobian < floor) return fit;
    for (int k : star.quads_at[static_cast<std::size_t>(v)])
      fit.deviation = std::max(fit.deviation, quad_to_surface(surface_tree, star.corners(k, v, p)));
    std::vector<std::array<Vec3, 4>> ring_corners;
    for (int k : ring) ring_corners.push_back(star.corners(k, v, p));
    for (int s : local) {
      if (fit.deviation >= bound) break;
      double best = std::numeric_limits<double>::infinity();
      int quad = -1;
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (const double d = squared_distance_to_quad(samples[static_cast<std::size_t>(s)], ring_corners[i]); d < best) {
          best = d;
          quad = ring[i];
        }
      fit.nearest.push_back(quad);
      fit.distance.push_back(std::sqrt(best));
      fit.deviation = std::max(fit.deviation, std::sqrt(best));
    }
    return fit;
  };

  const LatticeQuads original = quads;
  std::set<int> moved;
  for (int round = 0; round < options.rounds; ++round) {
    std::vector<int> far;
    for (std::size_t s = 0; s < samples.size(); ++s)
      if (distance[s] > options.tolerance) far.push_back(static_cast<int>(s));
    std::sort(far.begin(), far.end(), [&](int a, int b) {
      return distance[static_cast<std::size_t>(a)] > distance[static_cast<std::size_t>(b)];
    });
    std::vector<char> tried(quads.quads.size(), 0);
    std::size_t moves = 0;
    for (int s : far) {
      const std::size_t si = static_cast<std::size_t>(s);
      const int q = nearest[si];
      if (distance[si] <= options.tolerance || tried[static_cast<std::size_t>(q)]) continue;
      tried[static_cast<std::size_t>(q)] = 1;
      struct Move {
        int v = -1;
        std::pair<Vec3, SurfaceLocation> to;
        double gain = 0;
        LocalFit fit;
        std::vector<int> ring, local;
      } best;
      for (int v : quads.quads[static_cast<std::size_t>(q)]) {
        if (!movable[static_cast<std::size_t>(v)]) continue;
        const Vec3 here = quads.points[static_cast<std::size_t>(v)];
        const std::vector<int> ring = star.ring(v);
        std::vector<int> local;
        double now = 0;
        for (int k : star.quads_at[static_cast<std::size_t>(v)]) {
          now = std::max(now, quad_side[static_cast<std::size_t>(k)]);
          local.insert(local.end(), samples_of[static_cast<std::size_t>(k)].begin(),
                       samples_of[static_cast<std::size_t>(k)].end());
        }
        const auto farther = [&](int a, int b) {
          return distance[static_cast<std::size_t>(a)] > distance[static_cast<std::size_t>(b)];
        };
        std::partial_sort(local.begin(), local.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(8, local.size())),
                          local.end(), farther);
        if (!local.empty()) now = std::max(now, distance[static_cast<std::size_t>(local.front())]);
        const double floor = std::min(options.min_scaled_jacobian, star.min_scaled_jacobian(ring, v, here));
        for (double t : {1.0, 0.6, 0.3}) {
          auto to = closest_location(surface, surface_tree, here + t * (samples[si] - here));
          // kept only if better than the best so far, by a margin
          const double bound = now - std::max(best.gain, 1e-9 * options.tolerance);
          LocalFit fit = evaluate(v, to.first, ring, local, floor, bound);
          if (fit.min_jacobian >= floor && fit.deviation < bound)
            best = {v, std::move(to), now - fit.deviation, std::move(fit), ring, local};
        }
      }
      if (best.v < 0) continue;
      quads.points[static_cast<std::size_t>(best.v)] = best.to.first;
      quads.locations[static_cast<std::size_t>(best.v)] = best.to.second;
      moved.insert(best.v);
      ++moves;
      // the quads at the point and their samples, as evaluated
      for (int k : star.quads_at[static_cast<std::size_t>(best.v)]) {
        quad_side[static_cast<std::size_t>(k)] = quad_to_surface(surface_tree, quad_corners(quads, static_cast<std::size_t>(k)));
        samples_of[static_cast<std::size_t>(k)].clear();
      }
      for (std::size_t i = 0; i < best.local.size(); ++i) {
        const std::size_t x = static_cast<std::size_t>(best.local[i]);
        nearest[x] = best.fit.nearest[i];
        distance[x] = best.fit.distance[i];
        samples_of[static_cast<std::size_t>(nearest[x])].push_back(static_cast<int>(x));
      }
    }
    if (moves == 0) break;
  }
  report.deviation_after = deviation_now();
  // each move lowered the deviation where it was and kept its ring above the floor
  // (or where it was), so this only guards against rounding
  if (report.deviation_after > report.deviation_before * (1 + 1e-9) ||
      min_jacobian_now() < std::min(jacobian_before, options.min_scaled_jacobian) - 1e-12) {
    quads = original;
    report.deviation_after = report.deviation_before;
    moved.clear();
  }
  report.moved_points = moved.size();
  return report;
}

}  // namespace qm
