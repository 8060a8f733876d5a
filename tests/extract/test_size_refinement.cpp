// The size refinement (extract/size_refinement.h) on a flat grid whose middle row
// and column are four times as wide as the others: the one quad where they cross
// is 4 x the size, its two chords are split, and nothing else changes.
#include "libquadmesh/extract/size_refinement.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "libquadmesh/quality/size_band.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

/// test::grid(6) with its grid lines moved to 0, 0.1, 0.2, 0.6, 0.7, 0.85, 1 in x
/// and in y: the third row and column 0.4 wide, the others 0.1 or 0.15.
TriangleSoup uneven_grid() {
  const double lines[] = {0, 0.1, 0.2, 0.6, 0.7, 0.85, 1};
  TriangleSoup s = test::grid(6);
  for (Vec3& p : s.points) {
    p.x() = lines[std::lround(6 * p.x())];
    p.y() = lines[std::lround(6 * p.y())];
  }
  return s;
}

double largest(const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); }

}  // namespace

TEST_CASE("size refinement: the chords through a quad above the ratio are split, no irregular vertex added") {
  const TriangleSoup surface = uneven_grid();
  LatticeQuads q = test::grid_quads(surface, 6);
  std::vector<int> loops = test::unit_square_boundary(q);
  SizeRefinementOptions options;
  options.size = 0.1;
  options.max_ratio = 3.0;
  // the crossing's quad 0.4 x 0.4 (4 x), the rest of its row and column 0.4 x 0.1
  // or 0.4 x 0.15 (2.5 x, 2.75 x): only the one quad is above 3 x
  REQUIRE(largest(quad_size_ratios(polygon_mesh(q), options.size)) == doctest::Approx(4.0));
  const SizeRefinementReport report = refine_to_size(surface, surface_adjacency(surface), q, loops, options);
  CHECK(report.max_ratio_before == doctest::Approx(4.0));
  CHECK(report.chords_split == 2);
  CHECK(report.rounds == 1);
  CHECK(report.rounds_undone == 0);
  // five more quads of the row and five of the column each cut in two, the
  // crossing in four
  CHECK(report.quads_added == 13);
  CHECK(q.quads.size() == 49);
  // the crossing's quarters 0.2 x 0.2, its row's and column's halves 0.2 x 0.1 and 0.2 x 0.15
  const std::vector<double> ratios = quad_size_ratios(polygon_mesh(q), options.size);
  CHECK(largest(ratios) == doctest::Approx(2.0));
  CHECK(report.max_ratio_after == doctest::Approx(2.0));
  REQUIRE(loops.size() == q.points.size());
  // every new point on S, the boundary ones on its boundary; every interior point
  // in four quads, every boundary point but the square's corners in two
  std::vector<int> quads_at(q.points.size(), 0);
  for (const auto& c : q.quads)
    for (int v : c) ++quads_at[static_cast<std::size_t>(v)];
  const TriangleTree tree(surface.points, surface.triangles);
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    const Vec3& p = q.points[v];
    CHECK(std::sqrt(tree.squared_distance(p)) < 1e-12);
    const bool on_boundary = p.x() == 0 || p.y() == 0 || p.x() == 1 || p.y() == 1;
    CHECK((loops[v] >= 0) == on_boundary);
    const bool corner = (p.x() == 0 || p.x() == 1) && (p.y() == 0 || p.y() == 1);
    CHECK(quads_at[v] == (corner ? 1 : on_boundary ? 2 : 4));
  }
  CHECK(test::min_scaled_jacobian(q) == doctest::Approx(1.0));
}

TEST_CASE("size refinement: quads all within the ratio are left alone") {
  const TriangleSoup surface = uneven_grid();
  LatticeQuads q = test::grid_quads(surface, 6);
  const LatticeQuads before = q;
  std::vector<int> loops = test::unit_square_boundary(q);
  SizeRefinementOptions options;
  options.size = 0.15;  // the largest quad 2.67 x
  options.max_ratio = 3.0;
  const SizeRefinementReport report = refine_to_size(surface, surface_adjacency(surface), q, loops, options);
  CHECK(report.chords_split == 0);
  CHECK(report.quads_added == 0);
  CHECK(report.max_ratio_after == report.max_ratio_before);
  CHECK(q.quads == before.quads);
  CHECK(q.points == before.points);
}
