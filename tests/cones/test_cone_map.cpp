// Integer-grid maps with prescribed quarter-turn cones (method.md section 11) on
// a square and an L-shape, where the answer is known: with only the corners as
// cones the map is the scaled square itself; a valence-3/5 pair inside turns the
// charts by quarter turns across the cut between them.
#include "libquadmesh/cones/cone_map.h"
#include "libquadmesh/core/error.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

int vertex_at(const TriangleSoup& soup, double x, double y) {
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (std::abs(soup.points[v].x() - x) < 1e-12 && std::abs(soup.points[v].y() - y) < 1e-12) return static_cast<int>(v);
  return -1;
}

/// The images of v in every triangle corner at v.
std::vector<Complex> images_of(const TriangleSoup& soup, const FaceMap& map, int v) {
  std::vector<Complex> out;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k)
      if (soup.triangles[f][k] == v) out.push_back(map.corners[f][k]);
  return out;
}

bool on_lattice(Complex z) {
  return std::abs(z.real() - std::round(z.real())) < 1e-6 && std::abs(z.imag() - std::round(z.imag())) < 1e-6;
}

std::vector<Cone> square_corners(const TriangleSoup& soup, double side) {
  return {{vertex_at(soup, 0, 0), 1}, {vertex_at(soup, side, 0), 1}, {vertex_at(soup, side, side), 1},
          {vertex_at(soup, 0, side), 1}};
}

}  // namespace

TEST_CASE("a cone set that breaks Gauss-Bonnet is refused with the count it misses") {
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  // a disk needs four quarter turns; no corner cone gives none
  CHECK_THROWS_WITH_AS(cone_map(soup, adjacency, {}, 0.25),
                       "the cones turn by 0 quarter turns in all where Gauss-Bonnet needs 4 (4 chi, chi = 1)", Error);
  CHECK_THROWS_WITH_AS(cone_map(soup, adjacency, {{1000, 3}}, 0.25), doctest::Contains("cone 0 (vertex 1000): no such vertex"),
                       Error);
}

TEST_CASE("a square with its four corners as cones maps onto the scaled square") {
  const TriangleSoup soup = test::grid(8);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const ConeMap m = cone_map(soup, adjacency, square_corners(soup, 1.0), 0.25);
  CHECK(m.field.max_misalignment < 1e-7);
  CHECK(m.cut.cut_edges == 0);
  CHECK(m.report.inverted_triangles == 0);
  CHECK(m.report.max_seam_residual < 1e-6);
  CHECK(total_image_area(m.map) == doctest::Approx(16.0).epsilon(1e-6));
  for (const Cone& c : square_corners(soup, 1.0))
    for (Complex z : images_of(soup, m.map, c.vertex)) CHECK(on_lattice(z));
  // the metric needs no change: the corners already turn by a quarter each
  CHECK(m.u.cwiseAbs().maxCoeff() < 1e-9);
}

TEST_CASE("a valence-3/5 pair inside a square: quarter-turn transitions, cones on lattice points") {
  const TriangleSoup soup = test::grid(12);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  std::vector<Cone> cones = square_corners(soup, 1.0);
  const int three = vertex_at(soup, 4.0 / 12, 6.0 / 12), five = vertex_at(soup, 8.0 / 12, 6.0 / 12);
  cones.push_back({three, 3});
  cones.push_back({five, 5});
  const ConeMap m = cone_map(soup, adjacency, cones, 1.0 / 6);
  CHECK(m.field.max_misalignment < 1e-7);
  CHECK(m.cut.cut_edges > 0);
  int turned = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (std::size_t k = 0; k < 3; ++k) turned += m.cut.cut_side[f][k] && m.field.quarter_turns[f][k] != 0;
  CHECK(turned > 0);
  CHECK(m.report.max_seam_residual < 1e-6);
  CHECK(m.report.inverted_triangles == 0);
  for (int v : {three, five})
    for (Complex z : images_of(soup, m.map, v)) CHECK(on_lattice(z));
  for (const Cone& c : square_corners(soup, 1.0))
    for (Complex z : images_of(soup, m.map, c.vertex)) CHECK(on_lattice(z));
}

TEST_CASE("an L-shape with its five convex corners and one concave corner maps onto a lattice L") {
  const TriangleSoup soup = test::l_shape(6);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  std::vector<Cone> cones;
  for (auto [x, y] : {std::pair{0.0, 0.0}, {2.0, 0.0}, {2.0, 1.0}, {1.0, 2.0}, {0.0, 2.0}})
    cones.push_back({vertex_at(soup, x, y), 1});
  cones.push_back({vertex_at(soup, 1.0, 1.0), 3});
  const ConeMap m = cone_map(soup, adjacency, cones, 1.0 / 3);
  CHECK(m.field.max_misalignment < 1e-7);
  CHECK(m.report.max_seam_residual < 1e-6);
  CHECK(m.report.inverted_triangles == 0);
  // three unit squares of 3 x 3 cells each
  CHECK(total_image_area(m.map) == doctest::Approx(27.0).epsilon(1e-6));
  for (const Cone& c : cones)
    for (Complex z : images_of(soup, m.map, c.vertex)) CHECK(on_lattice(z));
}
