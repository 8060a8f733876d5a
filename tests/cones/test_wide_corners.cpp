// Corners the cone metric opens too wide (cones/wide_corners.h): a valence-5 cone
// at a point beside an edge, as at the midpoint of a split edge (pig).
#include "libquadmesh/cones/cone_map.h"
#include "libquadmesh/cones/wide_corners.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>

using namespace qm;

namespace {

constexpr int n = 8;

int grid_point(int i, int j) { return i * (n + 1) + j; }

/// The widest opened corner at a cone (radians).
double widest_cone_corner(const TriangleSoup& soup, const std::vector<Cone>& cones) {
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<int> quads = quads_per_vertex(adjacency, cones);
  const std::vector<double> opened = opened_corners(soup, quads);
  double widest = 0;
  for (const Cone& c : cones)
    for (std::size_t corner = 0; corner < opened.size(); ++corner)
      if (soup.triangles[corner / 3][corner % 3] == c.vertex) widest = std::max(widest, opened[corner]);
  return widest;
}

}  // namespace

TEST_CASE("a valence-5 cone beside a grid diagonal gets its wide corner bisected") {
  // a unit square in 8 x 8 cells, a point put in the cell triangle (4, 4), (5, 4),
  // (5, 5) a fiftieth of a cell below its diagonal: its corner facing the diagonal
  // is 177.7 degrees, and a valence-5 cone there opens it to 222
  TriangleSoup soup = test::grid(n);
  const auto cell = std::find(soup.triangles.begin(), soup.triangles.end(),
                              Triangle{grid_point(4, 4), grid_point(5, 4), grid_point(5, 5)});
  REQUIRE(cell != soup.triangles.end());
  const int m = static_cast<int>(soup.points.size());
  soup.points.emplace_back(4.5 / n, 4.48 / n, 0.0);
  const Triangle t = *cell;
  *cell = {t[0], t[1], m};
  soup.triangles.push_back({t[1], t[2], m});
  soup.triangles.push_back({t[2], t[0], m});
  std::vector<Cone> cones{{grid_point(0, 0), 1}, {grid_point(n, 0), 1}, {grid_point(n, n), 1},
                          {grid_point(0, n), 1}, {m, 5},                {grid_point(2, 6), 3}};
  CHECK(widest_cone_corner(soup, cones) * 180 / M_PI == doctest::Approx(177.71 * 1.25).epsilon(1e-3));

  const TriangleSoup before = soup;
  const WideCornerSplits result = split_wide_corners(soup, cones);
  const std::size_t splits = result.splits;
  CHECK(splits >= 1);
  // the adjacency handed back is the split soup's
  const SurfaceAdjacency fresh = surface_adjacency(soup);
  CHECK(result.adjacency.vertex_faces == fresh.vertex_faces);
  CHECK(result.adjacency.boundary_vertex == fresh.boundary_vertex);
  CHECK(widest_cone_corner(soup, cones) <= max_opened_corner);
  // the old points keep their indices and places; each split of an interior edge
  // adds one point and two triangles; the new points lie on the unit square
  REQUIRE(soup.points.size() == before.points.size() + splits);
  CHECK(soup.triangles.size() == before.triangles.size() + 2 * splits);
  for (std::size_t v = 0; v < before.points.size(); ++v) CHECK(soup.points[v] == before.points[v]);
  for (std::size_t v = before.points.size(); v < soup.points.size(); ++v) {
    CHECK(soup.points[v].z() == 0.0);
    CHECK(std::min(soup.points[v].x(), soup.points[v].y()) > 0.0);
    CHECK(std::max(soup.points[v].x(), soup.points[v].y()) < 1.0);
  }
  // nothing more to split
  CHECK(split_wide_corners(soup, cones).splits == 0);

  // the map folds a triangle there at one of these sizes without the split, none
  // at any of them with it
  std::size_t unsplit_folds = 0;
  for (const double size : {0.25, 0.125, 1.0 / 16}) {
    CAPTURE(size);
    unsplit_folds += cone_map(before, surface_adjacency(before), cones, size).report.inverted_triangles;
    const ConeMap split = cone_map(soup, surface_adjacency(soup), cones, size);
    CHECK(split.report.inverted_triangles == 0);
    CHECK(split.report.max_seam_residual < 1e-9);
  }
  CHECK(unsplit_folds > 0);
}
