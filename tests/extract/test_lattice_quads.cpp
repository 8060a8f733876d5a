// Quad extraction (method.md section 9) on maps whose grid is known exactly:
// lattice points on vertices, on edges and across a cut are the common case.
#include "libquadmesh/extract/lattice_quads.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <map>
#include <set>

using namespace qm;

namespace {

/// The map z -> scale * z + shift on a planar soup (corners in soup order).
FaceMap affine_map(const TriangleSoup& soup, Complex scale, Complex shift) {
  FaceMap m;
  for (const Triangle& t : soup.triangles) {
    CornerValues c;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = soup.points[static_cast<std::size_t>(t[i])];
      c[static_cast<std::size_t>(i)] = scale * Complex(p.x(), p.y()) + shift;
    }
    m.corners.push_back(c);
  }
  return m;
}

/// V - E + F of a quad mesh.
int euler_characteristic(const LatticeQuads& q) {
  std::set<std::pair<int, int>> edges;
  for (const auto& quad : q.quads)
    for (int i = 0; i < 4; ++i) {
      const int a = quad[static_cast<std::size_t>(i)], b = quad[static_cast<std::size_t>((i + 1) % 4)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return static_cast<int>(q.points.size()) - static_cast<int>(edges.size()) + static_cast<int>(q.quads.size());
}

}  // namespace

TEST_CASE("a grid whose lattice points are all mesh vertices gives one quad per cell") {
  // grid(n): the unit square with n x n cells split in two; scale n puts every
  // lattice point on a vertex and every grid line on mesh edges
  const TriangleSoup soup = test::grid(6);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, affine_map(soup, 6.0, 0.0), report);
  CHECK(q.quads.size() == 36);
  CHECK(q.points.size() == 49);
  CHECK(report.incomplete_cells == 0);
  CHECK(report.degenerate_cells == 0);
  CHECK(euler_characteristic(q) == 1);
  for (const SurfaceLocation& loc : q.locations) CHECK(loc.kind == SurfaceLocation::Kind::vertex);
}

TEST_CASE("a rotated and shifted grid: lattice points inside triangles and on edges") {
  const TriangleSoup soup = test::grid(7);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  // 5 x 5 cells turned by 90 degrees, the lattice shifted by half a cell in U:
  // integer points fall on edges and inside triangles; the image is [-5, 0] x [0, 5]
  // shifted, so exactly 4 x 5 cells are complete
  ExtractionReport report;
  const LatticeQuads q =
      extract_lattice_quads(soup, adjacency, affine_map(soup, Complex(0, 5.0), Complex(0.5, 0)), report);
  CHECK(q.quads.size() == 20);
  CHECK(report.incomplete_cells == 10);  // the half cells along two sides
  std::map<SurfaceLocation::Kind, int> kinds;
  for (const SurfaceLocation& loc : q.locations) ++kinds[loc.kind];
  CHECK(kinds[SurfaceLocation::Kind::face] + kinds[SurfaceLocation::Kind::edge] > 0);
  // corners map back to the square: |x|, |y| in [0, 1] and spacing 1/5
  for (const auto& quad : q.quads) {
    const Vec3 e = q.points[static_cast<std::size_t>(quad[1])] - q.points[static_cast<std::size_t>(quad[0])];
    CHECK(e.norm() == doctest::Approx(0.2).epsilon(1e-8));
  }
}

TEST_CASE("charts that differ by an integer translation across a cut give the same quads") {
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap cut = affine_map(soup, 4.0, 0.0);
  // move the triangles of the right half by (7, -3): a seam along x = 1/2
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    double x = 0;
    for (int v : soup.triangles[f]) x += soup.points[static_cast<std::size_t>(v)].x() / 3;
    if (x > 0.5)
      for (Complex& z : cut.corners[f]) z += Complex(7, -3);
  }
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, cut, report);
  CHECK(q.quads.size() == 16);
  CHECK(q.points.size() == 25);
  CHECK(report.seam_mismatches == 0);
  CHECK(euler_characteristic(q) == 1);
}

TEST_CASE("a folded triangle is reported, never extracted") {
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = affine_map(soup, 4.0, 0.0);
  // pull one interior vertex across its neighbours
  const int v = 12;  // (2/4, 2/4)... any interior vertex of grid(4)
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (soup.triangles[f][i] == v) m.corners[f][static_cast<std::size_t>(i)] += Complex(1.6, 0.0);
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, m, report);
  CHECK(report.bad_triangles > 0);
  CHECK(q.quads.size() < 16);
}

TEST_CASE("a map blown up over millions of cells is refused triangle by triangle, not enumerated") {
  // grid(4) scaled so that each triangle spans (2^12 / 4)^2 / 2 ~ 500000 cells
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, affine_map(soup, 4096.0, 0.0), report);
  CHECK(report.bad_triangles == soup.triangles.size());
  CHECK(q.quads.empty());
  // just under the limit, the same triangles are extracted: (2^7 / 4)^2 = 1024 cells per square
  const LatticeQuads fine = extract_lattice_quads(soup, adjacency, affine_map(soup, 128.0, 0.0), report);
  CHECK(report.bad_triangles == 0);
  CHECK(fine.quads.size() == 128u * 128u);
}

TEST_CASE("stray boundary points: the quads' own boundary off the boundary of S") {
  // 3 x 3 quads on the unit square, its outer ring on boundary loop 0
  const LatticeQuads full = test::grid_quads(test::grid(3), 3);
  const std::vector<int> loop_of = test::unit_square_boundary(full);
  CHECK(stray_boundary_points(full, loop_of).empty());
  // without the middle quad, its 4 corners (interior points of S) are on a hole
  // the input does not have
  LatticeQuads holed = full;
  holed.quads.erase(holed.quads.begin() + 4);
  const std::vector<int> stray = stray_boundary_points(holed, loop_of);
  CHECK(stray.size() == 4);
  for (int v : stray) CHECK(loop_of[static_cast<std::size_t>(v)] < 0);
  // without a corner quad: only its inner corner is off the square's boundary
  LatticeQuads notched = full;
  notched.quads.erase(notched.quads.begin());
  CHECK(stray_boundary_points(notched, loop_of).size() == 1);
}
