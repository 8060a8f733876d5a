// Topology of generated surfaces whose numbers are known by construction.
#include "libquadmesh/core/mesh.h"
#include "libquadmesh/topology/applicability.h"
#include "libquadmesh/topology/internal/soup_cleaning.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace qm;

namespace {

AnalyzedSurface analyze(const TriangleSoup& soup) { return analyze_topology(soup); }

TriangleSoup disjoint_union(const TriangleSoup& a, const TriangleSoup& b, const Vec3& shift) {
  TriangleSoup out = a;
  const int offset = static_cast<int>(a.points.size());
  for (const Vec3& p : b.points) out.points.push_back(p + shift);
  for (const Triangle& t : b.triangles)
    out.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  return out;
}

/// Signed area of a closed planar polygon (x, y), counter-clockwise positive.
double signed_area(const TriangleSoup& soup, const std::vector<int>& loop) {
  double twice = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3& p = soup.points[loop[i]];
    const Vec3& q = soup.points[loop[(i + 1) % loop.size()]];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return twice / 2;
}

}  // namespace

TEST_CASE("annulus: chi 0, two boundaries, supported with doubled genus 1") {
  const AnalyzedSurface s = analyze(test::annulus(1.0, 2.0, 4, 16));
  const TopologyReport& r = s.report;
  CHECK(r.vertices == 80);
  CHECK(r.faces == 128);
  CHECK(r.edges == 80 + 128 - 0);  // V - E + F = 0
  CHECK(r.euler_characteristic == 0);
  CHECK(r.boundary_loop_count() == 2);
  CHECK(r.genus == 0);
  CHECK(r.manifold());
  CHECK(r.orientation.consistent);
  const Applicability a = assess_applicability(s);
  CHECK(a.supported);
  CHECK(a.kind == SurfaceCase::annulus);
  CHECK(a.doubled_genus == 1);
}

TEST_CASE("boundary loops are ordered cycles with the surface on their left") {
  const AnalyzedSurface s = analyze(test::annulus(1.0, 2.0, 3, 24));
  REQUIRE(s.report.boundary.loops.size() == 2);
  for (std::size_t l = 0; l < 2; ++l) {
    const auto& loop = s.report.boundary.loops[l];
    CHECK(loop.size() == 24);
    // consecutive points are joined by an edge of the loop: |p_i - p_{i+1}| is a chord
    const double radius = s.soup.points[loop[0]].norm();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      CHECK(s.soup.points[loop[i]].norm() == doctest::Approx(radius));
      const double chord = (s.soup.points[loop[i]] - s.soup.points[loop[(i + 1) % 24]]).norm();
      CHECK(chord == doctest::Approx(2 * radius * std::sin(M_PI / 24)));
    }
    // outer loop counter-clockwise, inner loop clockwise (triangles face +z)
    const double area = signed_area(s.soup, loop);
    CHECK(area == doctest::Approx(radius > 1.5 ? 4 * 24 * std::sin(M_PI / 12) / 2
                                               : -24 * std::sin(M_PI / 12) / 2));
  }
}

TEST_CASE("disk and sphere are refused: no holomorphic 1-form") {
  const Applicability d = assess_applicability(analyze(test::disk(3, 12)));
  CHECK_FALSE(d.supported);
  CHECK(d.kind == SurfaceCase::disk);
  CHECK(d.code == ErrorCode::unsupported);
  CHECK(d.reason.find("chi = 1") != std::string::npos);
  CHECK(d.reason.find("disk") != std::string::npos);

  const AnalyzedSurface sphere = analyze(test::sphere());
  CHECK(sphere.report.euler_characteristic == 2);
  CHECK(sphere.report.genus == 0);
  const Applicability s = assess_applicability(sphere);
  CHECK_FALSE(s.supported);
  CHECK(s.kind == SurfaceCase::sphere);
  CHECK(s.reason.find("chi = 2") != std::string::npos);
}

