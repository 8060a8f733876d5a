// Smoothing of the worst quads (extract/quad_smoothing.h) on a planar grid whose
// best positions are known: the centre of the neighbours.
#include "libquadmesh/extract/quad_smoothing.h"
#include "libquadmesh/extract/internal/quad_star.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>

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

TEST_CASE("quads around a point: regular interior corners, rings, and moves put back") {
  LatticeQuads q = grid_quads(4);  // 5 x 5 points, point (i, j) = 5 j + i
  const std::vector<int> loops = test::unit_square_boundary(q);
  const QuadStar star(q);
  REQUIRE(star.quads_at.size() == q.points.size());
  std::size_t regular = 0;
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    const std::size_t i = v % 5, j = v / 5;
    const bool interior = i > 0 && i < 4 && j > 0 && j < 4;
    CHECK(star.quads_at[v].size() == (interior ? 4u : (i % 4 == 0) + (j % 4 == 0) == 2 ? 1u : 2u));
    CHECK(std::is_sorted(star.quads_at[v].begin(), star.quads_at[v].end()));
    CHECK(star.regular_interior(v, loops) == interior);
    regular += star.regular_interior(v, loops);
  }
  CHECK(regular == 9);
  CHECK(star.ring(2 * 5 + 2).size() == 16);  // the centre: every quad
  CHECK(star.ring(1 * 5 + 1).size() == 9);   // beside a corner: a 3 x 3 block
  CHECK(star.ring(0).size() == 4);           // a corner of the square: a 2 x 2 block

  const LatticeQuads before = q;
  PointMoves moves(q);
  const SurfaceLocation there{SurfaceLocation::Kind::face, -1, -1, 0, {0.2, 0.3, 0.5}};
  moves.move(12, {Vec3(0.55, 0.45, 0), there});
  moves.move(6, {Vec3(0.3, 0.2, 0), there});
  moves.move(12, {Vec3(0.52, 0.48, 0), there});
  CHECK(moves.count() == 2);
  CHECK(moves.moved(12));
  CHECK(q.points[12] == Vec3(0.52, 0.48, 0));
  CHECK(moves.original().points[12] == before.points[12]);
  moves.put_back(6);
  CHECK(!moves.moved(6));
  CHECK(q.points[6] == before.points[6]);
  CHECK(moves.count() == 1);
  moves.undo_all();
  CHECK(moves.count() == 0);
  CHECK(q.points == before.points);
}
