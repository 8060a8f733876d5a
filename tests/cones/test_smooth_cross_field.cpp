// The smoothest boundary-aligned cross field (smooth_cross_field.h): on shapes
// whose field is known it is exact, and its indices always add up to what
// Gauss-Bonnet leaves to the interior once the corners are counted.
#include "libquadmesh/cones/cone_placement.h"
#include "libquadmesh/cones/smooth_cross_field.h"
#include "io/read_surface.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <cmath>

using namespace qm;

namespace {

/// 4 chi - sum (2 - q) over the corners at quads of edge `size`: the quarter turns
/// the interior cones carry.
int interior_quarter_turns(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, double size) {
  int deficit = 4 * euler_characteristic(adjacency);
  for (const Cone& c : corner_cones(soup, size)) deficit -= 2 - c.quads;
  return deficit;
}

int index_sum(const SmoothCrossField& field) {
  int sum = 0;
  for (int m : field.index) sum += m;
  return sum;
}

}  // namespace

TEST_CASE("the smooth cross field of a square grid is the constant one: no singularity") {
  const TriangleSoup soup = test::grid(8);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const SmoothCrossField field = smooth_cross_field(soup, adjacency);
  // every triangle's cross along the axes: psi = e^(4 i theta) with theta the
  // axis' angle in the local frame, so |psi| = 1 everywhere
  for (const auto& psi : field.psi) CHECK(std::abs(std::abs(psi) - 1) < 1e-9);
  CHECK(field_singularities(field).empty());
}

TEST_CASE("an annulus: the field follows both circles everywhere, no singularity") {
  const TriangleSoup soup = test::annulus(1.0, 2.0, 8, 48);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  CrossFieldOptions options;
  options.length = 0.25;
  const SmoothCrossField field = smooth_cross_field(soup, adjacency, options);
  CHECK(field_singularities(field).empty());
  // the analytic field is the circles' tangent: compare in each triangle's frame
  // (corner 0 at 0, corner 1 on the real axis, counter-clockwise)
  double worst = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const Vec3 p0 = soup.points[static_cast<std::size_t>(t[0])], p1 = soup.points[static_cast<std::size_t>(t[1])],
               p2 = soup.points[static_cast<std::size_t>(t[2])];
    const Vec3 e1 = (p1 - p0).normalized(), normal = (p1 - p0).cross(p2 - p0).normalized();
    const Vec3 e2 = normal.cross(e1);
    const Vec3 centre = (p0 + p1 + p2) / 3;
    const Vec3 tangent(-centre.y(), centre.x(), 0);
    const std::complex<double> expected = std::pow(std::complex<double>(tangent.dot(e1), tangent.dot(e2)) /
                                                       tangent.norm(), 4);
    worst = std::max(worst, std::abs(std::arg(field.psi[f] / expected)) / 4);
  }
  CHECK(worst < 2 * M_PI / 180);
}

TEST_CASE("a disk: four valence-3 singularities inside, not one of index 1 at the centre") {
  const TriangleSoup soup = test::disk(12, 48);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  CrossFieldOptions options;
  options.length = 0.2;
  const SmoothCrossField field = smooth_cross_field(soup, adjacency, options);
  const std::vector<Cone> cones = field_singularities(field);
  REQUIRE(cones.size() == 4);
  for (const Cone& c : cones) CHECK(c.quads == 3);
  CHECK(index_sum(field) == interior_quarter_turns(soup, adjacency, options.length));
  // without the diffusion steps, the linear minimizer merges them at the centre
  options.diffusion_steps = 0;
  const std::vector<Cone> merged = field_singularities(smooth_cross_field(soup, adjacency, options));
  REQUIRE(merged.size() == 1);
  CHECK(merged[0].quads == 0);
}

TEST_CASE("plate, T-plate and a curved shell with holes: indices add up to what the corners leave" *
          doctest::test_suite("slow")) {
  for (const char* name : {"plate-two-holes.geo", "t-plate-two-holes.geo", "curved-shell-holes.geo",
                           "bent-bracket.geo"}) {
    CAPTURE(name);
    io::ReadOptions read;
    read.quad_size = 2.0;
    const TriangleSoup soup = io::read_surface(test::example(name), read).soup;
    const SurfaceAdjacency adjacency = surface_adjacency(soup);
    const SmoothCrossField field = smooth_cross_field(soup, adjacency);
    CHECK(index_sum(field) == interior_quarter_turns(soup, adjacency, read.quad_size));
    MESSAGE(name, ": ", field_singularities(field).size(), " singularities");
  }
}

TEST_CASE("a field held to the corners' counts: a square corner in two quads leaves a valence-3 singularity inside") {
  // left to itself the field turns by the least angle at each corner: a square's
  // four corners in one quad each, no singularity. Asked for one corner in two
  // quads (a straight boundary's count), the field's crosses round it turn by a
  // quarter turn against the corner's, and the interior carries the quarter turn
  // Gauss-Bonnet leaves: 4 chi - sum (2 - q) = 4 - 3. (The corners (0, 0) and
  // (1, 1) lie in two triangles: the quarter turn goes in three steps of 30
  // degrees; in the one triangle at the other two it would be two steps of 45, a
  // tie either way.)
  const int n = 8;
  const TriangleSoup soup = test::grid(n);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<int> corners{0, n, n * (n + 1), n * (n + 1) + n};
  CrossFieldOptions options;
  options.length = 0.25;
  std::vector<Cone> cones;
  for (int v : corners) cones.push_back({v, 1});
  options.boundary_quads = quads_per_vertex(adjacency, cones);
  CHECK(field_singularities(smooth_cross_field(soup, adjacency, options)).empty());
  for (int turned : {corners[0], corners[3]}) {
    CAPTURE(turned);
    cones.clear();
    for (int v : corners) cones.push_back({v, v == turned ? 2 : 1});
    options.boundary_quads = quads_per_vertex(adjacency, cones);
    const SmoothCrossField field = smooth_cross_field(soup, adjacency, options);
    const std::vector<Cone> singular = field_singularities(field);
    REQUIRE(singular.size() == 1);
    CHECK(singular[0].quads == 3);
    CHECK(index_sum(field) == 1);
  }
}
