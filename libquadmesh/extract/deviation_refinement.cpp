#include "libquadmesh/extract/deviation_refinement.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"
#include "libquadmesh/extract/internal/chord_split_round.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "libquadmesh/quality/quad_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace qm {

namespace {

double max_of(const std::vector<double>& v) { return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end()); }

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

/// Each round of the refinement proper splits the chords through the quads above
/// this fraction of the largest deviation (and above the tolerance)...
constexpr double worst_fraction = 0.75;
/// ...and the rounds that spend the rest of the budget up to min_quads, above this one.
constexpr double budget_fraction = 0.8;
/// A failed round is retried one chord at a time this many times at most.
constexpr int single_chord_tries = 8;

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
  const ChordPointPlacement placement(surface, adjacency, index);
  const QuadMeasure measure = [&](const LatticeQuads& q) { return quad_deviation(index, samples, q); };
  std::vector<double> dev = quad_deviation(index, samples, quads);
  report.deviation_before = max_of(dev);
  const std::size_t start = quads.quads.size();
  // a round that turns a quad over, or takes the smallest scaled Jacobian below
  // both its value before the refinement and the usual 0.3 floor, is undone
  // (split_chord_round_or_undo; named variables, not a structured binding: a
  // lambda below updates `inverted`)
  const auto at_start = inverted_quad_count(quads);
  std::size_t inverted = at_start.first;
  const double jacobian_floor = std::min(at_start.second, options.min_scaled_jacobian);
  // chords whose split was undone, as (quad, direction) of the current quads: a
  // round that fails is tried again with the chords of one quad at a time (the
  // worst), and chords that fail alone are left out until a split succeeds (the
  // quads are numbered anew then); at most single_chord_tries such tries per round
  std::vector<std::pair<int, int>> forbidden, crossings;
  auto attempt = [&](double threshold, std::size_t max_quads, std::size_t max_chosen) {
    const std::optional<std::size_t> chosen =
        split_chord_round_or_undo(placement, measure, quads, boundary_loop_of_point, dev, threshold, max_quads,
                                  forbidden, max_chosen, crossings, inverted, jacobian_floor);
    if (!chosen) {
      ++report.rounds_undone;
      return -1;
    }
    if (*chosen == 0) return 0;
    report.chords_split += *chosen;
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
