// The winding of a map round its cones (cone_winding.h): the signed sum of the
// corner angles at a cone, against the quarter turns it is meant to have.
#include "libquadmesh/cones/cone_winding.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

/// A fan of six triangles round vertex 0 (ring vertices 1..6 on the unit circle
/// in 3D, the ring closed), with vertex 0 inside.
TriangleSoup fan() {
  TriangleSoup soup;
  soup.points.push_back(Vec3(0, 0, 0));
  for (int k = 0; k < 6; ++k)
    soup.points.push_back(Vec3(std::cos(k * M_PI / 3), std::sin(k * M_PI / 3), 0));
  for (int k = 0; k < 6; ++k)
    soup.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
  return soup;
}

/// A map of the fan whose triangle k spans angles[k] at the centre (negative:
/// turned over), each triangle in its own chart.
FaceMap fan_map(const std::array<double, 6>& angles) {
  FaceMap map;
  double at = 0;
  for (double a : angles) {
    map.corners.push_back({Complex(0, 0), std::polar(1.0, at), std::polar(1.0, at + a)});
    at += a;
  }
  return map;
}

}  // namespace

TEST_CASE(
    "cone winding: a valence-5 cone whose star winds a full turn short is found by its signed "
    "angle") {
  const TriangleSoup soup = fan();
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  REQUIRE(!adjacency.boundary_vertex[0]);
  std::vector<int> quads(soup.points.size(), 2);  // the ring is the boundary
  quads[0] = 5;
  // five quarter turns round the centre, in six positive triangles: as meant
  const double fifth = 5 * M_PI / 2 / 6;
  CHECK(misturned_cones(soup, adjacency, fan_map({fifth, fifth, fifth, fifth, fifth, fifth}), quads)
            .empty());
  // one quarter turn: the star a full turn short
  const double short_sixth = M_PI / 2 / 6;
  const std::vector<int> short_star = misturned_cones(
      soup, adjacency,
      fan_map({short_sixth, short_sixth, short_sixth, short_sixth, short_sixth, short_sixth}),
      quads);
  CHECK(short_star == std::vector<int>{0});
  // a triangle folded nearly flat across the cone: the corners' angles taken
  // positive would add up to 2.3 pi, near the 2.5 pi meant; signed, to pi/2
  const double a = 0.28 * M_PI;
  CHECK(misturned_cones(soup, adjacency, fan_map({a, a, a, a, a, -0.9 * M_PI}), quads) ==
        std::vector<int>{0});
  // a regular vertex is never a misturned cone, however its star is folded
  quads[0] = 4;
  CHECK(misturned_cones(soup, adjacency, fan_map({a, a, a, a, a, -0.9 * M_PI}), quads).empty());
}
