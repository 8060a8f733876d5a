// Acute corners' singular scale left out near the tip (tip_scale.h): on a flat
// sector whose metric is the tip's k log(d / R) exactly, the sizes' scale is that
// metric raised to its mean on the rim within the reach, and nothing beyond it.
#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/cones/tip_scale.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>

using namespace qm;

namespace {

/// A flat sector of angle `alpha` at the origin (test::sector): rings 1..rings at
/// radius i, each of sectors + 1 points; the tip is vertex 0.
TriangleSoup sector(double alpha, int rings, int sectors) { return test::sector(alpha, rings, sectors, rings); }

/// The sector's targets: its own curvature everywhere but at the tip, asked in
/// one quad (a quarter turn).
std::vector<double> one_quad_tip(const std::vector<double>& curvature) {
  std::vector<double> target = curvature;
  target[0] = M_PI / 2;
  return target;
}

/// The tip's metric k log(d / radius), d the distance from the origin (half a
/// ring at the tip).
Eigen::VectorXd tip_metric(const TriangleSoup& soup, double k, double radius) {
  Eigen::VectorXd u(static_cast<Eigen::Index>(soup.points.size()));
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    u[static_cast<Eigen::Index>(v)] = k * std::log(std::max(0.5, soup.points[v].norm()) / radius);
  return u;
}

/// The mean of u over the vertices at a distance in [from, to) from the origin.
double mean_between(const TriangleSoup& soup, const Eigen::VectorXd& u, double from, double to) {
  double sum = 0;
  int count = 0;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    const double d = soup.points[v].norm();
    if (d >= from - 1e-9 && d < to - 1e-9) {
      sum += u[static_cast<Eigen::Index>(v)];
      ++count;
    }
  }
  return sum / count;
}

/// tip_scale_offset at the acute tips found for quads of `size`.
Eigen::VectorXd offset_near_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<double>& target, const std::vector<double>& curvature,
                                 const Eigen::VectorXd& u, double size) {
  return tip_scale_offset(soup, adjacency, acute_tips(soup, adjacency, target, curvature, size), u);
}

}  // namespace

TEST_CASE("an acute tip's singular scale is left out within the reach: the sizes there are the rim's") {
  // a 45-degree tip in one quad: k = 90 / 45 - 1 = 1; the reach 20.5 rings of 40
  // (its rim, the last fifth: rings 17 to 20)
  const TriangleSoup soup = sector(M_PI / 4, 40, 6);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  REQUIRE(curvature[0] == doctest::Approx(3 * M_PI / 4));
  const double radius = 20.5, size = radius / tip_radius_quads;
  const Eigen::VectorXd u = tip_metric(soup, 1.0, radius);
  const Eigen::VectorXd offset = offset_near_tips(soup, adjacency, one_quad_tip(curvature), curvature, u, size);
  const double rim = mean_between(soup, u, 0.8 * radius, radius);
  double worst = 0;
  for (std::size_t v = 1; v < soup.points.size(); ++v) {
    const auto e = static_cast<Eigen::Index>(v);
    const double d = soup.points[v].norm();
    if (d < radius - 1e-9)
      worst = std::max(worst, std::abs(u[e] + offset[e] - std::max(u[e], rim)));
    else
      worst = std::max(worst, std::abs(offset[e]));
  }
  CHECK(worst < 1e-12);
  CHECK(u[0] + offset[0] == doctest::Approx(rim));  // the tip: its neighbours' mean, lifted
  // the sizes near the tip lifted from e^-3 (ring 1) to the rim's
  CHECK(u[1] + offset[1] == doctest::Approx(rim));
  CHECK(rim < 0);
  CHECK(u[1] < rim - 2.5);
  // no size, nothing
  CHECK(offset_near_tips(soup, adjacency, one_quad_tip(curvature), curvature, u, 0).cwiseAbs().maxCoeff() == 0);
}

TEST_CASE("a corner near its quads' angle is not a tip; a turn of the boundary near the tip ends the reach, and "
          "within two quads, the tip is none") {
  // 70 degrees in one quad: k = 0.29, below the 0.4 a tip has
  const TriangleSoup wide = sector(70 * M_PI / 180, 30, 6);
  const SurfaceAdjacency wide_adjacency = surface_adjacency(wide);
  const std::vector<double> wide_curvature = vertex_curvature(wide, wide_adjacency);
  const Eigen::VectorXd offset_wide = offset_near_tips(wide, wide_adjacency, one_quad_tip(wide_curvature),
                                                       wide_curvature, tip_metric(wide, 0.29, 20), 20 / tip_radius_quads);
  CHECK(offset_wide.cwiseAbs().maxCoeff() == 0);
  // 60 degrees (k = 0.5) is a tip
  const TriangleSoup sixty = sector(M_PI / 3, 30, 6);
  const SurfaceAdjacency sixty_adjacency = surface_adjacency(sixty);
  const std::vector<double> sixty_curvature = vertex_curvature(sixty, sixty_adjacency);
  CHECK(offset_near_tips(sixty, sixty_adjacency, one_quad_tip(sixty_curvature), sixty_curvature,
                         tip_metric(sixty, 0.5, 20), 20 / tip_radius_quads)
            .maxCoeff() > 0);
  // the 45-degree sector with a side vertex 11 rings out asked to turn by a third
  // of the tip's excess (pi / 4) more than it does: the reach ends there (its rim:
  // rings 9 and 10)
  const TriangleSoup soup = sector(M_PI / 4, 40, 6);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  std::vector<double> target = one_quad_tip(curvature);
  const int turned = 1 + 10 * 7;  // ring 11, ray 0
  REQUIRE(soup.points[static_cast<std::size_t>(turned)].x() == doctest::Approx(11));
  target[static_cast<std::size_t>(turned)] += M_PI / 12;
  const Eigen::VectorXd u = tip_metric(soup, 1.0, 20);
  const double size = 20 / tip_radius_quads;  // a reach of 11 is 6.6 quads
  const Eigen::VectorXd offset = offset_near_tips(soup, adjacency, target, curvature, u, size);
  const double rim = mean_between(soup, u, 8.8, 11);
  double beyond = 0, within = 0;
  for (std::size_t v = 1; v < soup.points.size(); ++v) {
    const auto e = static_cast<Eigen::Index>(v);
    if (soup.points[v].norm() >= 11 - 1e-9)
      beyond = std::max(beyond, std::abs(offset[e]));
    else
      within = std::max(within, std::abs(u[e] + offset[e] - std::max(u[e], rim)));
  }
  CHECK(beyond == 0);
  CHECK(within < 1e-12);
  // a quarter of the excess or less does not
  target[static_cast<std::size_t>(turned)] = curvature[static_cast<std::size_t>(turned)] + M_PI / 20;
  const Eigen::VectorXd farther = offset_near_tips(soup, adjacency, target, curvature, u, size);
  CHECK(farther[static_cast<Eigen::Index>(1 + 14 * 7)] > 0);  // ring 15
  // a turn 11 rings out is under two quads of 6 rings: the tip is left as it is
  target[static_cast<std::size_t>(turned)] += M_PI / 12;
  CHECK(offset_near_tips(soup, adjacency, target, curvature, u, 6).cwiseAbs().maxCoeff() == 0);
  CHECK(offset_near_tips(soup, adjacency, target, curvature, u, 5).maxCoeff() > 0);
}
