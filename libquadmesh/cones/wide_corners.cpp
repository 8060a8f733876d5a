#include "libquadmesh/cones/wide_corners.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/internal/edge_incidence.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace qm {

namespace {

constexpr int max_passes = 8;
/// A boundary vertex whose turn (radians) is more than this times its inner
/// edges' weight would make u jump by more than about 1 (the scale by e) at it.
constexpr double max_turn_per_weight = 1.0;
/// Turns below this (radians) are the rounding of a CAD corner's angle.
constexpr double min_turn = 1e-6;

/// The indices of every triangle of `soup`, in order.
std::vector<std::size_t> every_triangle(const TriangleSoup& soup) {
  std::vector<std::size_t> out(soup.triangles.size());
  std::iota(out.begin(), out.end(), std::size_t{0});
  return out;
}

/// Per point, the sum of the angles of its corners in `triangles` (in order): its
/// whole angle sum at a point all of whose triangles are there.
std::vector<double> angle_sums(const TriangleSoup& soup, const std::vector<std::size_t>& triangles) {
  std::vector<double> total(soup.points.size(), 0.0);
  for (std::size_t f : triangles)
    for (int k = 0; k < 3; ++k)
      total[static_cast<std::size_t>(soup.triangles[f][static_cast<std::size_t>(k)])] += corner_angle(soup, f, k);
  return total;
}

/// Corner k of triangle f as the cone metric opens it: its angle times n pi/2
/// over its point's angle sum (`total`), n = quads at the point.
double opened_corner(const TriangleSoup& soup, std::size_t f, int k, const std::vector<double>& total,
                     const std::vector<int>& quads) {
  double angle = corner_angle(soup, f, k);
  const auto v = static_cast<std::size_t>(soup.triangles[f][static_cast<std::size_t>(k)]);
  if (total[v] > 0) angle *= quads[v] * quarter_turn / total[v];
  return angle;
}

}  // namespace

std::vector<double> opened_corners(const TriangleSoup& soup, const std::vector<int>& quads) {
  const std::vector<double> total = angle_sums(soup, every_triangle(soup));
  std::vector<double> angle(3 * soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) angle[3 * f + static_cast<std::size_t>(k)] = opened_corner(soup, f, k, total, quads);
  return angle;
}

namespace {

/// The splits of split_wide_corners and split_turned_boundary: pass after pass,
/// the edge opposite each corner (3 f + k) that `choose(soup, adjacency, quads)`
/// names, the first named first, a triangle once per pass.
template <typename Choose>
WideCornerSplits split_chosen_corners(TriangleSoup& soup, const std::vector<Cone>& cones, const Choose& choose) {
  if (!soup.point_labels.empty()) soup.point_labels.resize(soup.points.size(), -1);
  WideCornerSplits out;
  SurfaceAdjacency& adjacency = out.adjacency;
  bool current = false;  // adjacency describes the soup as it is
  for (int pass = 0; pass < max_passes; ++pass) {
    adjacency = surface_adjacency(soup);
    current = true;
    const std::vector<int> quads = quads_per_vertex(adjacency, cones);
    const std::vector<int> wide = choose(soup, adjacency, quads);
    if (wide.empty()) break;
    const EdgeIncidence inc = edge_incidence(soup);
    CurveEdgeIndex curves = curve_edge_index(soup);
    std::vector<char> touched(soup.triangles.size(), 0);
    std::size_t pass_splits = 0;
    for (int corner : wide) {
      const int f = corner / 3, k = corner % 3;
      const int h = 3 * f + (k + 1) % 3;  // the side opposite corner k
      const int e = inc.halfedge_edge[static_cast<std::size_t>(h)];
      if (e < 0) continue;
      const auto [a, b] = inc.edges[static_cast<std::size_t>(e)];
      // where the corner's bisector meets the side: it divides the side as the
      // corner's other two sides (the midpoint would leave a sliver where the
      // triangle is skewed)
      const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
      const Vec3& apex = soup.points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
      const double to_a = (soup.points[static_cast<std::size_t>(a)] - apex).norm();
      const double to_b = (soup.points[static_cast<std::size_t>(b)] - apex).norm();
      if (split_edge_at(soup, inc, e, to_a / (to_a + to_b), touched, curves) < 0) continue;  // next pass
      ++pass_splits;
    }
    if (pass_splits == 0) break;
    out.splits += pass_splits;
    current = false;
  }
  if (!current) adjacency = surface_adjacency(soup);
  return out;
}

/// The corners of `triangles` opened wider than `max_opened` (opened_corner, with
/// `total` the points' angle sums, whole at the points `takes(v)` selects) at
/// those points, the widest first.
template <typename Takes>
std::vector<int> wide_corners_among(const TriangleSoup& soup, const std::vector<std::size_t>& triangles,
                                    const std::vector<double>& total, const std::vector<int>& quads,
                                    double max_opened, const Takes& takes) {
  std::vector<std::pair<double, int>> wide;
  for (std::size_t f : triangles)
    for (int k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(soup.triangles[f][static_cast<std::size_t>(k)]);
      if (!takes(v)) continue;
      const double opened = opened_corner(soup, f, k, total, quads);
      if (opened > max_opened) wide.push_back({opened, static_cast<int>(3 * f) + k});
    }
  std::sort(wide.begin(), wide.end(), std::greater<>());
  std::vector<int> out;
  for (const auto& w : wide) out.push_back(w.second);
  return out;
}

/// The triangles with a corner at a boundary vertex, in order: all that the
/// boundary vertices' angle sums, inner edge weights and corners read.
std::vector<std::size_t> boundary_triangles(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  std::vector<std::size_t> out;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (std::any_of(soup.triangles[f].begin(), soup.triangles[f].end(),
                    [&](int v) { return adjacency.boundary_vertex[static_cast<std::size_t>(v)] != 0; }))
      out.push_back(f);
  return out;
}

/// Per point, the cotangent weights of its inner edges in `triangles` summed:
/// what turns the cone metric's field there (cone_metric.h; 0 at a corner in one
/// triangle); whole at a vertex all of whose triangles are there.
std::vector<double> inner_edge_weight(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                      const std::vector<std::size_t>& triangles) {
  std::vector<double> weight(soup.points.size(), 0.0);
  for (std::size_t f : triangles) {
    const Triangle& t = soup.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int i = t[static_cast<std::size_t>((k + 1) % 3)], j = t[static_cast<std::size_t>((k + 2) % 3)];
      if (adjacency.find(j, i).face < 0) continue;  // a boundary edge
      const double w = 0.5 / std::tan(corner_angle(soup, f, k));
      weight[static_cast<std::size_t>(i)] += w;
      weight[static_cast<std::size_t>(j)] += w;
    }
  }
  return weight;
}

}  // namespace

