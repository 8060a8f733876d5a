#include "libquadmesh/extract/deviation_refinement.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/quad_chords.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "libquadmesh/quality/quad_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace qm {

namespace {

/// Places new points on S: boundary midpoints on S's boundary, the others on S.
class Placement {
 public:
  Placement(const TriangleSoup& s, const SurfaceAdjacency& adjacency, const TriangleTree& surface)
      : s_(s), adjacency_(adjacency), surface_(surface) {
    for (const auto& loop : adjacency.boundary_loops)
      for (std::size_t i = 0; i < loop.size(); ++i) {
        const int a = loop[i], b = loop[(i + 1) % loop.size()];
        boundary_.add(point(a), point(b), static_cast<int>(ends_.size()));
        ends_.push_back({a, b});
      }
    if (!ends_.empty()) boundary_.build();
  }

  std::pair<Vec3, SurfaceLocation> on_surface(const Vec3& guess) const {
    return closest_location(s_, surface_, guess);
  }

  std::pair<Vec3, SurfaceLocation> on_boundary(const Vec3& guess) const {
    if (boundary_.empty()) return on_surface(guess);
    const auto [p, segment] = boundary_.closest(guess);
    const auto [a, b] = ends_[static_cast<std::size_t>(segment)];
    const Vec3 ab = point(b) - point(a);
    const double t = std::clamp((p - point(a)).dot(ab) / std::max(ab.squaredNorm(), 1e-300), 0.0, 1.0);
    const EdgeCorner e = adjacency_.find(a, b);
    QM_ASSERT(e.face >= 0);
    SurfaceLocation loc;
    loc.face = e.face;
    loc.barycentric = {0.0, 0.0, 0.0};
    loc.barycentric[static_cast<std::size_t>(e.i)] = 1 - t;
    loc.barycentric[static_cast<std::size_t>(e.j)] = t;
    if (t <= 0 || t >= 1) {
      loc.kind = SurfaceLocation::Kind::vertex;
      loc.a = t <= 0 ? a : b;
    } else {
      loc.kind = SurfaceLocation::Kind::edge;
      loc.a = std::min(a, b);
      loc.b = std::max(a, b);
    }
    return {p, loc};
  }

 private:
  const Vec3& point(int v) const { return s_.points[static_cast<std::size_t>(v)]; }
  const TriangleSoup& s_;
  const SurfaceAdjacency& adjacency_;
  const TriangleTree& surface_;
  std::vector<std::pair<int, int>> ends_;  ///< per boundary segment, its two vertices
  SegmentTree boundary_;
};

double length(const LatticeQuads& q, const Quad& c, int i) {
  return (q.points[static_cast<std::size_t>(c[static_cast<std::size_t>(i)])] -
          q.points[static_cast<std::size_t>(c[static_cast<std::size_t>((i + 1) % 4)])])
      .norm();
}

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

/// The quads with a corner whose scaled Jacobian (the quality module's) is <= 0, and
/// the smallest scaled Jacobian.
std::pair<std::size_t, double> inverted_quads(const LatticeQuads& quads) {
  const std::vector<double> jacobians = sound_scaled_jacobians(polygon_mesh(quads));
  const auto inverted =
      static_cast<std::size_t>(std::count_if(jacobians.begin(), jacobians.end(), [](double j) { return j <= 0; }));
  return {inverted, jacobians.empty() ? 1.0 : *std::min_element(jacobians.begin(), jacobians.end())};
}

}  // namespace

TriangleTree quad_triangle_tree(const LatticeQuads& quads) {
  TriangleTree index;
  for (std::size_t k = 0; k < quads.quads.size(); ++k) {
    const std::array<Vec3, 4> c = quad_corners(quads, k);
    index.add(c[0], c[1], c[2], static_cast<int>(k));
    index.add(c[0], c[2], c[3], static_cast<int>(k));
  }
  index.build();
  return index;
}

