// The working triangulation of inputs far finer than the quads (forms/coarsen.h).
#include "io/read_surface.h"
#include "libquadmesh/forms/coarsen.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/topology/topology_report.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace qm;

namespace {

/// Every point of `coarse` is the input point its label names, at the same place.
void check_points_are_input_points(const TriangleSoup& coarse, const TriangleSoup& input) {
  REQUIRE(coarse.point_labels.size() == coarse.points.size());
  std::map<std::int64_t, int> index;
  for (int v = 0; v < static_cast<int>(input.points.size()); ++v) index[input.point_label(v)] = v;
  std::set<std::int64_t> labels;
  int misplaced = 0;
  for (std::size_t i = 0; i < coarse.points.size(); ++i) {
    const auto at = index.find(coarse.point_labels[i]);
    REQUIRE(at != index.end());
    misplaced += coarse.points[i] == input.points[static_cast<std::size_t>(at->second)] ? 0 : 1;
    labels.insert(coarse.point_labels[i]);
  }
  CHECK(misplaced == 0);
  CHECK(labels.size() == coarse.points.size());
}

long euler_characteristic(const TriangleSoup& soup) {
  std::set<std::pair<int, int>> edges;
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k) edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
  return static_cast<long>(soup.points.size()) - static_cast<long>(edges.size()) +
         static_cast<long>(soup.triangles.size());
}

double longest_edge(const TriangleSoup& soup) {
  double longest = 0;
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, (soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm());
  return longest;
}

/// The 2 x 1 rectangle on an n x n/2 grid, folded by 90 degrees along x = 1 (a crease).
TriangleSoup folded_strip(int n) {
  TriangleSoup s;
  const int m = n / 2;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = 2.0 * i / n, y = 1.0 * j / m;
      s.points.push_back(x <= 1 ? Vec3(x, y, 0) : Vec3(1, y, x - 1));
    }
  auto id = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

}  // namespace

TEST_CASE("coarsen: an annulus keeps its topology, its points and its orientation, with edges near the target") {
  const TriangleSoup input = test::annulus(1.0, 2.0, 40, 240);  // edges 0.025 to 0.05
  CoarsenOptions options;
  options.edge_length = 0.2;
  CoarsenReport report;
  const TriangleSoup coarse = coarsen(input, options, &report);
  CHECK(report.topology_kept);
  CHECK(report.collapses > 0);
  CHECK(coarse.triangles.size() * 8 < input.triangles.size());
  check_points_are_input_points(coarse, input);
  CHECK(euler_characteristic(coarse) == 0);
  CHECK(surface_adjacency(coarse).boundary_loops.size() == 2);
  CHECK(longest_edge(coarse) <= options.max_edge_factor * options.edge_length + 1e-12);
  double area = 0;
  for (const Triangle& t : coarse.triangles) {
    const Vec3 n = (coarse.points[t[1]] - coarse.points[t[0]]).cross(coarse.points[t[2]] - coarse.points[t[0]]);
    CHECK(n.z() > 0);
    area += 0.5 * n.z();
  }
  // the boundary polygons are inscribed in the circles: the area is within the
  // sagitta of 0.2-chords (area of the annulus 3 pi)
  CHECK(area == doctest::Approx(3 * M_PI).epsilon(0.01));
  CHECK(area < 3 * M_PI + 1e-9);
}

TEST_CASE("coarsen: corners of the boundary and a crease stay where they are") {
  SUBCASE("the L-shape's six corners") {
    const TriangleSoup input = test::l_shape(30);
    CoarsenOptions options;
    options.edge_length = 0.25;
    const TriangleSoup coarse = coarsen(input, options);
    CHECK(coarse.triangles.size() * 8 < input.triangles.size());
    const std::vector<Vec3> corners = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    for (const Vec3& c : corners)
      CHECK(std::any_of(coarse.points.begin(), coarse.points.end(), [&](const Vec3& p) { return (p - c).norm() < 1e-12; }));
    // the L's outline is kept exactly (area 3), every point of it within 1e-12 of the coarse one
    const HausdorffDistance d = two_sided_hausdorff(input.points, input.triangles, coarse.points, coarse.triangles);
    CHECK(d.value() < 1e-9);
  }
  SUBCASE("a strip folded by 90 degrees") {
    const TriangleSoup input = folded_strip(80);
    CoarsenOptions options;
    options.edge_length = 0.2;
    const TriangleSoup coarse = coarsen(input, options);
    CHECK(coarse.triangles.size() * 8 < input.triangles.size());
    check_points_are_input_points(coarse, input);
    // no triangle cuts across the crease: the surfaces coincide
    const HausdorffDistance d = two_sided_hausdorff(input.points, input.triangles, coarse.points, coarse.triangles);
    CHECK(d.value() < 1e-9);
  }
}

TEST_CASE("coarsen: bunny-open-large to a third of 1.5% of its diagonal" * doctest::description("shared mesh")) {
  const TriangleSoup input = analyze_topology(io::read_surface(test::shared_mesh("bunny-open-large.obj")).soup).soup;
  const double diagonal = bounding_box_diagonal(input.points, input.triangles);
  CoarsenOptions options;
  options.edge_length = 0.015 * diagonal / 3;
  CoarsenReport report;
  const TriangleSoup coarse = coarsen(input, options, &report);
  CHECK(report.topology_kept);
  MESSAGE(coarse.triangles.size(), " triangles of ", input.triangles.size(), " in ", report.passes, " passes");
  CHECK(coarse.triangles.size() * 3 < input.triangles.size());
  check_points_are_input_points(coarse, input);
  CHECK(euler_characteristic(coarse) == -3);  // MANIFEST.md
  CHECK(surface_adjacency(coarse).boundary_loops.size() == 5);
  // no collapse made an edge longer than the cap (the scan has a few longer ones of its own)
  CHECK(longest_edge(coarse) <= std::max(options.max_edge_factor * options.edge_length, longest_edge(input)));
  // inscribed: within a small fraction of the working edge of the scan everywhere
  // (0.13 with 10-degree normal turns; 0.28 with 20: the ears)
  const HausdorffDistance d = two_sided_hausdorff(input.points, input.triangles, coarse.points, coarse.triangles);
  MESSAGE("Hausdorff ", d.value() / options.edge_length, " x the working edge");
  CHECK(d.value() < 0.2 * options.edge_length);
}

