// The quads at the input's corners (corner_quads.h) and the quad sizes against a
// target (quad_quality with a target size), on meshes whose answers are known by
// construction: a square, an L-shape, a split corner, a corner the quads miss, a
// 30-degree corner.
#include "libquadmesh/quality/corner_quads.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/size_band.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>

using namespace qm;

namespace {

/// The cells (i, j) of an n x n grid of spacing h for which `keep` holds, as quads
/// (CCW) over the grid's points.
PolygonMesh grid_cells(int n, double h, const std::function<bool(int, int)>& keep) {
  PolygonMesh mesh;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.points.push_back(Vec3(i * h, j * h, 0));
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (keep(i, j)) mesh.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

/// The mesh's faces as triangles (fans from the first corner): the reference.
TriangleSoup triangles_of(const PolygonMesh& mesh) {
  TriangleSoup soup;
  soup.points = mesh.points;
  for (const auto& f : mesh.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) soup.triangles.push_back({f[0], f[k], f[k + 1]});
  return soup;
}

const auto all_cells = [](int, int) { return true; };

}  // namespace

TEST_CASE("a square's four corners are each in one quad") {
  const PolygonMesh quads = grid_cells(4, 0.25, all_cells);
  const CornerQuads c = corner_quads(quads, triangles_of(grid_cells(2, 0.5, all_cells)));
  CHECK(c.convex == 4);
  CHECK(c.convex_wrong == 0);
  CHECK(c.concave == 0);
  CHECK(c.other == 0);
  REQUIRE(c.corners.size() == 4);
  for (const CornerCount& k : c.corners) {
    CHECK(k.angle_deg == doctest::Approx(90).epsilon(1e-12));
    CHECK(k.quads_wanted == 1);
    CHECK(k.quads == 1);
  }
}

TEST_CASE("an L-shape: five convex corners in one quad, the concave one in three") {
  // [0,2]^2 without [1,2]^2: cells of side 1 for the reference, of side 0.5 for the quads
  const auto l_shape = [](int cells) { return [cells](int i, int j) { return i < cells || j < cells; }; };
  const CornerQuads c = corner_quads(grid_cells(4, 0.5, l_shape(2)), triangles_of(grid_cells(2, 1.0, l_shape(1))));
  CHECK(c.convex == 5);
  CHECK(c.convex_wrong == 0);
  CHECK(c.concave == 1);
  CHECK(c.concave_wrong == 0);
  for (const CornerCount& k : c.corners)
    if (k.quads_wanted == 3) {
      CHECK(k.angle_deg == doctest::Approx(270).epsilon(1e-12));
      CHECK(k.position.isApprox(Vec3(1, 1, 0)));
      CHECK(k.quads == 3);
    }
}

TEST_CASE("a corner split in two faces, or missed by the quads, is wrong") {
  const TriangleSoup square = triangles_of(grid_cells(1, 1.0, all_cells));
  SUBCASE("split: the corner quad cut along its diagonal from the corner") {
    PolygonMesh quads = grid_cells(2, 0.5, all_cells);
    const std::vector<int> corner = quads.faces.front();  // (0,0) (0.5,0) (0.5,0.5) (0,0.5)
    quads.faces.front() = {corner[0], corner[1], corner[2]};
    quads.faces.push_back({corner[0], corner[2], corner[3]});
    const CornerQuads c = corner_quads(quads, square);
    CHECK(c.convex == 4);
    CHECK(c.convex_wrong == 1);
  }
  SUBCASE("missed: the quads' corner point 0.14 from the square's corner") {
    PolygonMesh quads = grid_cells(2, 0.5, all_cells);
    quads.points[0] = Vec3(0.1, 0.1, 0);  // its boundary edges are 0.41 long: a quarter is 0.10
    const CornerQuads c = corner_quads(quads, square);
    CHECK(c.convex_wrong == 1);
    int missed = 0;
    for (const CornerCount& k : c.corners) missed += k.quads == 0;
    CHECK(missed == 1);
  }
}

TEST_CASE("a 30-degree corner is another corner, wanting one quad; 135 degrees is no corner") {
  // a triangle (0,0) (1,0) (cos 30, sin 30) fanned from its centroid: corners of 30,
  // 75 and 75 degrees
  const double a = M_PI / 6;
  PolygonMesh tri;
  tri.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(std::cos(a), std::sin(a), 0)};
  tri.points.push_back((tri.points[0] + tri.points[1] + tri.points[2]) / 3);
  tri.faces = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  PolygonMesh one_face = tri;  // the whole triangle as one face: each corner in one face
  one_face.faces = {{0, 1, 2}};
  const CornerQuads c = corner_quads(one_face, triangles_of(tri));
  CHECK(c.other == 1);
  CHECK(c.convex == 2);
  CHECK(c.other_wrong == 0);
  CHECK(c.convex_wrong == 0);
  const CornerQuads fan = corner_quads(tri, triangles_of(tri));  // each corner in two faces of the fan
  CHECK(fan.other_wrong == 1);
  CHECK(fan.convex_wrong == 2);
  // a trapezoid (0,0) (3,0) (2,1) (1,1): 45-degree corners below (other corners), 135 degrees above (none)
  PolygonMesh trapezoid;
  trapezoid.points = {Vec3(0, 0, 0), Vec3(3, 0, 0), Vec3(2, 1, 0), Vec3(1, 1, 0)};
  trapezoid.faces = {{0, 1, 2, 3}};
  const CornerQuads t = corner_quads(trapezoid, triangles_of(trapezoid));
  CHECK(t.corners.size() == 2);
  CHECK(t.other == 2);
}

