// Fillets as corners (cones/fillet_corners.h): rounded corners a few quads in
// radius, between straight edges, and nothing on a hole's circle, a slot's end or
// a sharp corner.
#include "io/read_surface.h"
#include "libquadmesh/cones/boundary_corners.h"
#include "libquadmesh/cones/fillet_corners.h"
#include "libquadmesh/topology/topology_report.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

TriangleSoup example_surface(const std::string& name, double quad_size_relative) {
  io::ReadOptions read;
  read.quad_size_relative = quad_size_relative;
  return analyze_topology(io::read_surface(test::example(name), read).soup).soup;
}

}  // namespace

TEST_CASE(
    "a plate's four fillets of 2.9 quads' radius are fillet corners; its slot's ends and holes are "
    "not") {
  // examples/parts/slotted-plate.geo: 160 x 90, fillets of radius 8 centred 8 in
  // from each corner, a slot with round ends of radius 8, two holes of radius 5
  const TriangleSoup plate = example_surface("parts/slotted-plate.geo", 0.015);
  const double size = 0.015 * std::hypot(160.0, 90.0);  // 2.75: the fillets 2.9 quads in radius
  CHECK(boundary_corners(plate, corner_window_quads * size).empty());
  const std::vector<BoundaryCorner> fillets = fillet_corners(plate, size);
  REQUIRE(fillets.size() == 4);
  const Vec3 centres[] = {{8, 8, 0}, {152, 8, 0}, {8, 82, 0}, {152, 82, 0}};
  for (const BoundaryCorner& f : fillets) {
    // convex, near 90 degrees (the turn within the window is most of the arc's)
    CHECK(f.angle_deg > 80);
    CHECK(f.angle_deg < 100);
    // on a fillet's arc, at its middle (the diagonal from the centre)
    const Vec3& p = plate.points[static_cast<std::size_t>(f.vertex)];
    double nearest = 1e9;
    Vec3 offset;
    for (const Vec3& c : centres)
      if ((p - c).norm() < nearest) {
        nearest = (p - c).norm();
        offset = p - c;
      }
    CHECK(nearest == doctest::Approx(8).epsilon(0.01));
    CHECK(std::abs(std::abs(offset.x()) - std::abs(offset.y())) < 2.0);
  }
  // larger than the window can hold (6.9 quads' radius): no fillet corner
  CHECK(fillet_corners(plate, size / 2.4).empty());
  // a quad the fillet's radius: still no corner at the quad scale (its turn is
  // spread), still the same four fillet corners
  CHECK(boundary_corners(plate, corner_window_quads * 8.0).empty());
  CHECK(fillet_corners(plate, 8.0).size() == 4);
}

TEST_CASE("a plate with sharp corners and round holes has no fillet corner") {
  // examples/plate-two-holes.geo: 100 x 60, holes of radius 10 (5.9 quads)
  const TriangleSoup plate = example_surface("plate-two-holes.geo", 0.015);
  CHECK(fillet_corners(plate, 0.015 * std::hypot(100.0, 60.0)).empty());
}

TEST_CASE(
    "an L-plate's concave inner fillet is a fillet corner of about 270 degrees; its sharp corners "
    "block none") {
  // arms 40 wide, 120 and 100 long, the inner corner rounded to 6 (2.6 quads at
  // 1.5% of the diagonal), the outer corners sharp
  const std::string geo = R"(SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 120, 40};
Rectangle(2) = {0, 0, 0, 40, 100};
Rectangle(3) = {40, 40, 0, 6, 6};
Disk(4) = {46, 46, 0, 6, 6};
BooleanDifference(5) = { Surface{3}; Delete; }{ Surface{4}; Delete; };
BooleanUnion(6) = { Surface{1}; Delete; }{ Surface{2, 5}; Delete; };
)";
  io::ReadOptions read;
  read.quad_size_relative = 0.015;
  const std::string path =
      test::write_text(test::scratch_dir("fillet_corners_l_plate"), "l.geo", geo);
  const TriangleSoup plate = analyze_topology(io::read_surface(path, read).soup).soup;
  const double size = 0.015 * std::hypot(120.0, 100.0);
  CHECK(boundary_corners(plate, corner_window_quads * size).size() == 5);  // the outer corners
  const std::vector<BoundaryCorner> fillets = fillet_corners(plate, size);
  REQUIRE(fillets.size() == 1);
  CHECK(fillets[0].angle_deg > 260);
  CHECK(fillets[0].angle_deg < 280);
  // on the arc's middle: 6 from its centre (46, 46), on the diagonal
  const Vec3& p = plate.points[static_cast<std::size_t>(fillets[0].vertex)];
  CHECK((p - Vec3(46, 46, 0)).norm() == doctest::Approx(6).epsilon(0.01));
  CHECK(std::abs(p.x() - p.y()) < 1.5);
}
