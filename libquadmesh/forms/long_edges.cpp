#include "libquadmesh/forms/long_edges.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/topology/internal/edge_incidence.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
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

/// Two triangles are one plane when their normals are this close (radians): a
/// triangle's halves after a split, or a CAD part's flat face in an STL file.
constexpr double coplanar_normals = 1e-6;
/// An edge is flipped only where one of its two triangles has an angle below this
/// (radians): the needles the bisection fans out of a sliver. (15 degrees flipped
/// the halves of a flat mesh's fair triangles too, and changed its quads, the Abel
/// ones for the worse.)
constexpr double needle_angle = 10.0 * M_PI / 180.0;
/// Flip passes after each split pass, at most.
constexpr int max_flip_passes = 32;

Vec3 normal(const TriangleSoup& soup, const Triangle& t) {
  const Vec3& a = soup.points[static_cast<std::size_t>(t[0])];
  return (soup.points[static_cast<std::size_t>(t[1])] - a).cross(soup.points[static_cast<std::size_t>(t[2])] - a);
}

double smallest_angle(const TriangleSoup& soup, std::size_t f) {
  return std::min({corner_angle(soup, f, 0), corner_angle(soup, f, 1), corner_angle(soup, f, 2)});
}

/// Per triangle of the input: it lies in a flat face, a plane it shares with a
/// neighbour (coplanar_normals), as a CAD part's STL has its faces, fans of long
/// thin triangles. A scan's triangles share no plane.
std::vector<char> flat_face_triangles(const TriangleSoup& soup) {
  const EdgeIncidence inc = edge_incidence(soup);
  std::vector<char> flat(soup.triangles.size(), 0);
  for (std::size_t e = 0; e < inc.edge_count(); ++e) {
    if (inc.valence(static_cast<int>(e)) != 2) continue;
    const auto f1 = static_cast<std::size_t>(inc.halfedges[static_cast<std::size_t>(inc.offsets[e])] / 3);
    const auto f2 = static_cast<std::size_t>(inc.halfedges[static_cast<std::size_t>(inc.offsets[e]) + 1] / 3);
    const Vec3 n1 = normal(soup, soup.triangles[f1]), n2 = normal(soup, soup.triangles[f2]);
    // (a triangle of no area has no plane: its zero normal is at angle 0 to any)
    if (n1.squaredNorm() > 0 && n2.squaredNorm() > 0 && angle_between(n1, n2) < coplanar_normals)
      flat[f1] = flat[f2] = 1;
  }
  return flat;
}

/// One pass of Delaunay flips among needles in the input's flat faces: an edge whose
/// two triangles come from triangles of flat faces (`flat`, per input triangle;
/// `ancestor`, per triangle, the input triangle it comes from), lie in one plane,
/// are not on a CAD curve, one of them a needle (needle_angle), and whose opposite
/// angles add up to more than pi, is replaced by the other diagonal of their quad
/// (convex, since it is not Delaunay). The surface is the same; each triangle flips
/// at most once per pass. Returns the flips made.
std::size_t flip_flat_needles(TriangleSoup& soup, const std::vector<char>& flat,
                              const std::vector<std::int64_t>& ancestor) {
  const EdgeIncidence inc = edge_incidence(soup);
  const CurveEdgeIndex curves = curve_edge_index(soup);
  std::set<std::pair<int, int>> edges;
  for (const auto& [a, b] : inc.edges) edges.insert({a, b});
  std::vector<char> touched(soup.triangles.size(), 0);
  std::size_t flips = 0;
  for (std::size_t e = 0; e < inc.edge_count(); ++e) {
    if (inc.valence(static_cast<int>(e)) != 2) continue;
    const auto [a0, b0] = inc.edges[e];
    if (curves.count({a0, b0})) continue;
    const int h1 = inc.halfedges[static_cast<std::size_t>(inc.offsets[e])];
    const int h2 = inc.halfedges[static_cast<std::size_t>(inc.offsets[e]) + 1];
    const auto f1 = static_cast<std::size_t>(h1 / 3), f2 = static_cast<std::size_t>(h2 / 3);
    if (touched[f1] || touched[f2] || !flat[static_cast<std::size_t>(ancestor[f1])] ||
        !flat[static_cast<std::size_t>(ancestor[f2])])
      continue;
    const Triangle t1 = soup.triangles[f1], t2 = soup.triangles[f2];
    const int k1 = h1 % 3, k2 = h2 % 3;
    const int a = t1[k1], b = t1[(k1 + 1) % 3], c = t1[(k1 + 2) % 3], d = t2[(k2 + 2) % 3];
    if (t2[k2] != b || t2[(k2 + 1) % 3] != a || c == d) continue;  // not oppositely oriented: left alone
    const Vec3 n1 = normal(soup, t1), n2 = normal(soup, t2);
    if (!(angle_between(n1, n2) < coplanar_normals)) continue;
    if (std::min(smallest_angle(soup, f1), smallest_angle(soup, f2)) >= needle_angle) continue;
    if (corner_angle(soup, f1, (k1 + 2) % 3) + corner_angle(soup, f2, (k2 + 2) % 3) <= M_PI + 1e-12) continue;
    if (edges.count({std::min(c, d), std::max(c, d)})) continue;
    const Triangle n1t{a, d, c}, n2t{d, b, c};
    if (!(normal(soup, n1t).dot(n1) > 0) || !(normal(soup, n2t).dot(n1) > 0)) continue;
    soup.triangles[f1] = n1t;
    soup.triangles[f2] = n2t;
    edges.erase({a0, b0});
    edges.insert({std::min(c, d), std::max(c, d)});
    touched[f1] = touched[f2] = 1;
    ++flips;
  }
  return flips;
}

}  // namespace

std::size_t split_long_edges(TriangleSoup& soup, double max_length) {
  QM_ASSERT(max_length > 0);
  if (!soup.point_labels.empty()) soup.point_labels.resize(soup.points.size(), -1);
  // where the input has flat faces, each triangle is labelled with its input
  // triangle while it is split (a split triangle's halves take its label), and
  // the file's labels are put back at the end
  const std::vector<char> flat = flat_face_triangles(soup);
  const bool flips = std::find(flat.begin(), flat.end(), 1) != flat.end();
  std::vector<std::int64_t> file_labels;
  if (flips) {
    file_labels = soup.triangle_labels;
    soup.triangle_labels.resize(soup.triangles.size());
    for (std::size_t f = 0; f < soup.triangles.size(); ++f) soup.triangle_labels[f] = static_cast<std::int64_t>(f);
  }
  const auto restore_labels = [&] {
    if (!flips) return;
    if (file_labels.empty()) {
      soup.triangle_labels.clear();
      return;
    }
    for (std::int64_t& label : soup.triangle_labels) label = file_labels[static_cast<std::size_t>(label)];
  };
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
    if (wanted.empty()) {
      restore_labels();
      return splits;
    }
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
    // the bisection fans a sliver (a CAD part's STL, its faces long thin triangles)
    // out into needles along its long sides, each as thin as the sliver: in a
    // flat face, flipped to the Delaunay diagonal, their next splits fall inside
    // the face, and the triangles stay about as many as its area needs (the hinge
    // with two holes: 107,422 -> 47,436)
    for (int p = 0; flips && p < max_flip_passes && flip_flat_needles(soup, flat, soup.triangle_labels) > 0; ++p) {
    }
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