TEST_CASE("torus: closed genus 1, forms on the surface itself") {
  const AnalyzedSurface s = analyze(test::torus(3.0, 1.0, 24, 12));
  CHECK(s.report.euler_characteristic == 0);
  CHECK(s.report.boundary_loop_count() == 0);
  CHECK(s.report.genus == 1);
  const Applicability a = assess_applicability(s);
  CHECK(a.supported);
  CHECK(a.kind == SurfaceCase::closed);
  CHECK(a.doubled_genus == 1);
}

TEST_CASE("Möbius strip: non-orientable, one boundary loop") {
  const AnalyzedSurface s = analyze(test::moebius(20));
  CHECK_FALSE(s.report.orientation.orientable);
  CHECK(s.report.manifold());
  CHECK(s.report.euler_characteristic == 0);
  CHECK(s.report.boundary_loop_count() == 1);
  CHECK(s.report.boundary.loops[0].size() == 40);
  CHECK(s.report.genus == -1);
  const Applicability a = assess_applicability(s);
  CHECK_FALSE(a.supported);
  CHECK(a.kind == SurfaceCase::non_orientable);
  CHECK(a.code == ErrorCode::unsupported);
}

TEST_CASE("several components are refused; the largest one can be kept") {
  const AnalyzedSurface two = analyze(test::two_components());
  CHECK(two.report.components.count == 2);
  const Applicability a = assess_applicability(two);
  CHECK_FALSE(a.supported);
  CHECK(a.kind == SurfaceCase::several_components);
  CHECK(a.reason.find("2 connected components") != std::string::npos);

  const TriangleSoup small = test::disk(2, 8), big = test::annulus(1, 2, 5, 20);
  const AnalyzedSurface mixed = analyze(disjoint_union(small, big, Vec3(10, 0, 0)));
  CHECK(mixed.report.components.count == 2);
  const AnalyzedSurface largest = largest_component(mixed);
  CHECK(largest.report.components.count == 1);
  CHECK(largest.report.faces == big.triangles.size());
  CHECK(largest.report.vertices == big.points.size());
  CHECK(assess_applicability(largest).kind == SurfaceCase::annulus);
}

TEST_CASE("bow-tie: a non-manifold vertex is bad input that names the vertex") {
  const AnalyzedSurface s = analyze(test::bow_tie());
  CHECK(s.report.edge_manifold());
  REQUIRE(s.report.nonmanifold_vertices.size() == 1);
  CHECK(s.report.nonmanifold_vertices[0] == 0);
  const Applicability a = assess_applicability(s);
  CHECK(a.code == ErrorCode::bad_input);
  CHECK(a.reason.find("non-manifold vertex 0 at (0, 0, 0)") != std::string::npos);
  CHECK_THROWS_AS(require_supported(s), Error);
}

TEST_CASE("three triangles on an edge: a non-manifold edge named by its vertices") {
  const AnalyzedSurface s = analyze(test::book());
  REQUIRE(s.report.nonmanifold_edges.size() == 1);
  CHECK(s.report.nonmanifold_edges[0].a == 0);
  CHECK(s.report.nonmanifold_edges[0].b == 1);
  CHECK(s.report.nonmanifold_edges[0].triangles == 3);
  const Applicability a = assess_applicability(s);
  CHECK(a.code == ErrorCode::bad_input);
  CHECK(a.reason.find("non-manifold edge between vertex 0") != std::string::npos);
}

TEST_CASE("inconsistent orientation is repaired, the majority wins") {
  TriangleSoup soup = test::annulus(1, 2, 3, 12);
  std::swap(soup.triangles[5][1], soup.triangles[5][2]);
  std::swap(soup.triangles[17][1], soup.triangles[17][2]);
  const AnalyzedSurface s = analyze(soup);
  CHECK(s.report.orientation.orientable);
  CHECK_FALSE(s.report.orientation.consistent);
  CHECK(s.report.orientation.flip_count == 2);
  // the repaired soup is the original one
  const TriangleSoup original = test::annulus(1, 2, 3, 12);
  CHECK(s.soup.triangles == original.triangles);
  CHECK(assess_applicability(s).supported);
  const Mesh mesh = to_surface_mesh(s.soup);
  CHECK(mesh.number_of_faces() == original.triangles.size());
  CHECK(mesh.is_valid(false));
}

