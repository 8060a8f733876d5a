// Boundary tips (param/boundary_tips.h): the leading coefficient of a symmetric
// form's expansion at a tip, recovered from analytic forms; and the zero it buys on
// a CAD plate whose hole has a 16-degree corner.
#include "io/read_surface.h"
#include "libquadmesh/param/boundary_tips.h"
#include "libquadmesh/pipeline/acceptance_criteria.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/topology/topology_report.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>

using namespace qm;

namespace {

/// The face map of F(z) at every corner, z = w^a with w the flattened position
/// (polar angle theta j / sectors of ring index j, distance r): z = r^a e^(i a t).
FaceMap face_map(const TriangleSoup& s, double theta, int sectors, double a,
                 const std::function<Complex(Complex)>& F) {
  FaceMap m;
  for (const Triangle& t : s.triangles) {
    CornerValues c;
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = static_cast<std::size_t>(t[k]);
      const int j = t[k] == 0 ? 0 : (t[k] - 1) % (sectors + 1);
      c[k] = F(t[k] == 0 ? Complex(0) : std::polar(std::pow(s.points[v].norm(), a), a * theta * j / sectors));
    }
    m.corners.push_back(c);
  }
  return m;
}

}  // namespace

TEST_CASE("tip_leading_coefficient recovers f_0 of h = sum f_n z^n dz, z = w^(pi / theta)") {
  for (const double degrees : {300.0, 330.0, 350.0}) {
    CAPTURE(degrees);
    const double theta = degrees * M_PI / 180;
    const int sectors = 7;
    const TriangleSoup s = test::sector(theta, 3, sectors);
    const SurfaceAdjacency adjacency = surface_adjacency(s);
    const std::vector<BoundaryTip> tips = boundary_tips(s, adjacency, 250 * M_PI / 180);
    REQUIRE(tips.size() == 1);
    CHECK(tips[0].vertex == 0);
    const VertexRing ring = vertex_ring(s, adjacency, 0);
    const double measured = tips[0].angle;
    CHECK(measured == doctest::Approx(theta));
    const double a = M_PI / measured;
    // f_0 = 1, f_1 = 0, f_2 = 0; then 0, 1, 0; 0, 0, 1; two mixes
    const std::vector<FaceMap> basis = {
        face_map(s, measured, sectors, a, [](Complex z) { return z; }),
        face_map(s, measured, sectors, a, [](Complex z) { return z * z / 2.0; }),
        face_map(s, measured, sectors, a, [](Complex z) { return z * z * z / 3.0; }),
        face_map(s, measured, sectors, a, [](Complex z) { return -0.7 * z + 2.5 * z * z / 2.0; }),
        face_map(s, measured, sectors, a, [](Complex z) { return z + 2.0 * z * z * z * z / 4.0; }),
    };
    const Eigen::RowVectorXd row = tip_leading_coefficient(s, adjacency, basis, 0);
    REQUIRE(row.size() == 5);
    // exact for the three terms fitted; a fourth term, not fitted, moves f_0 a little
    CHECK(row[0] == doctest::Approx(1.0).epsilon(1e-9));
    CHECK(std::abs(row[1]) < 1e-9);
    CHECK(std::abs(row[2]) < 1e-9);
    CHECK(row[3] == doctest::Approx(-0.7).epsilon(1e-9));
    CHECK(row[4] == doctest::Approx(1.0).epsilon(0.05));
    // one tip per loop, the widest: at 170 degrees the vertices along the straight
    // sides (180 degrees) qualify too
    const std::vector<BoundaryTip> one = boundary_tips(s, adjacency, 170 * M_PI / 180);
    REQUIRE(one.size() == 1);
    CHECK(one[0].vertex == 0);
    CHECK(ring.boundary);
  }
}

TEST_CASE("a plate whose hole has a 16-degree corner: a zero at the tip, four quads round it" *
          doctest::test_suite("slow")) {
  // examples/plate-v-hole.geo: 100 x 60 with a round hole and a triangular one
  // whose sharpest corner (at (50, 30)) is 16.3 degrees: the plate turns 343.7
  // degrees round it
  const std::string geo = test::example("plate-v-hole.geo");
  io::ReadOptions read;
  read.quad_size_relative = 0.015;
  const TriangleSoup input = analyze_topology(io::read_surface(geo, read).soup).soup;
  auto quads_at_tip = [](const QuadMeshResult& r) {
    int count = 0;
    for (const auto& quad : r.quads.quads)
      for (int v : quad)
        if ((r.quads.points[static_cast<std::size_t>(v)] - Vec3(50, 30, 0)).norm() < 1e-9) ++count;
    return count;
  };
  QuadMeshOptions options;
  options.singularities = Singularities::abel;  // the differential's own zero at the tip
  options.size_relative = 0.015;
  const QuadMeshResult tipped = mesh_quads(input, options);
  CHECK(tipped.boundary_tips == 1);
  const QuadQuality q = quad_quality(polygon_mesh(tipped.quads), &input);
  CHECK(q.inverted == 0);
  CHECK(q.euler_characteristic == -1);
  CHECK(q.boundary_loops == 3);
  CHECK(quads_at_tip(tipped) >= 4);
  CHECK(q.min_scaled_jacobian >= 0.5);
  // without the tip's zero two quads share 343.7 degrees there
  options.tip_angle_deg = 720;
  const QuadMeshResult plain = mesh_quads(input, options);
  CHECK(plain.boundary_tips == 0);
  CHECK(quads_at_tip(plain) == 2);
  CHECK(quad_quality(polygon_mesh(plain.quads), &input).min_scaled_jacobian < AcceptanceCriteria{}.min_scaled_jacobian);
}