double quad_to_surface(const TriangleTree& surface, const std::array<Vec3, 4>& corners) {
  double d = 0;
  for (const Vec3& s : quad_deviation_samples(corners)) d = std::max(d, (surface.closest(s).first - s).norm());
  return d;
}

std::vector<double> quads_to_surface(const TriangleTree& surface, const LatticeQuads& quads) {
  return parallel_map<double>(quads.quads.size(),
                              [&](std::size_t k) { return quad_to_surface(surface, quad_corners(quads, k)); });
}

std::array<Vec3, 7> quad_deviation_samples(const std::array<Vec3, 4>& p) {
  return {(p[0] + p[1] + p[2] + p[3]) / 4, (p[0] + p[1] + p[2]) / 3, (p[0] + p[2] + p[3]) / 3, (p[0] + p[1]) / 2,
          (p[1] + p[2]) / 2, (p[2] + p[3]) / 2, (p[3] + p[0]) / 2};
}

std::vector<double> quad_deviation(const TriangleTree& surface, const std::vector<Vec3>& surface_samples,
                                   const LatticeQuads& q) {
  std::vector<double> out(q.quads.size(), 0.0);
  if (q.quads.empty()) return out;
  const TriangleTree quads = quad_triangle_tree(q);
  if (quads.empty()) return out;
  const std::vector<std::pair<Vec3, int>> nearest = quads.closest_to_each(surface_samples);
  for (std::size_t i = 0; i < surface_samples.size(); ++i) {
    const auto& [p, k] = nearest[i];
    double& d = out[static_cast<std::size_t>(k)];
    d = std::max(d, (p - surface_samples[i]).norm());
  }
  const std::vector<double> side = quads_to_surface(surface, q);
  for (std::size_t k = 0; k < q.quads.size(); ++k) out[k] = std::max(out[k], side[k]);
  return out;
}

/// S's vertices alone sample its side of the deviation where its mean edge is at
/// most this fraction of the tolerance (deviation_samples()).
constexpr double vertex_samples_edge_fraction = 0.5;

std::vector<Vec3> deviation_samples(const TriangleSoup& surface, double tolerance) {
  if (!surface.triangles.empty() && mean_edge_length(surface) <= vertex_samples_edge_fraction * tolerance) {
    std::vector<char> used(surface.points.size(), 0);
    std::vector<Vec3> vertices;
    for (const Triangle& t : surface.triangles)
      for (int v : t)
        if (!used[static_cast<std::size_t>(v)]) {
          used[static_cast<std::size_t>(v)] = 1;
          vertices.push_back(surface.points[static_cast<std::size_t>(v)]);
        }
    return vertices;
  }
  return surface_samples(surface.points, surface.triangles, {2});
}

std::vector<double> quad_deviation(const TriangleSoup& surface, const LatticeQuads& quads) {
  return quad_deviation(TriangleTree(surface.points, surface.triangles), surface_samples(surface.points, surface.triangles, {2}), quads);
}

