#include "libquadmesh/cones/wide_corners.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/internal/edge_incidence.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <utility>

namespace qm {

namespace {
constexpr int max_passes = 8;
}  // namespace

std::vector<double> opened_corners(const TriangleSoup& soup, const std::vector<int>& quads) {
  std::vector<double> angle(3 * soup.triangles.size());
  std::vector<double> total(soup.points.size(), 0.0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      angle[3 * f + static_cast<std::size_t>(k)] = corner_angle(soup, f, k);
      total[static_cast<std::size_t>(soup.triangles[f][static_cast<std::size_t>(k)])] +=
          angle[3 * f + static_cast<std::size_t>(k)];
    }
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const auto v = static_cast<std::size_t>(soup.triangles[f][k]);
      if (total[v] > 0) angle[3 * f + k] *= quads[v] * quarter_turn / total[v];
    }
  return angle;
}

WideCornerSplits split_wide_corners(TriangleSoup& soup, const std::vector<Cone>& cones, double max_opened) {
  QM_ASSERT(max_opened > 0);
  if (!soup.point_labels.empty()) soup.point_labels.resize(soup.points.size(), -1);
  WideCornerSplits out;
  SurfaceAdjacency& adjacency = out.adjacency;
  bool current = false;  // adjacency describes the soup as it is
  for (int pass = 0; pass < max_passes; ++pass) {
    adjacency = surface_adjacency(soup);
    current = true;
    const std::vector<int> quads = quads_per_vertex(adjacency, cones);
    const std::vector<double> opened = opened_corners(soup, quads);
    // the widest corners at cones first (a regular vertex keeps about its angles);
    // a triangle takes one split per pass
    std::vector<std::pair<double, int>> wide;
    for (std::size_t c = 0; c < opened.size(); ++c) {
      const auto v = static_cast<std::size_t>(soup.triangles[c / 3][c % 3]);
      const bool cone = quads[v] != (adjacency.boundary_vertex[v] ? 2 : 4);
      if (cone && opened[c] > max_opened) wide.push_back({opened[c], static_cast<int>(c)});
    }
    if (wide.empty()) break;
    std::sort(wide.begin(), wide.end(), std::greater<>());
    const EdgeIncidence inc = edge_incidence(soup);
    CurveEdgeIndex curves = curve_edge_index(soup);
    std::vector<char> touched(soup.triangles.size(), 0);
    std::size_t pass_splits = 0;
    for (const auto& [angle, corner] : wide) {
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

}  // namespace qm
