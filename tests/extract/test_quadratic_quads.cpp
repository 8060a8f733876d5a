// Quadratic quads: every new node on the surface (not the straight midpoint),
// boundary nodes on the boundary; the Jacobian ratio of curved elements.
#include "libquadmesh/extract/quadratic_quads.h"
#include "libquadmesh/quality/curved_jacobian.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

constexpr double radius = 1.0, angle = 1.2, length = 1.0;

Vec3 on_cylinder(double u, double v) { return {radius * std::cos(u), radius * std::sin(u), v}; }

/// The panel u in [0, angle], v in [0, length] of the unit cylinder, nu x nv cells
/// split into triangles.
TriangleSoup cylinder_panel(int nu, int nv) {
  TriangleSoup s;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) s.points.push_back(on_cylinder(angle * i / nu, length * j / nv));
  const auto id = [&](int i, int j) { return j * (nu + 1) + i; };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

double off_cylinder(const Vec3& p) { return std::abs(std::hypot(p.x(), p.y()) - radius); }

}  // namespace

TEST_CASE("quadratic quads: edge and inside nodes on a curved surface, boundary nodes on its boundary") {
  const TriangleSoup surface = cylinder_panel(120, 10);
  const TriangleSoup coarse = cylinder_panel(4, 2);
  std::vector<std::array<int, 4>> quads;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 4; ++i) quads.push_back({j * 5 + i, j * 5 + i + 1, (j + 1) * 5 + i + 1, (j + 1) * 5 + i});
  // the fine triangulation's own sagitta: the tolerance of "on the surface"
  const double tolerance = radius * (1 - std::cos(angle / 120 / 2)) + 1e-12;
  const double coarse_sagitta = radius * (1 - std::cos(angle / 4 / 2));
  REQUIRE(coarse_sagitta > 100 * tolerance);  // a straight midpoint would fail the test

  for (bool complete : {false, true}) {
    CAPTURE(complete);
    QuadraticQuadsOptions options;
    options.complete = complete;
    const QuadraticQuads q = quadratic_quads(coarse.points, quads, surface, options);
    const std::size_t edges = 4 * 3 + 2 * 5;  // 3 rows of 4 edges along u, 5 columns of 2 along v
    CHECK(q.first_edge_node == 15);
    CHECK(q.edge_of_node.size() == edges);
    CHECK(q.points.size() == 15 + edges + (complete ? 8 : 0));
    CHECK(q.boundary_nodes.size() == 12);
    CHECK(q.max_move == doctest::Approx(coarse_sagitta).epsilon(0.01));
    for (std::size_t k = 15; k < q.points.size(); ++k) CHECK(off_cylinder(q.points[k]) <= tolerance);
    for (int b : q.boundary_nodes) {  // on v = 0, v = length, u = 0 or u = angle
      const Vec3& p = q.points[static_cast<std::size_t>(b)];
      const double u = std::atan2(p.y(), p.x());
      const bool on = std::abs(p.z()) < 1e-12 || std::abs(p.z() - length) < 1e-12 || std::abs(u) < 1e-9 ||
                      std::abs(u - angle) < 1e-9;
      CHECK(on);
    }
    for (const auto& e : q.elements) {
      REQUIRE(e.size() == (complete ? 9u : 8u));
      CHECK(jacobian_ratio(q.points, e) > 0.9);
    }
    const CurvedJacobians j = curved_jacobians(q.points, q.elements);
    CHECK(j.non_positive == 0);
    CHECK(j.min_ratio > 0.9);
    CHECK(j.min_ratio < 1.0);
  }
}

TEST_CASE("Jacobian ratio: 1 for a straight parallelogram, below 1 when bent, <= 0 when folded") {
  std::vector<Vec3> p{{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 0, 0}, {2.5, 0.5, 0}, {2, 1, 0}, {0.5, 0.5, 0}};
  const std::vector<int> e8{0, 1, 2, 3, 4, 5, 6, 7};
  CHECK(jacobian_ratio(p, e8) == doctest::Approx(1.0));
  std::vector<int> e4{0, 1, 2, 3};
  CHECK(jacobian_ratio(p, e4) == doctest::Approx(1.0));
  p.push_back({1.5, 0.5, 0});
  std::vector<int> e9 = e8;
  e9.push_back(8);
  CHECK(jacobian_ratio(p, e9) == doctest::Approx(1.0));
  p[4] = {1, 0.25, 0};  // the bottom edge bent inwards
  const double bent = jacobian_ratio(p, e8);
  CHECK(bent > 0);
  CHECK(bent < 0.9);
  p[4] = {1, 0.9, 0};  // past the middle: folded
  CHECK(jacobian_ratio(p, e8) <= 0);
  CHECK(curved_jacobians(p, {e8}).non_positive == 1);
  // a node off the plane does not change the in-plane determinant's sign
  p[4] = {1, 0, 0.3};
  CHECK(jacobian_ratio(p, e8) > 0);
  CHECK_THROWS(jacobian_ratio(p, {0, 1, 2}));
}
