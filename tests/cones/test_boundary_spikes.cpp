// Boundary spikes finer than a quad (boundary_spikes.h): a thin triangle hung on a
// square's edge is clipped; a sharp corner of a wedge, a corner at the quad scale,
// is not; nor is a spike longer than a quad.
#include "libquadmesh/cones/boundary_spikes.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

/// `s` with a spike hung below its bottom edge between x = 0.4 and 0.5: its tip
/// `depth` below the edge's midpoint.
TriangleSoup with_spike(TriangleSoup s, double depth) {
  const int tip = static_cast<int>(s.points.size());
  s.points.push_back(Vec3(0.45, -depth, 0));
  s.triangles.push_back({44, tip, 55});  // points 44 and 55: (0.4, 0) and (0.5, 0) of test::grid(10)
  return s;
}

}  // namespace

TEST_CASE("a spike shorter than a quad is clipped; the square it hangs on stays whole") {
  // the tip's angle 2 atan(0.05 / 0.2) = 28 degrees, its edges 0.21 long; quads of 0.5
  TriangleSoup s = with_spike(test::grid(10), 0.2);
  REQUIRE(std::abs(corner_angle(s, s.triangles.size() - 1, 1) * 180 / M_PI - 28.07) < 0.01);
  CHECK(clip_boundary_spikes(s, 0.5) == 1);
  CHECK(s.points.size() == 121);
  CHECK(s.triangles.size() == 200);
  for (const Vec3& p : s.points) CHECK(p.y() >= 0);
  CHECK(surface_adjacency(s).boundary_loops.size() == 1);
  // longer than a quad (quads of 0.2: edges of 0.21), or blunter than 60 degrees
  // (depth 0.05: 90 degrees), it stays
  TriangleSoup long_spike = with_spike(test::grid(10), 0.2);
  CHECK(clip_boundary_spikes(long_spike, 0.2) == 0);
  TriangleSoup blunt = with_spike(test::grid(10), 0.05);
  CHECK(clip_boundary_spikes(blunt, 0.5) == 0);
  CHECK(blunt.points.size() == 122);
}

TEST_CASE("a wedge's 30-degree tip is a corner at the quad scale and stays") {
  // a strip between the rays at 0 and 30 degrees, points 0.05 apart along each:
  // the tip (the origin) in one triangle with edges of 0.05, quads of 0.5
  TriangleSoup wedge;
  wedge.points.push_back(Vec3::Zero());
  const double a = M_PI / 6;
  for (int i = 1; i <= 20; ++i) {
    wedge.points.push_back(Vec3(0.05 * i, 0, 0));
    wedge.points.push_back(Vec3(0.05 * i * std::cos(a), 0.05 * i * std::sin(a), 0));
  }
  wedge.triangles.push_back({0, 1, 2});
  for (int i = 1; i < 20; ++i) {
    const int p = 2 * i - 1, q = 2 * i, p2 = 2 * i + 1, q2 = 2 * i + 2;
    wedge.triangles.push_back({p, p2, q2});
    wedge.triangles.push_back({p, q2, q});
  }
  CHECK(clip_boundary_spikes(wedge, 0.5) == 0);
  CHECK(wedge.triangles.size() == 39);
}