TEST_CASE("quad sizes against a target: the band share and the extreme ratios") {
  const PolygonMesh quads = grid_cells(4, 0.25, all_cells);
  const QuadQuality at_size = quad_quality(quads, nullptr, 0.25);
  CHECK(at_size.size_band_share == 1.0);
  CHECK(at_size.size_ratio_max == doctest::Approx(1.0).epsilon(1e-12));
  const QuadQuality too_fine = quad_quality(quads, nullptr, 0.1);  // 2.5 x the target
  CHECK(too_fine.size_band_share == 0.0);
  CHECK(too_fine.size_ratio_min == doctest::Approx(2.5).epsilon(1e-12));
  CHECK(std::isnan(quad_quality(quads, nullptr).size_band_share));
  // with a reference the corners are counted too
  const QuadQuality q = quad_quality(quads, nullptr, 0.25);
  CHECK(q.corners_convex == 0);
  const TriangleSoup square = triangles_of(grid_cells(1, 1.0, all_cells));
  const QuadQuality r = quad_quality(quads, &square, 0.25);
  CHECK(r.corners_convex == 4);
  CHECK(r.corners_convex_wrong == 0);
}

TEST_CASE("quad sizes on a lattice of another scale: each ratio scaled, the band counted again") {
  // 16 quads 0.25 wide and 4 quads 0.125 wide (a finer corner), against 0.3: the
  // small ones at 0.417 x are below the band, the others at 0.833 x in it
  PolygonMesh quads = grid_cells(4, 0.25, all_cells);
  const PolygonMesh fine = grid_cells(2, 0.125, all_cells);
  const int offset = static_cast<int>(quads.points.size());
  for (const Vec3& p : fine.points) quads.points.push_back(p + Vec3(2, 0, 0));
  for (auto face : fine.faces) {
    for (int& v : face) v += offset;
    quads.faces.push_back(face);
  }
  const std::vector<double> ratios = quad_size_ratios(quads, 0.3);
  REQUIRE(ratios.size() == 20);
  const SizeBand as_is = scaled_size_band(ratios, 1.0);
  CHECK(as_is.share_in_band == doctest::Approx(0.8));
  CHECK(as_is.min_ratio == doctest::Approx(0.125 / 0.3));
  CHECK(as_is.max_ratio == doctest::Approx(0.25 / 0.3));
  CHECK(as_is.share_in_band == quad_size_band(quads, 0.3).share_in_band);
  // a lattice 1.25 x coarser: 0.521 x and 1.04 x, every quad in the band
  const SizeBand coarser = scaled_size_band(ratios, 1.25);
  CHECK(coarser.share_in_band == 1.0);
  CHECK(coarser.max_ratio == doctest::Approx(1.25 * 0.25 / 0.3));
  // 2.5 x coarser: the large ones at 2.08 x leave it
  CHECK(scaled_size_band(ratios, 2.5).share_in_band == doctest::Approx(0.2));
  CHECK(std::isnan(scaled_size_band({}, 1.0).share_in_band));
}

