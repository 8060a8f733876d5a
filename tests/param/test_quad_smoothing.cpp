// Smoothing of the worst quads (extract/quad_smoothing.h) on a planar grid whose
// best positions are known: the centre of the neighbours.
#include "libquadmesh/extract/quad_smoothing.h"
#include "libquadmesh/quality/quad_quality.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace qm;

namespace {

/// The n x n quad grid on the unit square, on the points of test::grid(n).
LatticeQuads grid_quads(int n) {
  const TriangleSoup soup = test::grid(n);
  LatticeQuads q;
  q.points = soup.points;
  q.locations.resize(q.points.size());
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) q.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return q;
}

std::vector<int> boundary_of(const LatticeQuads& q) {
  std::vector<int> loop(q.points.size(), -1);
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    const Vec3& p = q.points[v];
    if (p.x() == 0 || p.y() == 0 || p.x() == 1 || p.y() == 1) loop[v] = 0;
  }
  return loop;
}

double min_jacobian(const LatticeQuads& q) {
  const std::vector<double> j = quad_shape_samples(polygon_mesh(q)).scaled_jacobian;
  return *std::min_element(j.begin(), j.end());
}

}  // namespace

TEST_CASE("a skewed interior point goes back to the centre of its neighbours, on the surface") {
  const TriangleSoup surface = test::grid(4);
  LatticeQuads q = grid_quads(4);
  const int centre = 2 * 5 + 2;  // (0.5, 0.5)
  q.points[centre] += Vec3(0.18, 0.12, 0.0);
  const double before = min_jacobian(q);
  REQUIRE(before < 0.7);
  const std::vector<int> loops = boundary_of(q);
  const LatticeQuads skewed = q;
  const QuadSmoothingReport report = smooth_worst_quads(surface, q, loops);
  CHECK(report.min_before == doctest::Approx(before));
  CHECK(report.min_after > 0.99);
  CHECK(min_jacobian(q) == doctest::Approx(report.min_after));
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
  const QuadSmoothingReport report = smooth_worst_quads(surface, q, boundary_of(q), options);
  CHECK((q.points[centre] - start).norm() <= 0.05 + 1e-12);
  CHECK(report.min_after > report.min_before);

  LatticeQuads square = grid_quads(4);
  const LatticeQuads untouched = square;
  const QuadSmoothingReport none = smooth_worst_quads(surface, square, boundary_of(square));
  CHECK(none.moved_points == 0);
  CHECK(square.points == untouched.points);
}