namespace {

/// A quad whose shorter pair of opposite sides is longer than this fraction of
/// the other pair counts as near-square: both its chords are split.
constexpr double near_square_ratio = 0.7;
/// Each round of the refinement proper splits the chords through the quads above
/// this fraction of the largest deviation (and above the tolerance)...
constexpr double worst_fraction = 0.75;
/// ...and the rounds that spend the rest of the budget up to min_quads, above this one.
constexpr double budget_fraction = 0.8;
/// A failed round is retried one chord at a time this many times at most.
constexpr int single_chord_tries = 8;

/// One round: splits the chords through the quads whose deviation exceeds
/// `threshold`, worst first, as long as the quad count stays within `max_quads`,
/// taking no further quad once `max_chosen` chords are taken (a near-square quad
/// gives two) and leaving out the `forbidden` ones (quad, direction); places the
/// new points and updates `dev`.
/// Returns the number of chords split; `chosen_crossings` says which.
std::size_t split_round(const Placement& placement, const TriangleTree& index, const std::vector<Vec3>& samples,
                        LatticeQuads& quads, std::vector<int>& boundary_loop_of_point, std::vector<double>& dev,
                        double threshold, std::size_t max_quads,
                        const std::vector<std::pair<int, int>>& forbidden, std::size_t max_chosen,
                        std::vector<std::pair<int, int>>& chosen_crossings) {
  std::vector<int> worst;
  for (std::size_t k = 0; k < dev.size(); ++k)
    if (dev[k] > threshold) worst.push_back(static_cast<int>(k));
  if (worst.empty()) return 0;
  std::sort(worst.begin(), worst.end(), [&](int a, int b) { return dev[static_cast<std::size_t>(a)] > dev[static_cast<std::size_t>(b)]; });
  const QuadChords chords = quad_chords(quads.quads);
  std::vector<char> split(chords.length.size(), 0), left_out(chords.length.size(), 0);
  for (const auto& [quad, direction] : forbidden)
    left_out[static_cast<std::size_t>(chords.chord_of[static_cast<std::size_t>(quad)][static_cast<std::size_t>(direction)])] = 1;
  std::size_t planned = 0, chosen = 0;
  chosen_crossings.clear();
  const std::size_t budget = max_quads > quads.quads.size() ? max_quads - quads.quads.size() : 0;
  for (int k : worst) {
    if (chosen >= max_chosen) break;
    const Quad& c = quads.quads[static_cast<std::size_t>(k)];
    // cut the long edges: direction 0 cuts edges 0 and 2
    const double l0 = length(quads, c, 0) + length(quads, c, 2);
    const double l1 = length(quads, c, 1) + length(quads, c, 3);
    // a near-square quad: the shorter chord first (both halve the quad)
    const auto& of = chords.chord_of[static_cast<std::size_t>(k)];
    int first = l0 >= l1 ? 0 : 1;
    const bool square = std::min(l0, l1) > near_square_ratio * std::max(l0, l1);
    if (square && chords.length[static_cast<std::size_t>(of[1 - first])] < chords.length[static_cast<std::size_t>(of[first])])
      first = 1 - first;
    std::vector<int> directions{first};
    if (square) directions.push_back(1 - first);
    for (int d : directions) {
      const int chord = of[static_cast<std::size_t>(d)];
      const std::size_t cost = static_cast<std::size_t>(chords.length[static_cast<std::size_t>(chord)]);
      if (split[static_cast<std::size_t>(chord)] || left_out[static_cast<std::size_t>(chord)] || planned + cost > budget)
        continue;
      split[static_cast<std::size_t>(chord)] = 1;
      chosen_crossings.push_back({k, d});
      planned += cost;
      ++chosen;
    }
  }
  if (chosen == 0) return 0;
  const int n = static_cast<int>(quads.points.size());
  const std::vector<Quad> before = quads.quads;
  SplitQuads out = split_chords(before, n, chords, split);
  for (const SplitPoint& sp : out.new_points) {
    if (sp.quad >= 0) {
      Vec3 centre = Vec3::Zero();
      for (int v : before[static_cast<std::size_t>(sp.quad)]) centre += quads.points[static_cast<std::size_t>(v)];
      const auto [p, loc] = placement.on_surface(centre / 4);
      quads.points.push_back(p);
      quads.locations.push_back(loc);
      boundary_loop_of_point.push_back(-1);
      continue;
    }
    const Vec3 middle = (quads.points[static_cast<std::size_t>(sp.a)] + quads.points[static_cast<std::size_t>(sp.b)]) / 2;
    // an edge on the quads' boundary lies on S's boundary unless it borders a dropped cell
    const int loop = boundary_loop_of_point[static_cast<std::size_t>(sp.a)];
    const bool on_boundary = sp.boundary && loop >= 0 && boundary_loop_of_point[static_cast<std::size_t>(sp.b)] >= 0;
    const auto [p, loc] = on_boundary ? placement.on_boundary(middle) : placement.on_surface(middle);
    quads.points.push_back(p);
    quads.locations.push_back(loc);
    boundary_loop_of_point.push_back(on_boundary ? loop : -1);
  }
  quads.quads = std::move(out.quads);
  dev = quad_deviation(index, samples, quads);
  return chosen;
}

}  // namespace

