// Untangling folds of a parameterization (method.md section 9) and cones that
// share a lattice point (section 7, constraint 3), on planar grids whose maps are
// known exactly.
#include "libquadmesh/param/barrier_untangle.h"
#include "libquadmesh/param/untangle.h"
#include "libquadmesh/param/zero_stars.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

/// The map (x, y) -> scale * (x + bump(x, y), y) on the planar grid: a Gaussian
/// push along U of height `amplitude` and width `width` around `centre`. Its
/// U-derivative turns negative (a fold) when amplitude / width > ~1.17.
FaceMap pushed_map(const TriangleSoup& soup, double scale, Complex centre, double amplitude, double width) {
  FaceMap m;
  for (const Triangle& t : soup.triangles) {
    CornerValues c;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = soup.points[static_cast<std::size_t>(t[i])];
      const double r2 = std::norm(Complex(p.x(), p.y()) - centre);
      c[static_cast<std::size_t>(i)] = scale * Complex(p.x() - amplitude * std::exp(-r2 / (width * width)), p.y());
    }
    m.corners.push_back(c);
  }
  return m;
}

/// Every vertex has one image: the map has no cut, so its corners must agree.
bool continuous(const TriangleSoup& soup, const FaceMap& m) {
  std::vector<Complex> image(soup.points.size());
  std::vector<char> seen(soup.points.size(), 0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const auto v = static_cast<std::size_t>(soup.triangles[f][i]);
      const Complex z = m.corners[f][static_cast<std::size_t>(i)];
      if (seen[v] && std::abs(image[v] - z) > 1e-12) return false;
      seen[v] = 1;
      image[v] = z;
    }
  return true;
}

Complex image_of(const TriangleSoup& soup, const FaceMap& m, int v) {
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (soup.triangles[f][i] == v) return m.corners[f][static_cast<std::size_t>(i)];
  return {};
}

int vertex_at(const TriangleSoup& soup, double x, double y) {
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (std::abs(soup.points[v].x() - x) < 1e-9 && std::abs(soup.points[v].y() - y) < 1e-9) return static_cast<int>(v);
  return -1;
}

}  // namespace

TEST_CASE("a crease inside: the barrier untangles it, the map stays continuous and the cone stays put") {
  const TriangleSoup soup = test::grid(24);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = pushed_map(soup, 24.0, Complex(0.5, 0.5), 0.2, 0.08);
  const FaceMap before = m;
  const std::size_t folded = count_flipped(m);
  REQUIRE(folded >= 10);
  std::vector<char> pinned(soup.points.size(), 0);
  const int cone = vertex_at(soup, 0.5, 0.5);
  pinned[static_cast<std::size_t>(cone)] = 1;

  const UntangleReport report = untangle_by_barrier(soup, adjacency, m, pinned);
  CHECK(report.flipped_before == folded);
  CHECK(report.flipped_after == 0);
  CHECK(count_flipped(m) == 0);
  CHECK(report.moved_vertices > 0);
  CHECK(continuous(soup, m));
  CHECK(image_of(soup, m, cone) == image_of(soup, before, cone));
  // far from the crease nothing moves: the outer ring of every region is fixed
  for (double x : {0.0, 0.25, 1.0})
    for (double y : {0.0, 0.1, 1.0})
      CHECK(image_of(soup, m, vertex_at(soup, x, y)) == image_of(soup, before, vertex_at(soup, x, y)));
}

TEST_CASE("a crease on the boundary: boundary vertices slide along U only") {
  const TriangleSoup soup = test::grid(24);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = pushed_map(soup, 24.0, Complex(0.5, 0.0), 0.2, 0.08);
  REQUIRE(count_flipped(m) > 0);
  const std::vector<char> pinned(soup.points.size(), 0);
  const UntangleReport report = untangle_by_barrier(soup, adjacency, m, pinned);
  CHECK(report.flipped_after == 0);
  CHECK(continuous(soup, m));
  // the bottom edge (y = 0) stays on V = 0: the boundary keeps its level
  for (int k = 0; k <= 24; ++k) CHECK(image_of(soup, m, vertex_at(soup, k / 24.0, 0.0)).imag() == 0.0);
}

