// The library's entry point (include/quadmesh/quadmesh.h): arrays in, quads or a
// typed qm::Error out, with the checks a tool would make.
#include "quadmesh/quadmesh.h"

#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

using namespace qm;

namespace {

/// The code and message of the qm::Error that meshing (points, triangles) throws.
std::pair<ErrorCode, std::string> error_of(const TriangleSoup& soup) {
  try {
    mesh_quads(soup.points, soup.triangles);
  } catch (const Error& e) {
    return {e.code(), e.what()};
  }
  FAIL("no qm::Error");
  return {};
}

}  // namespace

TEST_CASE("entry point: an annulus from arrays gives a grid of quads, one ring of forms on the double") {
  // quads 2% of the diagonal 4 sqrt 2: about 55 round the inner circle, whose
  // trapezoids' corners are 90 +- 3.3 degrees
  const TriangleSoup annulus = test::annulus(1.0, 2.0, 12, 96);
  QuadMeshOptions options;
  options.size_relative = 0.02;
  const QuadMeshResult r = mesh_quads(annulus.points, annulus.triangles, options);
  CHECK(r.doubled_genus == 1);
  REQUIRE(!r.quads.quads.empty());
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), &r.surface);
  CHECK(q.min_scaled_jacobian >= AcceptanceCriteria{}.min_scaled_jacobian);
  CHECK(q.angle_dev_mean <= AcceptanceCriteria{}.max_mean_angle_deviation_deg);
  CHECK(q.inverted == 0);
  // chi 0 and no corner: the grid has no singular vertex at all
  CHECK(q.irregular_interior == 0);
}

TEST_CASE("entry point: surfaces the method does not apply to are a typed error, not a crash") {
  CHECK(error_of(test::disk(4, 16)).first == ErrorCode::unsupported);
  CHECK(error_of(test::sphere()).first == ErrorCode::unsupported);
  CHECK(error_of(test::two_components()).first == ErrorCode::unsupported);
  CHECK(error_of(test::bow_tie()).first == ErrorCode::bad_input);
}

TEST_CASE("entry point: indices out of range and non-finite points are named") {
  TriangleSoup soup = test::annulus(1.0, 2.0, 2, 12);
  const int n = static_cast<int>(soup.points.size());
  soup.triangles[5][1] = n;
  auto [code, message] = error_of(soup);
  CHECK(code == ErrorCode::bad_input);
  CHECK(message.find("triangle 5") != std::string::npos);
  CHECK(message.find("vertex " + std::to_string(n) + " is not one of the " + std::to_string(n) + " points") !=
        std::string::npos);
  soup.triangles[5][1] = -1;
  CHECK(error_of(soup).first == ErrorCode::bad_input);

  soup = test::annulus(1.0, 2.0, 2, 12);
  soup.points[3].y() = std::numeric_limits<double>::quiet_NaN();
  std::tie(code, message) = error_of(soup);
  CHECK(code == ErrorCode::bad_input);
  CHECK(message.find("vertex 3") != std::string::npos);
}

TEST_CASE("entry point: a size implying more quads than max_quads is refused before any work") {
  const TriangleSoup annulus = test::annulus(1.0, 2.0, 2, 12);
  QuadMeshOptions options;
  options.size_relative = 1e-9;
  // the 12-gons' areas 12 - 3 = 9 over (1e-9 x the diagonal 4 sqrt 2)^2: 2.8e17 quads
  const double size = 1e-9 * 4 * std::sqrt(2.0);
  CHECK(implied_quad_count(annulus, options) == doctest::Approx(9 / (size * size)).epsilon(1e-9));
  try {
    mesh_quads(annulus.points, annulus.triangles, options);
    FAIL("no qm::Error");
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::bad_input);
    CHECK(e.option() == "QuadMeshOptions::max_quads");
    CHECK(std::string(e.what()).find("more than QuadMeshOptions::max_quads 5000000") != std::string::npos);
  }
  options.max_quads = 0;  // no limit: the count is still what it is
  options.size_relative = 0.05;
  CHECK(implied_quad_count(annulus, options) < 2000);
}
