// Angle smoothing (extract/quad_angle_smoothing.h) on a planar grid whose best
// positions are known: the square grid, every corner at 90 degrees.
#include "libquadmesh/extract/quad_angle_smoothing.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/size_band.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

constexpr int n = 8;

/// The unit square's n x n grid with every interior point pushed off its place by
/// up to `fraction` of a cell (deterministic).
LatticeQuads jittered_grid(double fraction = 0.2) {
  LatticeQuads q = test::grid_quads(test::grid(n), n);
  const std::vector<int> loops = test::unit_square_boundary(q);
  for (std::size_t v = 0; v < q.points.size(); ++v)
    if (loops[v] < 0)
      q.points[v] += Vec3(fraction / n * std::sin(7.0 * static_cast<double>(v)),
                          fraction / n * std::cos(5.0 * static_cast<double>(v)), 0.0);
  return q;
}

double mean_angle_deviation(const LatticeQuads& q) { return quad_quality(polygon_mesh(q), nullptr).angle_dev_mean; }

}  // namespace

TEST_CASE("angle smoothing takes a jittered grid back to right angles, boundary and fixed points kept") {
  const TriangleSoup surface = test::grid(n);
  LatticeQuads q = jittered_grid();
  const LatticeQuads jittered = q;
  const std::vector<int> loops = test::unit_square_boundary(q);
  const double before = mean_angle_deviation(q);
  REQUIRE(before > 5.0);
  // one interior point is held where it is
  std::vector<char> fixed(q.points.size(), 0);
  const std::size_t held = 3 * (n + 1) + 4;
  REQUIRE(loops[held] < 0);
  fixed[held] = 1;
  QuadAngleSmoothingOptions options;
  options.rounds = 60;
  options.min_corner_deviation_deg = 0;  // the optimizer itself, to the end
  const QuadAngleSmoothingReport report = smooth_quad_angles(surface, q, loops, fixed, options);
  CHECK(report.angle_dev_before == doctest::Approx(before));
  CHECK(report.angle_dev_after == doctest::Approx(mean_angle_deviation(q)));
  // the held point's own jitter is all that is left, spread over its neighbours
  CHECK(report.angle_dev_after < 0.25 * before);
  CHECK(report.moved_points == static_cast<std::size_t>((n - 1) * (n - 1) - 1));
  CHECK(q.points[held] == jittered.points[held]);
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    CHECK(q.points[v].z() == doctest::Approx(0.0));
    if (loops[v] >= 0) CHECK(q.points[v] == jittered.points[v]);
  }
  // with nothing held, every point goes home
  LatticeQuads free = jittered;
  options.rounds = 200;
  const QuadAngleSmoothingReport all = smooth_quad_angles(surface, free, loops, {}, options);
  CHECK(all.angle_dev_after < 0.04 * before);
  CHECK(test::min_scaled_jacobian(free) > 0.99);
}

TEST_CASE("angle smoothing leaves a point whose corners are all within min_corner_deviation_deg") {
  // jitter of 1% of a cell turns corners by about 1 degree: under the default 3
  const TriangleSoup surface = test::grid(n);
  const LatticeQuads slight = jittered_grid(0.01);
  const double largest = quad_quality(polygon_mesh(slight), nullptr).angle_dev_max;
  REQUIRE(largest > 0.1);
  REQUIRE(largest < QuadAngleSmoothingOptions{}.min_corner_deviation_deg);
  LatticeQuads q = slight;
  const QuadAngleSmoothingReport kept = smooth_quad_angles(surface, q, test::unit_square_boundary(q), {});
  CHECK(kept.moved_points == 0);
  CHECK(q.points == slight.points);
  QuadAngleSmoothingOptions every;
  every.min_corner_deviation_deg = 0;
  const QuadAngleSmoothingReport moved = smooth_quad_angles(surface, q, test::unit_square_boundary(q), {}, every);
  CHECK(moved.moved_points > 0);
  CHECK(moved.angle_dev_after < moved.angle_dev_before);
}

TEST_CASE("angle smoothing leaves right angles alone and stays within max_move") {
  const TriangleSoup surface = test::grid(n);
  LatticeQuads square = test::grid_quads(surface, n);
  const LatticeQuads untouched = square;
  const QuadAngleSmoothingReport none = smooth_quad_angles(surface, square, test::unit_square_boundary(square), {});
  CHECK(none.moved_points == 0);
  CHECK(square.points == untouched.points);

  LatticeQuads q = jittered_grid();
  const LatticeQuads jittered = q;
  QuadAngleSmoothingOptions options;
  options.max_move = 0.005;
  const QuadAngleSmoothingReport report = smooth_quad_angles(surface, q, test::unit_square_boundary(q), {}, options);
  CHECK(report.angle_dev_after < report.angle_dev_before);
  for (std::size_t v = 0; v < q.points.size(); ++v) CHECK((q.points[v] - jittered.points[v]).norm() <= 0.005 + 1e-12);
}

TEST_CASE("angle smoothing lets no quad's mean edge cross max_mean_edge") {
  const TriangleSoup surface = test::grid(n);
  const LatticeQuads jittered = jittered_grid();
  // per quad, its mean edge (as the size band measures it)
  const auto mean_edges = [](const LatticeQuads& q) { return quad_size_ratios(polygon_mesh(q), 1.0); };
  const std::vector<double> before = mean_edges(jittered);
  // unbounded, the quad that grows most: a limit half-way through its growth,
  // which it crosses unless the moves that grow it are put back
  LatticeQuads unbounded = jittered;
  smooth_quad_angles(surface, unbounded, test::unit_square_boundary(unbounded), {});
  const std::vector<double> grown = mean_edges(unbounded);
  std::size_t most = 0;
  for (std::size_t q = 0; q < before.size(); ++q)
    if (grown[q] - before[q] > grown[most] - before[most]) most = q;
  REQUIRE(grown[most] > before[most] * 1.01);
  QuadAngleSmoothingOptions options;
  options.max_mean_edge = 0.5 * (before[most] + grown[most]);
  LatticeQuads bounded = jittered;
  const QuadAngleSmoothingReport report =
      smooth_quad_angles(surface, bounded, test::unit_square_boundary(bounded), {}, options);
  CHECK(report.angle_dev_after <= report.angle_dev_before);
  const std::vector<double> after = mean_edges(bounded);
  for (std::size_t q = 0; q < before.size(); ++q)
    if (before[q] <= options.max_mean_edge) CHECK(after[q] <= options.max_mean_edge);
}

TEST_CASE("angle smoothing sweeps on past `rounds` while the mean is above target_mean_deg, and only then") {
  const TriangleSoup surface = test::grid(n);
  const std::vector<int> loops = test::unit_square_boundary(jittered_grid());
  QuadAngleSmoothingOptions options;
  options.rounds = 1;
  options.min_corner_deviation_deg = 0;
  LatticeQuads one = jittered_grid();
  const double after_one = smooth_quad_angles(surface, one, loops, {}, options).angle_dev_after;
  // a target below what one sweep leaves: more sweeps, down to the target or below
  LatticeQuads more = jittered_grid();
  options.target_mean_deg = 0.5 * after_one;
  options.extra_rounds = 40;
  const double after_more = smooth_quad_angles(surface, more, loops, {}, options).angle_dev_after;
  CHECK(after_more <= options.target_mean_deg);
  // a target above it: the same sweep as without one, point for point
  LatticeQuads same = jittered_grid();
  options.target_mean_deg = 2 * after_one;
  smooth_quad_angles(surface, same, loops, {}, options);
  CHECK(same.points == one.points);
}
