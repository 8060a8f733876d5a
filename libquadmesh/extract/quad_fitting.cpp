#include "libquadmesh/extract/quad_fitting.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/internal/quad_star.h"
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
#include <vector>

namespace qm {

namespace {

/// The tries of a corner: on S at these fractions of the way to the far sample.
constexpr double fractions_to_sample[] = {1.0, 0.6, 0.3};
/// A try is kept only if it lowers the local deviation by more than the best
/// try so far, and at least by this fraction of the tolerance.
constexpr double min_relative_gain = 1e-9;
/// The local samples are evaluated farthest first; this many are sorted (the
/// evaluation usually stops among them).
constexpr std::size_t farthest_sorted = 8;
/// The final check only guards against rounding: a relative margin on the
/// deviation, an absolute one (scaled Jacobian units) on the Jacobian.
constexpr double rounding_margin_deviation = 1e-9;
constexpr double rounding_margin_jacobian = 1e-12;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;

Kernel::Point_3 cgal_point(const Vec3& p) { return {p.x(), p.y(), p.z()}; }

/// The smallest sound_scaled_jacobian (quad_quality.h) of the quads `ring` with
/// point v at p, as the quality module computes it (vertex normals from the
/// vector areas of the quads at each corner). With ring = star.ring(v), these are
/// all the quads whose value depends on where v is.
double min_scaled_jacobian(const QuadStar& star, const std::vector<int>& ring, int v, const Vec3& p) {
  double worst = std::numeric_limits<double>::infinity();
  for (int k : ring) {
    const auto c = quad_corners(star.quads, static_cast<std::size_t>(k), v, p);
    const Vec3 own = (c[2] - c[0]).cross(c[3] - c[1]);
    std::array<Vec3, 4> normals;
    for (std::size_t i = 0; i < 4; ++i) {
      Vec3 n = Vec3::Zero();
      for (int a : star.quads_at[static_cast<std::size_t>(star.quads.quads[static_cast<std::size_t>(k)][i])]) {
        const auto d = quad_corners(star.quads, static_cast<std::size_t>(a), v, p);
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

double min_scaled_jacobian(const LatticeQuads& quads) {
  const std::vector<double> j = sound_scaled_jacobians(polygon_mesh(quads));
  return j.empty() ? 1.0 : *std::min_element(j.begin(), j.end());
}

/// The squared distance from x to the quad's triangles v0v1v2 and v0v2v3 (the
/// degenerate ones left out; infinity when both are).
double squared_distance_to_quad(const Vec3& x, const std::array<Vec3, 4>& c) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& t : {Kernel::Triangle_3(cgal_point(c[0]), cgal_point(c[1]), cgal_point(c[2])),
                        Kernel::Triangle_3(cgal_point(c[0]), cgal_point(c[2]), cgal_point(c[3]))})
    if (!t.is_degenerate()) best = std::min(best, CGAL::squared_distance(cgal_point(x), t));
  return best;
}

/// The deviation of quad_deviation(), in two parts: per quad, its side
/// (quad_to_surface); per sample of S, its nearest quad and the distance to it.
/// After moves each sample's distance is to the quad it was last assigned to, so
/// largest() is an upper bound of quad_deviation()'s largest value (equal unless a
/// sample came nearer to a quad outside the ring it was measured against).
struct Deviation {
  std::vector<double> quad_side;
  std::vector<Vec3> samples;
  std::vector<double> distance;
  std::vector<int> nearest;
  std::vector<std::vector<int>> samples_of;  ///< per quad, the samples assigned to it

  double largest() const {
    return std::max(*std::max_element(quad_side.begin(), quad_side.end()),
                    samples.empty() ? 0.0 : *std::max_element(distance.begin(), distance.end()));
  }
};

/// Precondition: `surface_tree` and `quad_tree` are not empty.
Deviation measure_deviation(const TriangleSoup& surface, const TriangleTree& surface_tree,
                            const TriangleTree& quad_tree, const LatticeQuads& quads, double tolerance) {
  Deviation d;
  d.quad_side = quads_to_surface(surface_tree, quads);
  d.samples = deviation_samples(surface, tolerance);
  d.distance.resize(d.samples.size());
  d.nearest.resize(d.samples.size());
  d.samples_of.resize(quads.quads.size());
  const std::vector<std::pair<Vec3, int>> nearest = quad_tree.closest_to_each(d.samples);
  for (std::size_t s = 0; s < d.samples.size(); ++s) {
    const auto& [p, k] = nearest[s];
    d.distance[s] = (p - d.samples[s]).norm();
    d.nearest[s] = k;
    d.samples_of[static_cast<std::size_t>(k)].push_back(static_cast<int>(s));
  }
  return d;
}

/// What a position of one point gives locally.
struct LocalFit {
  double deviation = 0;          ///< largest distance between the quads at the point and S, both ways (see evaluate)
  double min_jacobian = 1;       ///< smallest corner scaled Jacobian of the ring's quads
  std::vector<int> nearest;      ///< per local sample, its nearest quad of the ring
  std::vector<double> distance;  ///< and its distance to it
};

/// The best move found for the corners of one quad.
struct Move {
  int v = -1;
  std::pair<Vec3, SurfaceLocation> to;
  double gain = 0;  ///< how much it lowers the local deviation
  LocalFit fit;
  std::vector<int> ring, local;  ///< the quads it was evaluated against, and the samples
};

/// The moves of the fitting and the deviation they leave, updated move by move.
class CornerFitting {
 public:
  CornerFitting(const TriangleSoup& surface, const TriangleTree& surface_tree, const QuadStar& star,
                LatticeQuads& quads, Deviation& deviation, PointMoves& moves, const std::vector<char>& movable,
                const QuadFittingOptions& options)
      : surface_(surface), surface_tree_(surface_tree), star_(star), quads_(quads), dev_(deviation),
        moves_(moves), movable_(movable), options_(options) {}

  /// One round: for the samples farther than the tolerance, farthest first, the
  /// best move of a corner of their nearest quad (each quad once). Returns the moves made.
  std::size_t round() {
    std::vector<int> far;
    for (std::size_t s = 0; s < dev_.samples.size(); ++s)
      if (dev_.distance[s] > options_.tolerance) far.push_back(static_cast<int>(s));
    std::sort(far.begin(), far.end(), [&](int a, int b) {
      return dev_.distance[static_cast<std::size_t>(a)] > dev_.distance[static_cast<std::size_t>(b)];
    });
    std::vector<char> tried(quads_.quads.size(), 0);
    std::size_t made = 0;
    for (int s : far) {
      const std::size_t si = static_cast<std::size_t>(s);
      const int q = dev_.nearest[si];
      if (dev_.distance[si] <= options_.tolerance || tried[static_cast<std::size_t>(q)]) continue;
      tried[static_cast<std::size_t>(q)] = 1;
      Move best;
      for (int v : quads_.quads[static_cast<std::size_t>(q)])
        if (movable_[static_cast<std::size_t>(v)]) try_corner(v, dev_.samples[si], best);
      if (best.v < 0) continue;
      apply(best);
      ++made;
    }
    return made;
  }

 private:
  /// The tries of corner v towards `sample`; `best` becomes one that beats it.
  void try_corner(int v, const Vec3& sample, Move& best) const {
    const Vec3 here = quads_.points[static_cast<std::size_t>(v)];
    const std::vector<int> ring = star_.ring(v);
    std::vector<int> local;
    double now = 0;
    for (int k : star_.quads_at[static_cast<std::size_t>(v)]) {
      now = std::max(now, dev_.quad_side[static_cast<std::size_t>(k)]);
      local.insert(local.end(), dev_.samples_of[static_cast<std::size_t>(k)].begin(),
                   dev_.samples_of[static_cast<std::size_t>(k)].end());
    }
    const auto farther = [&](int a, int b) {
      return dev_.distance[static_cast<std::size_t>(a)] > dev_.distance[static_cast<std::size_t>(b)];
    };
    std::partial_sort(local.begin(),
                      local.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(farthest_sorted, local.size())),
                      local.end(), farther);
    if (!local.empty()) now = std::max(now, dev_.distance[static_cast<std::size_t>(local.front())]);
    const double floor = std::min(options_.min_scaled_jacobian, min_scaled_jacobian(star_, ring, v, here));
    for (double t : fractions_to_sample) {
      auto to = closest_location(surface_, surface_tree_, here + t * (sample - here));
      // kept only if better than the best so far, by a margin
      const double bound = now - std::max(best.gain, min_relative_gain * options_.tolerance);
      LocalFit fit = evaluate(v, to.first, ring, local, floor, bound);
      if (fit.min_jacobian >= floor && fit.deviation < bound)
        best = {v, std::move(to), now - fit.deviation, std::move(fit), ring, local};
    }
  }

  /// v at p: the quads at v measured against S, and the S samples assigned to them
  /// against v's ring (a sample assigned to another quad keeps its distance or gets
  /// nearer). The evaluation stops as soon as the ring's scaled Jacobian is below
  /// `floor` or the deviation reaches `bound` (the move would not be kept), leaving
  /// `nearest` and `distance` incomplete; `local` starts with its farthest samples.
  LocalFit evaluate(int v, const Vec3& p, const std::vector<int>& ring, const std::vector<int>& local, double floor,
                    double bound) const {
    LocalFit fit;
    fit.min_jacobian = min_scaled_jacobian(star_, ring, v, p);
    if (fit.min_jacobian < floor) return fit;
    for (int k : star_.quads_at[static_cast<std::size_t>(v)])
      fit.deviation =
          std::max(fit.deviation, quad_to_surface(surface_tree_, quad_corners(quads_, static_cast<std::size_t>(k), v, p)));
    std::vector<std::array<Vec3, 4>> ring_corners;
    for (int k : ring) ring_corners.push_back(quad_corners(quads_, static_cast<std::size_t>(k), v, p));
    for (int s : local) {
      if (fit.deviation >= bound) break;
      double best = std::numeric_limits<double>::infinity();
      int quad = -1;
      for (std::size_t i = 0; i < ring.size(); ++i)
        if (const double d = squared_distance_to_quad(dev_.samples[static_cast<std::size_t>(s)], ring_corners[i]);
            d < best) {
          best = d;
          quad = ring[i];
        }
      fit.nearest.push_back(quad);
      fit.distance.push_back(std::sqrt(best));
      fit.deviation = std::max(fit.deviation, std::sqrt(best));
    }
    return fit;
  }

  /// Makes the move and updates the quads at the point and their samples, as evaluated.
  void apply(const Move& best) {
    moves_.move(static_cast<std::size_t>(best.v), best.to);
    for (int k : star_.quads_at[static_cast<std::size_t>(best.v)]) {
      dev_.quad_side[static_cast<std::size_t>(k)] =
          quad_to_surface(surface_tree_, quad_corners(quads_, static_cast<std::size_t>(k)));
      dev_.samples_of[static_cast<std::size_t>(k)].clear();
    }
    for (std::size_t i = 0; i < best.local.size(); ++i) {
      const std::size_t x = static_cast<std::size_t>(best.local[i]);
      dev_.nearest[x] = best.fit.nearest[i];
      dev_.distance[x] = best.fit.distance[i];
      dev_.samples_of[static_cast<std::size_t>(dev_.nearest[x])].push_back(static_cast<int>(x));
    }
  }

  const TriangleSoup& surface_;
  const TriangleTree& surface_tree_;
  const QuadStar& star_;
  LatticeQuads& quads_;
  Deviation& dev_;
  PointMoves& moves_;
  const std::vector<char>& movable_;
  const QuadFittingOptions& options_;
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
  const TriangleTree quad_tree = quad_triangle_tree(quads);
  if (surface_tree.empty() || quad_tree.empty()) return report;  // all degenerate: nothing to measure
  Deviation deviation = measure_deviation(surface, surface_tree, quad_tree, quads, options.tolerance);
  report.deviation_before = deviation.largest();
  report.deviation_after = report.deviation_before;
  if (report.deviation_before <= options.tolerance) return report;
  const double jacobian_before = min_scaled_jacobian(quads);
  std::vector<char> movable(quads.points.size(), 0);
  for (std::size_t v = 0; v < movable.size(); ++v) movable[v] = star.regular_interior(v, boundary_loop_of_point);

  PointMoves moves(quads);
  CornerFitting fitting(surface, surface_tree, star, quads, deviation, moves, movable, options);
  for (int round = 0; round < options.rounds; ++round)
    if (fitting.round() == 0) break;
  report.deviation_after = deviation.largest();
  // each move lowered the deviation where it was and kept its ring above the floor
  // (or where it was), so this only guards against rounding
  if (report.deviation_after > report.deviation_before * (1 + rounding_margin_deviation) ||
      min_scaled_jacobian(quads) < std::min(jacobian_before, options.min_scaled_jacobian) - rounding_margin_jacobian) {
    moves.undo_all();
    report.deviation_after = report.deviation_before;
  }
  report.moved_points = moves.count();
  return report;
}

}  // namespace qm
