// The map sheared at an acute tip (tip_shear.h): on a flat 30-degree sector whose
// field is the conformal opening z = w^3 (it turns by 60 degrees across the tip),
// the fit's target near the tip takes the tip's two edges to the two lattice
// axes at the frame's scale, and is the frame itself beyond the shear's reach.
#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/cones/tip_shear.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

/// The centroid of triangle f (3D).
Vec3 centroid(const TriangleSoup& soup, std::size_t f) {
  Vec3 c = Vec3::Zero();
  for (int v : soup.triangles[f]) c += soup.points[static_cast<std::size_t>(v)] / 3.0;
  return c;
}

/// A direction in the xy-plane (complex) in triangle f's local frame (the soup is planar).
Complex planar_direction(const TriangleSoup& soup, std::size_t f, Complex direction) {
  const Triangle& t = soup.triangles[f];
  const Vec3 a = soup.points[static_cast<std::size_t>(t[1])] - soup.points[static_cast<std::size_t>(t[0])];
  // the local real axis is a; the soup is counter-clockwise in the xy-plane
  const Complex axis(a.x(), a.y());
  return direction * std::abs(axis) / axis;
}

}  // namespace

TEST_CASE("an acute tip's fit is the shear that takes its edges to the lattice axes, within its reach only") {
  // a 30-degree sector of radius 20 (20 rings), its tip (vertex 0) asked in one quad
  const double alpha = M_PI / 6, size = 2.0;
  const TriangleSoup soup = test::sector(alpha, 20, 6, 20.0);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  std::vector<double> target = curvature;
  target[0] = M_PI / 2;
  const std::vector<AcuteTip> tips = acute_tips(soup, adjacency, target, curvature, size);
  REQUIRE(tips.size() == 1);
  CHECK(tips[0].vertex == 0);
  CHECK(tips[0].exponent == doctest::Approx(2.0));
  // the field of z = w^3: at polar angle phi, the real axis pulled back is at -2 phi
  CrossField field;
  field.angle.resize(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Vec3 c = centroid(soup, f);
    const double phi = std::atan2(c.y(), c.x());
    field.angle[f] = std::arg(planar_direction(soup, f, std::polar(1.0, -2 * phi)));
  }
  const FitShape shape = tip_shear(soup, adjacency, tips, field, size);
  const double reach = shear_radius_quads * size;
  const Complex i(0, 1);
  int full = 0, none = 0, faded = 0;
  double worst = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Complex a = shape.conformal[f], b = shape.anticonformal[f];
    const double far = centroid(soup, f).norm();
    if (far > reach + 1.5) {  // every corner beyond the reach: the frame itself
      CHECK(a == Complex(1, 0));
      CHECK(b == Complex(0, 0));
      ++none;
      continue;
    }
    const Complex frame = std::polar(1.0, -field.angle[f]);
    const Complex t1 = planar_direction(soup, f, 1.0), t2 = planar_direction(soup, f, std::polar(1.0, alpha));
    if (far < full_shear_share * reach - 1.5) {
      // the first edge to the real axis, the second to the imaginary one, at the scale
      worst = std::max({worst, std::abs(frame * (a * t1 + b * std::conj(t1)) - 1.0),
                        std::abs(frame * (a * t2 + b * std::conj(t2)) - i)});
      ++full;
    } else if (b != Complex(0, 0)) {
      ++faded;
    }
    // orientation kept: the affine map's determinant |a|^2 - |b|^2 is positive
    CHECK(std::norm(a) - std::norm(b) > 0);
  }
  CHECK(worst < 1e-12);
  CHECK(full >= 6);
  CHECK(faded > 0);
  CHECK(none > 50);
  // the shear's own size: a 30-degree wedge opened to a right angle doubles areas
  // (1 / sin 30 degrees)
  const std::size_t f0 = 0;
  CHECK(std::norm(shape.conformal[f0]) - std::norm(shape.anticonformal[f0]) == doctest::Approx(2.0));
}

TEST_CASE("a right-angle corner asked in one quad is no tip; a 30-degree one is") {
  const TriangleSoup soup = test::sector(M_PI / 2, 10, 6, 10.0);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  std::vector<double> target = curvature;
  target[0] = M_PI / 2;
  CHECK(acute_tips(soup, adjacency, target, curvature, 1.0).empty());
  const TriangleSoup narrow = test::sector(M_PI / 6, 10, 6, 10.0);
  const SurfaceAdjacency narrow_adjacency = surface_adjacency(narrow);
  const std::vector<double> narrow_curvature = vertex_curvature(narrow, narrow_adjacency);
  std::vector<double> narrow_target = narrow_curvature;
  narrow_target[0] = M_PI / 2;
  const std::vector<AcuteTip> tips = acute_tips(narrow, narrow_adjacency, narrow_target, narrow_curvature, 1.0);
  REQUIRE(tips.size() == 1);
  CHECK(tips[0].reach == doctest::Approx(tip_radius_quads));
}
