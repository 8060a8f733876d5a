#include "libquadmesh/extract/internal/chord_split_round.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/quad_chords.h"
#include "libquadmesh/quality/quad_quality.h"

#include <algorithm>
#include <cmath>

namespace qm {

ChordPointPlacement::ChordPointPlacement(const TriangleSoup& s, const SurfaceAdjacency& adjacency,
                                         const TriangleTree& surface)
    : s_(s), adjacency_(adjacency), surface_(surface) {
  for (const auto& loop : adjacency.boundary_loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      boundary_.add(point(a), point(b), static_cast<int>(ends_.size()));
      ends_.push_back({a, b});
    }
  if (!ends_.empty()) boundary_.build();
}

std::pair<Vec3, SurfaceLocation> ChordPointPlacement::on_surface(const Vec3& guess) const {
  return closest_location(s_, surface_, guess);
}

std::pair<Vec3, SurfaceLocation> ChordPointPlacement::on_boundary(const Vec3& guess) const {
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

namespace {

/// A quad whose shorter pair of opposite sides is longer than this fraction of
/// the other pair counts as near-square: both its chords are split.
constexpr double near_square_ratio = 0.7;

double length(const LatticeQuads& q, const Quad& c, int i) {
  return (q.points[static_cast<std::size_t>(c[static_cast<std::size_t>(i)])] -
          q.points[static_cast<std::size_t>(c[static_cast<std::size_t>((i + 1) % 4)])])
      .norm();
}

/// Splits the chords with split[c] != 0 (quad_chords.h split_chords) and places
/// the new points (edge midpoints, quad centres) on S, on its boundary for an edge
/// on the quads' boundary whose ends are on it; extends `boundary_loop_of_point`.
void split_and_place(const ChordPointPlacement& placement, LatticeQuads& quads, std::vector<int>& boundary_loop_of_point,
                     const QuadChords& chords, const std::vector<char>& split) {
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
}

}  // namespace

std::size_t split_chord_round(const ChordPointPlacement& placement, const QuadMeasure& measure, LatticeQuads& quads,
                              std::vector<int>& boundary_loop_of_point, std::vector<double>& values,
                              double threshold, std::size_t max_quads,
                              const std::vector<std::pair<int, int>>& forbidden, std::size_t max_chosen,
                              std::vector<std::pair<int, int>>& chosen_crossings) {
  std::vector<int> worst;
  for (std::size_t k = 0; k < values.size(); ++k)
    if (values[k] > threshold) worst.push_back(static_cast<int>(k));
  if (worst.empty()) return 0;
  std::sort(worst.begin(), worst.end(), [&](int a, int b) { return values[static_cast<std::size_t>(a)] > values[static_cast<std::size_t>(b)]; });
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
  split_and_place(placement, quads, boundary_loop_of_point, chords, split);
  values = measure(quads);
  return chosen;
}

std::optional<std::size_t> split_chord_round_or_undo(const ChordPointPlacement& placement, const QuadMeasure& measure,
                                                     LatticeQuads& quads, std::vector<int>& boundary_loop_of_point,
                                                     std::vector<double>& values, double threshold,
                                                     std::size_t max_quads,
                                                     const std::vector<std::pair<int, int>>& forbidden,
                                                     std::size_t max_chosen,
                                                     std::vector<std::pair<int, int>>& chosen_crossings,
                                                     std::size_t& inverted, double jacobian_floor) {
  const LatticeQuads before = quads;
  const std::vector<int> loops_before = boundary_loop_of_point;
  const std::vector<double> values_before = values;
  const std::size_t chosen = split_chord_round(placement, measure, quads, boundary_loop_of_point, values, threshold,
                                               max_quads, forbidden, max_chosen, chosen_crossings);
  if (chosen == 0) return 0;
  const auto [now, jacobian] = inverted_quad_count(quads);
  if (now > inverted || jacobian < jacobian_floor) {
    quads = before;
    boundary_loop_of_point = loops_before;
    values = values_before;
    return std::nullopt;
  }
  inverted = now;
  return chosen;
}

std::pair<std::size_t, double> inverted_quad_count(const LatticeQuads& quads) {
  const std::vector<double> jacobians = sound_scaled_jacobians(polygon_mesh(quads));
  const auto inverted =
      static_cast<std::size_t>(std::count_if(jacobians.begin(), jacobians.end(), [](double j) { return j <= 0; }));
  return {inverted, jacobians.empty() ? 1.0 : *std::min_element(jacobians.begin(), jacobians.end())};
}

}  // namespace qm