WideCornerSplits split_wide_corners(TriangleSoup& soup, const std::vector<Cone>& cones, double max_opened) {
  QM_ASSERT(max_opened > 0);
  // at cones (a regular vertex keeps about its own angles)
  return split_chosen_corners(soup, cones, [&](const TriangleSoup& s, const SurfaceAdjacency& adjacency,
                                               const std::vector<int>& quads) {
    const std::vector<std::size_t> triangles = every_triangle(s);
    return wide_corners_among(s, triangles, angle_sums(s, triangles), quads, max_opened,
                              [&](std::size_t v) { return quads[v] != (adjacency.boundary_vertex[v] ? 2 : 4); });
  });
}

WideCornerSplits split_turned_boundary(TriangleSoup& soup, const std::vector<Cone>& cones) {
  return split_chosen_corners(soup, cones, [](const TriangleSoup& s, const SurfaceAdjacency& adjacency,
                                              const std::vector<int>& quads) {
    // only the boundary vertices are read: their triangles' angles, not the
    // whole surface's (a scan of 70,000 triangles: 8 passes of those)
    const std::vector<std::size_t> triangles = boundary_triangles(s, adjacency);
    const std::vector<double> total = angle_sums(s, triangles);
    const std::vector<double> weight = inner_edge_weight(s, adjacency, triangles);
    // the boundary vertices the metric must turn by more than their inner edges
    // take at max_turn_per_weight
    std::vector<char> turned(s.points.size(), 0);
    for (std::size_t v = 0; v < s.points.size(); ++v)
      turned[v] = adjacency.boundary_vertex[v] &&
                  std::abs(quads[v] * quarter_turn - total[v]) > max_turn_per_weight * std::max(weight[v], 0.0) &&
                  std::abs(quads[v] * quarter_turn - total[v]) > min_turn;
    const auto vertex_of = [&](int c) {
      return static_cast<std::size_t>(s.triangles[static_cast<std::size_t>(c / 3)][static_cast<std::size_t>(c % 3)]);
    };
    std::vector<int> out = wide_corners_among(s, triangles, total, quads, max_turned_corner,
                                              [&](std::size_t v) { return turned[v] != 0; });
    // and the widest corner of one whose corners are none that wide
    std::vector<char> has(s.points.size(), 0);
    for (int c : out) has[vertex_of(c)] = 1;
    std::vector<int> widest(s.points.size(), -1);
    std::vector<double> widest_angle(s.points.size(), 0.0);
    for (std::size_t f : triangles)
      for (int k = 0; k < 3; ++k) {
        const int c = static_cast<int>(3 * f) + k;
        const std::size_t v = vertex_of(c);
        const double angle = corner_angle(s, f, k);
        if (turned[v] && !has[v] && angle > widest_angle[v]) widest[v] = c, widest_angle[v] = angle;
      }
    for (int c : widest)
      if (c >= 0) out.push_back(c);
    return out;
  });
}

}  // namespace qm
