// Fitting the quads to S (extract/quad_fitting.h) on a surface with a cone-shaped
// peak in the middle of one quad: the quads cut the peak off until a corner moves
// onto it.
#include "libquadmesh/extract/deviation_refinement.h"
#include "libquadmesh/extract/quad_fitting.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

const Vec3 peak_xy(0.375, 0.375, 0.0);  // the centre of the quad [0.25, 0.5]^2

/// A cone of height 0.3 and radius 0.25 on the unit square, at peak_xy.
double height(const Vec3& p) { return 0.3 * std::max(0.0, 1.0 - (p - peak_xy).head<2>().norm() / 0.25); }

/// test::grid(n) lifted onto the cone (its points at multiples of 1/n; n = 8 has
/// the peak as a vertex).
TriangleSoup peaked_grid(int n) {
  TriangleSoup s = test::grid(n);
  for (Vec3& p : s.points) p.z() = height(p);
  return s;
}

/// The n x n quad grid with its corners on the cone.
LatticeQuads peaked_quads(int n) { return test::grid_quads(peaked_grid(n), n); }

double max_deviation(const TriangleSoup& s, const LatticeQuads& q) {
  const std::vector<double> d = quad_deviation(s, q);
  return *std::max_element(d.begin(), d.end());
}

}  // namespace

TEST_CASE("fitting: a corner moves onto a peak the quads cut off; the grid and its boundary stay") {
  const TriangleSoup surface = peaked_grid(8);
  LatticeQuads q = peaked_quads(4);
  const LatticeQuads before = q;
  const std::vector<int> loops = test::unit_square_boundary(q);
  const double deviation = max_deviation(surface, q);
  // the corners of the peak's quad are 0.177 from its apex, at height 0.088
  REQUIRE(deviation > 0.15);
  QuadFittingOptions options;
  options.tolerance = 0.02;
  const QuadFittingReport report = fit_quads_to_surface(surface, q, loops, options);
  CHECK(report.deviation_before == doctest::Approx(deviation));
  // an upper bound, equal here
  CHECK(report.deviation_after >= max_deviation(surface, q) - 1e-12);
  CHECK(report.deviation_after == doctest::Approx(max_deviation(surface, q)));
  CHECK(report.deviation_after < 0.4 * deviation);  // 0.212 -> 0.071 here
  CHECK(report.moved_points >= 1);
  CHECK(test::min_scaled_jacobian(q) >= std::min(options.min_scaled_jacobian, test::min_scaled_jacobian(before)) - 1e-12);
  CHECK(q.quads == before.quads);
  const TriangleTree tree(surface.points, surface.triangles);
  std::size_t moved = 0;
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    if (loops[v] >= 0) CHECK(q.points[v] == before.points[v]);
    CHECK(std::sqrt(tree.squared_distance(q.points[v])) < 1e-9);  // on S
    if (q.points[v] != before.points[v]) {
      ++moved;
      CHECK(q.locations[v].kind == SurfaceLocation::Kind::face);
    }
  }
  CHECK(moved == report.moved_points);
}

TEST_CASE("fitting: quads within the tolerance are left alone") {
  const TriangleSoup surface = peaked_grid(8);
  LatticeQuads q = peaked_quads(4);
  const LatticeQuads before = q;
  QuadFittingOptions options;
  options.tolerance = 1.0;
  const QuadFittingReport report = fit_quads_to_surface(surface, q, test::unit_square_boundary(q), options);
  CHECK(report.moved_points == 0);
  CHECK(report.deviation_after == report.deviation_before);
  CHECK(q.points == before.points);
}

TEST_CASE("deviation samples: S's vertices alone where its edges are at most half the tolerance") {
  const TriangleSoup coarse = test::grid(8);  // 81 vertices, 208 edges, 128 triangles; mean edge 0.142
  CHECK(deviation_samples(coarse, 1.0).size() == 81);
  CHECK(deviation_samples(coarse, 0.2).size() == 81 + 208 + 128);  // edge midpoints and centroids too
  // on a fine S the vertices give S's side of the deviation within a quarter of the tolerance
  const TriangleSoup fine = peaked_grid(32);
  const LatticeQuads q = peaked_quads(4);
  const double tolerance = 0.1;
  const std::vector<Vec3> vertices = deviation_samples(fine, tolerance);
  REQUIRE(vertices.size() == 33 * 33);
  const std::vector<double> cheap = quad_deviation(TriangleTree(fine.points, fine.triangles), vertices, q);
  const std::vector<double> full = quad_deviation(fine, q);
  for (std::size_t k = 0; k < full.size(); ++k) {
    CHECK(cheap[k] <= full[k] + 1e-12);
    CHECK(cheap[k] >= full[k] - 0.25 * tolerance);
  }
  CHECK(*std::max_element(cheap.begin(), cheap.end()) > 0.15);  // the peak is still seen
}
