// The handle forms of handle_alignment.h on a torus with a square hole, where the
// handles are known: the ring of triangles around the tube and the ring around
// the axis. The forms must be closed around every vertex, vanish on the boundary,
// and their periods along the two rings must be a unimodular integer matrix (the
// forms are dual to a basis of the handles' cycles).
#include "libquadmesh/cones/handle_alignment.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

/// The torus of test::torus (u x v quads, two triangles each) without quad (hi, hj).
TriangleSoup holed_torus(int u, int v, int hi, int hj) {
  TriangleSoup s = test::torus(3.0, 1.0, u, v);
  const auto q = static_cast<std::size_t>(2 * (hi * v + hj));
  s.triangles.erase(s.triangles.begin() + static_cast<std::ptrdiff_t>(q), s.triangles.begin() + static_cast<std::ptrdiff_t>(q) + 2);
  return s;
}

/// Triangle a (first) or b (second) of quad (i, j) of the holed torus (the hole's
/// quad removed before it shifts the indices after it).
int triangle(int v, int hi, int hj, int i, int j, int which) {
  const int quad = i * v + j, hole = hi * v + hj;
  REQUIRE(quad != hole);
  return 2 * (quad > hole ? quad - 1 : quad) + which;
}

/// The sum of the form crossing from each triangle of the closed sequence into the next.
double period(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const SideForm& form,
              const std::vector<int>& ring) {
  double sum = 0;
  for (std::size_t s = 0; s < ring.size(); ++s) {
    const auto f = static_cast<std::size_t>(ring[s]);
    const int g = ring[(s + 1) % ring.size()];
    int side = -1;
    for (int k = 0; k < 3; ++k)
      if (adjacency.find(soup.triangles[f][(k + 1) % 3], soup.triangles[f][k]).face == g) side = k;
    REQUIRE(side >= 0);
    sum += form[f][static_cast<std::size_t>(side)];
  }
  return sum;
}

}  // namespace

TEST_CASE("handle forms on a torus with a square hole: closed, zero on the boundary, unimodular periods") {
  const int u = 12, v = 8, hi = 6, hj = 4;
  const TriangleSoup soup = holed_torus(u, v, hi, hj);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  REQUIRE(adjacency.boundary_loops.size() == 1);
  const std::vector<SideForm> forms = handle_forms(soup, adjacency);
  REQUIRE(forms.size() == 2);  // genus 1
  for (const SideForm& form : forms) {
    CHECK(max_vertex_curl(soup, adjacency, form) < 1e-12);
    for (std::size_t f = 0; f < soup.triangles.size(); ++f)
      for (int k = 0; k < 3; ++k) {
        const Triangle& t = soup.triangles[f];
        const EdgeCorner g = adjacency.find(t[(k + 1) % 3], t[k]);
        if (g.face < 0)
          CHECK(form[f][static_cast<std::size_t>(k)] == 0.0);
        else
          CHECK(form[f][static_cast<std::size_t>(k)] ==
                doctest::Approx(-form[static_cast<std::size_t>(g.face)][static_cast<std::size_t>(g.i)]).epsilon(1e-12));
      }
  }
  // around the tube (quads (2, j)) and around the axis (quads (i, 2)), away from the hole
  std::vector<int> tube, axis;
  for (int j = 0; j < v; ++j) {
    tube.push_back(triangle(v, hi, hj, 2, j, 0));
    tube.push_back(triangle(v, hi, hj, 2, j, 1));
  }
  for (int i = 0; i < u; ++i) {
    axis.push_back(triangle(v, hi, hj, i, 2, 1));
    axis.push_back(triangle(v, hi, hj, i, 2, 0));
  }
  double p[2][2];
  for (int k = 0; k < 2; ++k) {
    p[k][0] = period(soup, adjacency, forms[static_cast<std::size_t>(k)], tube);
    p[k][1] = period(soup, adjacency, forms[static_cast<std::size_t>(k)], axis);
    for (double x : p[k]) CHECK(std::abs(x - std::round(x)) < 1e-9);
  }
  CHECK(std::abs(std::round(p[0][0] * p[1][1] - p[0][1] * p[1][0])) == 1);
}

TEST_CASE("no handle forms on a surface of genus 0") {
  const TriangleSoup soup = test::annulus(1.0, 2.0, 4, 24);
  CHECK(handle_forms(soup, surface_adjacency(soup)).empty());
}
