// Longest-edge bisection of triangles wider than the quads (forms/long_edges.h).
#include "libquadmesh/forms/long_edges.h"
#include "libquadmesh/topology/internal/edge_incidence.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace qm;

TEST_CASE("long edges: split until none is longer than the limit, every input vertex kept") {
  TriangleSoup soup = test::grid(2);  // edges 0.5, diagonals 0.71
  for (int j = 0; j < 2; ++j) soup.cad.edges.push_back({j, j + 1, 7});  // the side x = 0 is CAD curve 7
  const TriangleSoup before = soup;
  const double limit = 0.2;
  const std::size_t splits = split_long_edges(soup, limit);
  CHECK(splits > 0);
  CHECK(soup.points.size() == before.points.size() + splits);
  for (std::size_t v = 0; v < before.points.size(); ++v) CHECK(soup.points[v] == before.points[v]);

  double area = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3 n = (soup.points[t[1]] - soup.points[t[0]]).cross(soup.points[t[2]] - soup.points[t[0]]);
    CHECK(n.z() > 0);  // orientation kept
    area += 0.5 * n.z();
    for (int k = 0; k < 3; ++k) CHECK((soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm() <= limit + 1e-12);
  }
  CHECK(area == doctest::Approx(1.0));
  // conforming: every edge has one or two triangles, boundary edges only on the square's sides
  const EdgeIncidence inc = edge_incidence(soup);
  double boundary = 0;
  for (std::size_t e = 0; e < inc.edge_count(); ++e) {
    CHECK(inc.valence(static_cast<int>(e)) <= 2);
    if (inc.is_boundary(static_cast<int>(e)))
      boundary += (soup.points[inc.edges[e][0]] - soup.points[inc.edges[e][1]]).norm();
  }
  CHECK(boundary == doctest::Approx(4.0));
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
