// Smoothing of the worst quads (extract/quad_smoothing.h) on a planar grid whose
// best positions are known: the centre of the neighbours.
#include "libquadmesh/extract/quad_smoothing.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

using namespace qm;

namespace {

LatticeQuads grid_quads(int n) { return test::grid_quads(test::grid(n), n); }

}  // namespace

TEST_CASE("a skewed interior point goes back to the centre of its neighbours, on the surface") {
  const TriangleSoup surface = test::grid(4);
  LatticeQuads q = grid_quads(4);
  const int centre = 2 * 5 + 2;  // (0.5, 0.5)
  q.points[centre] += Vec3(0.18, 0.12, 0.0);
  const double before = test::min_scaled_jacobian(q);
  REQUIRE(before < 0.7);
  const std::vector<int> loops = test::unit_square_boundary(q);
  const LatticeQuads skewed = q;
  const QuadSmoothingReport report = smooth_worst_quads(surface, q, loops);
  CHECK(report.min_before == doctest::Approx(before));
  CHECK(report.min_after > 0.99);
  CHECK(test::min_scaled_jacobian(q) == doctest::Approx(report.min_after));
  CHECK((q.points[centre] - Vec3(0.5, 0.5, 0)).norm() < 1e-3);
  CHECK(report.moved_points >= 1);
  // boundary points stay; every point stays on the plane of S
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    CHECK(q.points[v].z() == doctest::Approx(0.0));
    if (loops[v] >= 0) CHECK(q.points[v] == skewed.points[v]);
  }
  CHECK(q.locations[centre].kind == SurfaceLocation::Kind::face);
  CHECK(q.locations[centre].face >= 0);
}

TEST_CASE("smoothing: a move is limited by max_move, and quads already good are left alone") {
  const TriangleSoup surface = test::grid(4);
  LatticeQuads q = grid_quads(4);
  const int centre = 2 * 5 + 2;
  q.points[centre] += Vec3(0.18, 0.12, 0.0);
  QuadSmoothingOptions options;
  options.max_move = 0.05;
  const Vec3 start = q.points[centre];
  const QuadSmoothingReport report = smooth_worst_quads(surface, q, test::unit_square_boundary(q), options);
  CHECK((q.points[centre] - start).norm() <= 0.05 + 1e-12);
  CHECK(report.min_after > report.min_before);

  LatticeQuads square = grid_quads(4);
  const LatticeQuads untouched = square;
  const QuadSmoothingReport none = smooth_worst_quads(surface, square, test::unit_square_boundary(square));
  CHECK(none.moved_points == 0);
  CHECK(square.points == untouched.points);
}