TEST_CASE("a corner closer than one lattice unit to a boundary zero takes the zero's place") {
  const TriangleSoup soup = test::grid(10);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const FaceMap m = pushed_map(soup, 4.0, Complex(0, 0), 0.0, 1.0);  // 4 (x + i y): edges 0.4 long
  const int corner = vertex_at(soup, 0.0, 0.0);
  const int near = vertex_at(soup, 0.2, 0.0);  // image distance 0.8
  const int far = vertex_at(soup, 1.0, 0.5);   // image distance > 4
  const ZeroVertex corner_cone{corner, 0, true, true};

  const std::vector<ZeroVertex> merged =
      add_corners(soup, adjacency, m, {ZeroVertex{near, 1, true, false}}, {corner_cone}, 1.0);
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].vertex == corner);
  CHECK(merged[0].order == 1);
  CHECK_FALSE(merged[0].corner);

  const std::vector<ZeroVertex> apart =
      add_corners(soup, adjacency, m, {ZeroVertex{far, 1, true, false}}, {corner_cone}, 1.0);
  REQUIRE(apart.size() == 2);
  CHECK(apart[0].vertex == far);
  CHECK(apart[1].vertex == corner);
  CHECK(apart[1].corner);
}

TEST_CASE("two zeros of one boundary loop merge only when closer than a tenth of a cell") {
  const TriangleSoup soup = test::grid(10);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const FaceMap m = pushed_map(soup, 0.8, Complex(0, 0), 0.0, 1.0);  // edges 0.08 long in the image
  auto boundary_zero = [&](double x) { return ZeroVertex{vertex_at(soup, x, 0.0), 1, true, false}; };
  // 0.16 apart on the boundary: distinct integers U separate them (merged, the arc
  // between them would collapse, and the untangled map would branch at two points
  // of one lattice U: p7 and p13 of scripts/plate-sweep left a gap there)
  CHECK(merge_close_zeros(soup, adjacency, m, {boundary_zero(0.5), boundary_zero(0.7)}, 1.0).size() == 2);
  CHECK(merge_close_zeros(soup, adjacency, m, {boundary_zero(0.5), boundary_zero(0.9)}, 1.0).size() == 2);
  // 0.08 apart: one zero of order 2
  const std::vector<ZeroVertex> close = merge_close_zeros(soup, adjacency, m, {boundary_zero(0.5), boundary_zero(0.6)}, 1.0);
  REQUIRE(close.size() == 1);
  CHECK(close[0].order == 2);
  // interior zeros 0.8 apart (edges 0.4 long in the image) cannot both take a
  // lattice point: merged
  const FaceMap coarse = pushed_map(soup, 4.0, Complex(0, 0), 0.0, 1.0);
  const std::vector<ZeroVertex> inside = merge_close_zeros(
      soup, adjacency, coarse, {ZeroVertex{vertex_at(soup, 0.5, 0.5), 1, false, false}, ZeroVertex{vertex_at(soup, 0.7, 0.5), 1, false, false}},
      1.0);
  REQUIRE(inside.size() == 1);
  CHECK(inside[0].order == 2);
}

TEST_CASE("zeros of two boundary loops never merge, however close") {
  // a thin annulus: inner and outer circle 0.1 apart, 0.4 in the image
  const TriangleSoup soup = test::annulus(1.0, 1.1, 1, 48);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const FaceMap m = pushed_map(soup, 4.0, Complex(0, 0), 0.0, 1.0);
  auto nearest = [&](double x, double y) {
    int best = 0;
    for (std::size_t v = 1; v < soup.points.size(); ++v)
      if (std::hypot(soup.points[v].x() - x, soup.points[v].y() - y) <
          std::hypot(soup.points[static_cast<std::size_t>(best)].x() - x, soup.points[static_cast<std::size_t>(best)].y() - y))
        best = static_cast<int>(v);
    return best;
  };
  const int inner = nearest(1.0, 0.0), outer = nearest(1.1, 0.0);
  REQUIRE(adjacency.loop_of_vertex[static_cast<std::size_t>(inner)] != adjacency.loop_of_vertex[static_cast<std::size_t>(outer)]);
  const std::vector<ZeroVertex> zeros =
      merge_close_zeros(soup, adjacency, m, {ZeroVertex{inner, 1, true, false}, ZeroVertex{outer, 1, true, false}}, 1.0);
  REQUIRE(zeros.size() == 2);
  CHECK(zeros[0].vertex == inner);
  CHECK(zeros[1].vertex == outer);
}