DeviationRefinementReport refine_to_deviation(const TriangleSoup& surface,
                                              const SurfaceAdjacency& adjacency, LatticeQuads& quads,
                                              std::vector<int>& boundary_loop_of_point,
                                              const DeviationRefinementOptions& options) {
  QM_ASSERT(options.tolerance > 0);
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  DeviationRefinementReport report;
  const TriangleTree index(surface.points, surface.triangles);
  const std::vector<Vec3> samples = deviation_samples(surface, options.tolerance);
  const Placement placement(surface, adjacency, index);
  std::vector<double> dev = quad_deviation(index, samples, quads);
  report.deviation_before = max_of(dev);
  const std::size_t start = quads.quads.size();
  // a new point is placed on S by closest point; on a thin or sharply curved part
  // that point can fall where the split quads turn over or get thin: a round that
  // turns a quad over, or takes the smallest scaled Jacobian below both its value
  // before the refinement and the usual 0.3 floor, is undone
  // (named variables, not a structured binding: a lambda below updates `inverted`)
  const auto at_start = inverted_quads(quads);
  auto inverted = at_start.first;
  const double jacobian_floor = std::min(at_start.second, options.min_scaled_jacobian);
  // chords whose split was undone, as (quad, direction) of the current quads: a
  // round that fails is tried again with the chords of one quad at a time (the
  // worst), and chords that fail alone are left out until a split succeeds (the
  // quads are numbered anew then); at most single_chord_tries such tries per round
  std::vector<std::pair<int, int>> forbidden, crossings;
  auto attempt = [&](double threshold, std::size_t max_quads, std::size_t max_chosen) {
    const LatticeQuads before = quads;
    const std::vector<int> loops_before = boundary_loop_of_point;
    const std::vector<double> dev_before = dev;
    const std::size_t chosen = split_round(placement, index, samples, quads, boundary_loop_of_point, dev, threshold,
                                           max_quads, forbidden, max_chosen, crossings);
    if (chosen == 0) return 0;
    const auto [now, jacobian] = inverted_quads(quads);
    if (now > inverted || jacobian < jacobian_floor) {
      quads = before;
      boundary_loop_of_point = loops_before;
      dev = dev_before;
      ++report.rounds_undone;
      return -1;
    }
    inverted = now;
    report.chords_split += chosen;
    ++report.rounds;
    forbidden.clear();
    return 1;
  };
  auto round = [&](double threshold, std::size_t max_quads) {
    const int result = attempt(threshold, max_quads, std::numeric_limits<std::size_t>::max());
    if (result >= 0) return result > 0;
    for (int single = 0; single < single_chord_tries; ++single) {
      const int one = attempt(threshold, max_quads, 1);
      if (one > 0) return true;
      if (one == 0) return false;
      forbidden.insert(forbidden.end(), crossings.begin(), crossings.end());
    }
    return false;
  };
  // the worst quads first: the largest deviation is what the budget must bring down
  for (int r = 0; r < options.max_rounds; ++r)
    if (!round(std::max(options.tolerance, worst_fraction * max_of(dev)), options.max_quads)) break;
  report.tolerance_met = max_of(dev) <= options.tolerance;
  // the rest of the budget, up to min_quads: the largest deviations
  while (quads.quads.size() < options.min_quads)
    if (!round(budget_fraction * max_of(dev), options.min_quads)) break;
  report.deviation_after = max_of(dev);
  report.quads_added = quads.quads.size() - start;
  return report;
}

}  // namespace qm