TEST_CASE("element defects: unreferenced, non-finite, repeated, duplicate, zero-area") {
  TriangleSoup soup = test::annulus(1, 2, 2, 8);
  soup.points.emplace_back(9, 9, 9);  // unreferenced
  AnalyzedSurface s = analyze(soup);
  CHECK(s.report.unreferenced_points == 1);
  CHECK(s.report.points_read == 25);
  CHECK(s.report.vertices == 24);

  TriangleSoup nan_soup = test::annulus(1, 2, 2, 8);
  nan_soup.points[3].y() = std::numeric_limits<double>::quiet_NaN();
  s = analyze(nan_soup);
  CHECK(s.report.nonfinite_vertices == std::vector<int>{3});
  CHECK(assess_applicability(s).reason.find("vertex 3 at (") != std::string::npos);
  CHECK(assess_applicability(s).code == ErrorCode::bad_input);

  TriangleSoup repeated = test::grid(2);
  repeated.triangles.push_back({0, 0, 4});
  CHECK(repeated_corner_triangles(repeated) == std::vector<int>{8});

  TriangleSoup duplicated = test::grid(2);
  duplicated.triangles.push_back({duplicated.triangles[3][0], duplicated.triangles[3][2],
                                  duplicated.triangles[3][1]});
  CHECK(duplicate_triangles(duplicated) == std::vector<int>{8});
  CHECK(assess_applicability(analyze(duplicated)).reason.find("repeats the vertices") !=
        std::string::npos);

  TriangleSoup flat = test::grid(2);  // points (0,0), (0.5,0), (1,0) are collinear: ids 0, 3, 6
  flat.triangles.push_back({0, 3, 6});
  CHECK(zero_area_triangles(flat) == std::vector<int>{8});
}

TEST_CASE("coordinates outside the range the method computes in are refused with their figures") {
  const auto scaled = [](double factor, const Vec3& shift) {
    TriangleSoup soup = test::annulus(1, 2, 2, 8);
    for (Vec3& p : soup.points) p = p * factor + shift;
    return soup;
  };
  // the same annulus from a micron to 1e9 units across, and 1e5 of its sizes away: supported
  for (const double factor : {1e-6, 1.0, 1e9})
    CHECK(assess_applicability(analyze(scaled(factor, Vec3(1e5 * factor, 0, 0)))).supported);
  // a coordinate of 1e300 (the forms overflowed and the program died after `info` said supported)
  Applicability a = assess_applicability(analyze(scaled(1e300, Vec3::Zero())));
  CHECK(a.code == ErrorCode::bad_input);
  CHECK(a.kind == SurfaceCase::invalid);
  CHECK(a.reason.find("has a coordinate of 2e+300") != std::string::npos);
  CHECK(a.reason.find("vertex ") == 0);
  // 1e-160 across: the cotangent weights underflow
  a = assess_applicability(analyze(scaled(1e-160, Vec3::Zero())));
  CHECK(a.code == ErrorCode::bad_input);
  CHECK(a.reason.find("the model is 5.66e-160 across") == 0);
  // a 4-unit annulus 1e10 from the origin: 7 digits of its edges left
  a = assess_applicability(analyze(scaled(1.0, Vec3(1e10, 0, 0))));
  CHECK(a.code == ErrorCode::bad_input);
  CHECK(a.reason.find("from the origin, more than 1e+09 times the model's size") != std::string::npos);
  // the checks' own figures
  const CoordinateRange r = coordinate_range(scaled(1.0, Vec3(0, 0, 3)));
  CHECK(r.largest_magnitude == doctest::Approx(3.0));
  CHECK(r.diagonal == doctest::Approx(std::sqrt(32.0)));
}

TEST_CASE("empty soup is bad input") {
  const Applicability a = assess_applicability(analyze(TriangleSoup{}));
  CHECK_FALSE(a.supported);
  CHECK(a.code == ErrorCode::bad_input);
}