TEST_CASE("teeth of a scanned boundary smaller than the window are not corners; seen closer they are") {
  // the unit square whose bottom edge (points 0.05 apart) has four teeth 0.03 high in
  // its middle: peaks of 242 degrees, valleys of 118 between them, 149 at the ends
  TriangleSoup strip;
  const int n = 20;
  for (int i = 0; i <= n; ++i) strip.points.push_back(Vec3(0.05 * i, (i % 2 == 1 && i >= 7 && i <= 13) ? 0.03 : 0, 0));
  for (int i = 0; i <= n; ++i) strip.points.push_back(Vec3(0.05 * i, 1, 0));
  for (int i = 0; i < n; ++i) {
    const int b = i, t = n + 1 + i;
    strip.triangles.push_back({b, b + 1, t + 1});
    strip.triangles.push_back({b, t + 1, t});
  }
  // seen at the scale of quads of 0.5 (window 0.25): the square's four corners only
  const CornerQuads c = corner_quads(grid_cells(2, 0.5, all_cells), strip);
  CHECK(c.convex == 4);
  CHECK(c.convex_wrong == 0);
  CHECK(c.concave == 0);
  CHECK(c.other == 0);
  for (const CornerCount& k : c.corners) CHECK(k.angle_deg == doctest::Approx(90).epsilon(1e-9));
  // seen at 0.01: the square's corners, the four peaks and the three inner valleys
  const std::vector<BoundaryCorner> close = boundary_corners(strip, 0.01);
  int peaks = 0, valleys = 0, right = 0;
  for (const BoundaryCorner& k : close) {
    peaks += std::abs(k.angle_deg - (180 + 2 * std::atan(0.6) * 180 / M_PI)) < 1e-9;
    valleys += std::abs(k.angle_deg - (180 - 2 * std::atan(0.6) * 180 / M_PI)) < 1e-9;
    right += std::abs(k.angle_deg - 90) < 1e-9;
  }
  CHECK(close.size() == 11);
  CHECK(peaks == 4);
  CHECK(valleys == 3);
  CHECK(right == 4);
}

TEST_CASE("a staircase of steps lower than 0.75 quads has no corners; a step or a step and a half keeps its own") {
  // a 1.1 square of cells 0.055 whose floor rises in steps 0.11 (0.55 quads of 0.2)
  // high and deep from x = 0.33: seen at quads of 0.2 (window 0.1) each step is a
  // convex and a concave right corner (steps of 90 and 270 degrees)
  const double h = 0.055, quad = 0.2;
  const auto corners_of = [&](const std::function<int(int)>& floor) {
    const PolygonMesh cells = grid_cells(20, h, [&](int i, int j) { return floor(i) >= 0 && j >= floor(i); });
    return boundary_corners(triangles_of(cells), corner_window_quads * quad);
  };
  const auto count = [](const std::vector<BoundaryCorner>& cs, double angle) {
    return std::count_if(cs.begin(), cs.end(),
                         [&](const BoundaryCorner& c) { return std::abs(c.angle_deg - angle) < 1e-9; });
  };
  // one step up: a shoulder, its two corners stay
  const std::vector<BoundaryCorner> shoulder = corners_of([](int i) { return i < 6 ? 0 : 2; });
  CHECK(shoulder.size() == 6);
  CHECK(count(shoulder, 90) == 5);
  CHECK(count(shoulder, 270) == 1);
  // a step and a half (up, then a wall at x = 0.44: three corners in a row) keeps
  // its corners, beside the three other square corners
  const std::vector<BoundaryCorner> jog = corners_of([](int i) { return i < 6 ? 0 : i < 8 ? 2 : -1; });
  CHECK(jog.size() == 6);
  CHECK(count(jog, 90) == 5);
  CHECK(count(jog, 270) == 1);
  // two steps up (four corners in a row, each 0.55 quads from the next): a
  // staircase, no corner but the square's four
  const std::vector<BoundaryCorner> stairs = corners_of([](int i) { return i < 6 ? 0 : i < 8 ? 2 : 4; });
  CHECK(stairs.size() == 4);
  CHECK(count(stairs, 90) == 4);
  // the same steps ending at a wall (x = 0.55, five corners in a row): the net
  // quarter turn stays at one of them, beside the three other square corners
  const std::vector<BoundaryCorner> to_wall =
      corners_of([](int i) { return i < 6 ? 0 : i < 8 ? 2 : i < 10 ? 4 : -1; });
  CHECK(to_wall.size() == 4);
  CHECK(count(to_wall, 90) == 4);
  // seen at quads of 0.1 the steps are 1.1 quads apart: corners again
  const PolygonMesh cells = grid_cells(20, h, [](int i, int j) { return j >= (i < 6 ? 0 : i < 8 ? 2 : 4); });
  CHECK(boundary_corners(triangles_of(cells), corner_window_quads * 0.1).size() == 8);
}
