#include "libquadmesh/forms/long_edges.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/internal/edge_incidence.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <utility>

namespace qm {

namespace {

double length(const TriangleSoup& soup, int a, int b) {
  return (soup.points[static_cast<std::size_t>(a)] - soup.points[static_cast<std::size_t>(b)]).norm();
}

/// The side k (from corner k to k + 1) of triangle t that is longest.
int longest_side(const TriangleSoup& soup, const Triangle& t) {
  int best = 0;
  for (int k = 1; k < 3; ++k)
    if (length(soup, t[k], t[(k + 1) % 3]) > length(soup, t[best], t[(best + 1) % 3])) best = k;
  return best;
}

}  // namespace

std::size_t split_long_edges(TriangleSoup& soup, double max_length) {
  QM_ASSERT(max_length > 0);
  if (!soup.point_labels.empty()) soup.point_labels.resize(soup.points.size(), -1);
  std::size_t splits = 0;
  for (;;) {
    const EdgeIncidence inc = edge_incidence(soup);
    // the longest side of each triangle that is too long, longest first
    std::vector<std::pair<double, int>> wanted;
    for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
      const int k = longest_side(soup, soup.triangles[f]);
      const int h = static_cast<int>(3 * f) + k;
      const double l = length(soup, halfedge_source(soup, h), halfedge_target(soup, h));
      if (l > max_length) wanted.push_back({l, inc.halfedge_edge[static_cast<std::size_t>(h)]});
    }
    if (wanted.empty()) return splits;
    std::sort(wanted.begin(), wanted.end(), std::greater<>());
    CurveEdgeIndex curves = curve_edge_index(soup);
    std::vector<char> touched(soup.triangles.size(), 0);
    std::size_t pass = 0;
    for (const auto& [l, e] : wanted) {
      if (e < 0) continue;
      if (split_edge_at_midpoint(soup, inc, e, touched, curves) < 0) continue;  // next pass
      ++pass;
    }
    splits += pass;
  }
}

double long_edge_area_fraction(const TriangleSoup& soup, double max_length) {
  double total = 0, long_area = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3& a = soup.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = soup.points[static_cast<std::size_t>(t[1])];
    const Vec3& c = soup.points[static_cast<std::size_t>(t[2])];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    total += area;
    if (std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()}) > max_length) long_area += area;
  }
  return total > 0 ? long_area / total : 0.0;
}

}  // namespace qm
