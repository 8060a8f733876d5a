// A protrusion's cap (cones/protrusion_caps.h): the quarter turns a capped tube
// lacks, from the discrete Gauss-Bonnet theorem.
#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/protrusion_caps.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

constexpr int sectors = 24;
constexpr int tube_rings = 8;  ///< rings of the tube, z = 0 ... 4 (z = 0 the boundary)
constexpr int cap_rings = 6;   ///< rings of the hemisphere above z = 4, then the apex

/// A tube of radius 1 along z from z = 0 (its open end, the boundary) to z = 4,
/// closed by a hemisphere up to z = 5 (a disk: chi 1). The tube's vertices are
/// flat (four right angles each: its strips are planar rectangles), so all of the
/// curvature, 2 pi by Gauss-Bonnet with a straight boundary, lies at z >= 4. The
/// apex is the last point.
TriangleSoup capped_tube() {
  TriangleSoup soup;
  std::vector<std::pair<double, double>> rings;  // (radius, z) per ring, bottom up
  for (int i = 0; i <= tube_rings; ++i) rings.push_back({1.0, 4.0 * i / tube_rings});
  for (int i = 1; i < cap_rings; ++i) {
    const double a = 0.5 * M_PI * i / cap_rings;
    rings.push_back({std::cos(a), 4.0 + std::sin(a)});
  }
  for (const auto& [r, z] : rings)
    for (int s = 0; s < sectors; ++s) {
      const double t = 2 * M_PI * s / sectors;
      soup.points.push_back({r * std::cos(t), r * std::sin(t), z});
    }
  soup.points.push_back({0, 0, 5});
  const auto at = [](int ring, int s) { return ring * sectors + (s % sectors); };
  for (int ring = 0; ring + 1 < static_cast<int>(rings.size()); ++ring)
    for (int s = 0; s < sectors; ++s) {
      soup.triangles.push_back({at(ring, s), at(ring, s + 1), at(ring + 1, s + 1)});
      soup.triangles.push_back({at(ring, s), at(ring + 1, s + 1), at(ring + 1, s)});
    }
  const int apex = static_cast<int>(soup.points.size()) - 1;
  const int top = static_cast<int>(rings.size()) - 1;
  for (int s = 0; s < sectors; ++s) soup.triangles.push_back({at(top, s), at(top, s + 1), apex});
  return soup;
}

}  // namespace

TEST_CASE("a capped tube lacks four quarter turns in its cap, three with a valence-3 cone at the tip") {
  const TriangleSoup soup = capped_tube();
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  REQUIRE(adjacency.boundary_loops.size() == 1);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  // u falling towards the tip, as the cone metric's does along a protrusion
  Eigen::VectorXd u(static_cast<Eigen::Index>(soup.points.size()));
  for (std::size_t v = 0; v < soup.points.size(); ++v) u[static_cast<Eigen::Index>(v)] = -soup.points[v].z();
  const int apex = static_cast<int>(soup.points.size()) - 1;

  // the region above z = 3: the upper quarter of the tube and the cap, the tip first
  const std::vector<int> region = sublevel_region(soup, adjacency, u, apex, -3.0);
  REQUIRE(!region.empty());
  CHECK(region.front() == apex);
  const auto above = static_cast<std::size_t>(
      std::count_if(soup.points.begin(), soup.points.end(), [](const Vec3& p) { return p.z() > 3.0; }));
  CHECK(region.size() == above);

  // 2 pi of curvature, no cone: four quarter turns (the sum is exact up to rounding)
  double sum = 0;
  for (int v : region) sum += curvature[static_cast<std::size_t>(v)];
  CHECK(sum == doctest::Approx(2 * M_PI).epsilon(1e-9));
  CHECK(cap_quarter_turns(soup, adjacency, curvature, u, -3.0, apex, {}) == 4);
  // a valence-3 cone at the tip takes one of them
  CHECK(cap_quarter_turns(soup, adjacency, curvature, u, -3.0, apex, {Cone{apex, 3}}) == 3);
  // and a valence-5 one in the region gives one back
  const int side = (tube_rings + 2) * sectors;  // a point of the cap's second ring
  CHECK(cap_quarter_turns(soup, adjacency, curvature, u, -3.0, apex, {Cone{apex, 3}, Cone{side, 5}}) == 4);
  // a region down to the open end is an arm's end, not a cap
  CHECK(cap_quarter_turns(soup, adjacency, curvature, u, 0.5, apex, {}) == 0);
}
