// Longest-edge bisection of triangles wider than the quads (forms/long_edges.h).
#include "libquadmesh/forms/long_edges.h"
#include "libquadmesh/quality/triangle_quality.h"
#include "libquadmesh/topology/internal/edge_incidence.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace qm;

namespace {

/// The length of the soup's boundary edges, checking that every edge has one or two
/// triangles (conforming).
double conforming_boundary_length(const TriangleSoup& soup) {
  const EdgeIncidence inc = edge_incidence(soup);
  double boundary = 0;
  for (std::size_t e = 0; e < inc.edge_count(); ++e) {
    CHECK(inc.valence(static_cast<int>(e)) <= 2);
    if (inc.is_boundary(static_cast<int>(e)))
      boundary += (soup.points[inc.edges[e][0]] - soup.points[inc.edges[e][1]]).norm();
  }
  return boundary;
}

/// split_long_edges(soup, limit), checking that every input point is kept where it
/// was and the new points are as many as the splits.
std::size_t split_keeping_points(TriangleSoup& soup, double limit) {
  const TriangleSoup before = soup;
  const std::size_t splits = split_long_edges(soup, limit);
  CHECK(soup.points.size() == before.points.size() + splits);
  for (std::size_t v = 0; v < before.points.size(); ++v) CHECK(soup.points[v] == before.points[v]);
  return splits;
}

}  // namespace

TEST_CASE("long edges: split until none is longer than the limit, every input vertex kept") {
  TriangleSoup soup = test::grid(2);  // edges 0.5, diagonals 0.71
  for (int j = 0; j < 2; ++j) soup.cad.edges.push_back({j, j + 1, 7});  // the side x = 0 is CAD curve 7
  const double limit = 0.2;
  CHECK(split_keeping_points(soup, limit) > 0);

  double area = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3 n = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
    CHECK(n.z() > 0);  // orientation kept
    area += 0.5 * n.z();
    for (int k = 0; k < 3; ++k) CHECK((soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm() <= limit + 1e-12);
  }
  CHECK(area == doctest::Approx(1.0));
  // conforming, boundary edges only on the square's sides
  CHECK(conforming_boundary_length(soup) == doctest::Approx(4.0));
  // the CAD curve is split with its edges: still the whole side x = 0, in short pieces
  double curve = 0;
  for (const CurveEdge& e : soup.cad.edges) {
    CHECK(e.curve == 7);
    CHECK(soup.points[e.a].x() == 0.0);
    CHECK(soup.points[e.b].x() == 0.0);
    CHECK((soup.points[e.a] - soup.points[e.b]).norm() <= limit + 1e-12);
    curve += (soup.points[e.a] - soup.points[e.b]).norm();
  }
  CHECK(curve == doctest::Approx(1.0));
  // a second call has nothing left to do
  CHECK(split_long_edges(soup, limit) == 0);
}

TEST_CASE("long edges: a mesh already finer than the limit is left as it is") {
  TriangleSoup soup = test::grid(8);
  const TriangleSoup before = soup;
  CHECK(split_long_edges(soup, 0.2) == 0);
  CHECK(soup.triangles == before.triangles);
}

TEST_CASE("long edges: the fraction of the area they cover") {
  const TriangleSoup soup = test::grid(2);  // 8 triangles of area 1/8, sides 0.5 and 0.71
  CHECK(long_edge_area_fraction(soup, 0.6) == doctest::Approx(1.0));
  CHECK(long_edge_area_fraction(soup, 0.8) == 0.0);
  TriangleSoup mixed = soup;
  split_long_edges(mixed, 0.6);  // every triangle now has sides <= 0.5
  CHECK(long_edge_area_fraction(mixed, 0.6) == 0.0);
  CHECK(long_edge_area_fraction(TriangleSoup{}, 1.0) == 0.0);
}

namespace {

/// A strip [0, 10] x [0, 1], bent to z = `bend` x^2, triangulated as a CAD part's
/// STL has it: ten points along its lower side, two at the ends of the upper one,
/// the triangles between them slivers 10 long and 1 wide at most.
TriangleSoup sliver_strip(double bend) {
  TriangleSoup soup;
  for (int i = 0; i <= 10; ++i) soup.points.push_back(Vec3(i, 0, 0));
  soup.points.push_back(Vec3(0, 1, 0));   // 11
  soup.points.push_back(Vec3(10, 1, 0));  // 12
  for (Vec3& p : soup.points) p.z() = bend * p.x() * p.x();
  for (int i = 0; i < 5; ++i) soup.triangles.push_back({i, i + 1, 11});
  soup.triangles.push_back({5, 12, 11});
  for (int i = 5; i < 10; ++i) soup.triangles.push_back({i, i + 1, 12});
  return soup;
}

}  // namespace

TEST_CASE("long edges: a flat face of slivers is split into about as many triangles as its area needs") {
  // bisection alone fans each sliver out into needles along its long sides (as
  // many as the sliver is long over the limit, each as thin as the sliver); in a
  // flat face they are flipped to the Delaunay diagonal, and the next splits fall
  // inside the face. Without the flips: 2186 triangles, smallest angle 1.9 degrees
  TriangleSoup soup = sliver_strip(0.0);
  soup.triangle_labels.resize(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) soup.triangle_labels[f] = 100 + static_cast<int>(f);
  const double limit = 0.25;
  CHECK(split_keeping_points(soup, limit) > 0);
  CHECK(soup.triangles.size() < 1300);  // 1184; right isosceles halves of the limit: 640
  CHECK(triangle_quality(soup).min_angle_deg > 10);  // 11.1 degrees
  // the same surface: in the plane, the area, every triangle turned up, conforming,
  // the same boundary, and the file's triangle labels
  double area = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const Vec3 n = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
    CHECK(n.z() > 0);
    area += 0.5 * n.z();
    for (int k = 0; k < 3; ++k) {
      CHECK(soup.points[t[k]].z() == 0.0);
      CHECK((soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm() <= limit + 1e-12);
    }
    CHECK(soup.triangle_labels[f] >= 100);
    CHECK(soup.triangle_labels[f] <= 110);
  }
  CHECK(soup.triangle_labels.size() == soup.triangles.size());
  CHECK(area == doctest::Approx(10.0));
  CHECK(conforming_boundary_length(soup) == doctest::Approx(22.0));
}

TEST_CASE("long edges: where no two triangles share a plane (a scan), the bisection alone") {
  // the same strip bent (z = x^2 / 100): each sliver in its own plane, so no flip
  // (a flip would move the surface), and the needles stay
  TriangleSoup bent = sliver_strip(0.01);
  split_long_edges(bent, 0.25);
  CHECK(bent.triangles.size() > 2000);              // 2186
  CHECK(triangle_quality(bent).min_angle_deg < 3);  // 1.9 degrees
  CHECK(bent.triangle_labels.empty());              // none read, none made
}
