// Quad extraction (method.md sections 9, 11) on maps whose grid is known exactly:
// lattice points on vertices, on edges and across a cut are the common case, and
// across a cut the charts may differ by a quarter turn (cones of valence 3 and 5).
#include "libquadmesh/extract/lattice_quads.h"
#include "tests/support/grid_quads.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <set>

using namespace qm;

namespace {

/// The map z -> scale * z + shift on a planar soup (corners in soup order).
FaceMap affine_map(const TriangleSoup& soup, Complex scale, Complex shift) {
  FaceMap m;
  for (const Triangle& t : soup.triangles) {
    CornerValues c;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = soup.points[static_cast<std::size_t>(t[i])];
      c[static_cast<std::size_t>(i)] = scale * Complex(p.x(), p.y()) + shift;
    }
    m.corners.push_back(c);
  }
  return m;
}

/// V - E + F of a quad mesh.
int euler_characteristic(const LatticeQuads& q) {
  std::set<std::pair<int, int>> edges;
  for (const auto& quad : q.quads)
    for (int i = 0; i < 4; ++i) {
      const int a = quad[static_cast<std::size_t>(i)], b = quad[static_cast<std::size_t>((i + 1) % 4)];
      edges.insert({std::min(a, b), std::max(a, b)});
    }
  return static_cast<int>(q.points.size()) - static_cast<int>(edges.size()) + static_cast<int>(q.quads.size());
}

/// A cone fan: `quadrants` copies of the square [0, n]^2 (its unit squares split
/// along the diagonal (x, y)-(x+1, y+1)) glued cyclically around their common corner,
/// the side x = 0 of copy j to the side y = 0 of copy j + 1, and the last copy's to
/// the first's. The centre is a cone of angle quadrants * pi / 2: valence 3 for three
/// copies, 5 for five. Copy j's chart is scale * i^j (x + i y) (plus `shift` on the
/// triangles of turn `shifted_turn`), seamless between copies j and j + 1, so the
/// charts of the last and first copies differ by i^quadrants, a quarter turn; with
/// `diagonal_cut` the triangles of copy 0 below its diagonal take the turn
/// `quadrants` instead, and the quarter-turn seam runs along that diagonal, across
/// the lattice's cells. The 3D points: the fan opened or closed into the unit disk
/// (polar angle times 4 / quadrants, radius kept).
struct ConeFan {
  int quadrants = 3;
  int n = 2;
  double scale = 1.0;
  bool diagonal_cut = false;
  int shifted_turn = -1;
  Complex shift = 0.0;

  /// Point of (x, y) of copy j: the centre is 0; the side x = 0 is the next copy's y = 0.
  int index(int j, int x, int y) const {
    if (x == 0 && y == 0) return 0;
    if (x == 0) return index((j + 1) % quadrants, y, 0);
    return 1 + (j * n + (x - 1)) * (n + 1) + y;
  }
  TriangleSoup soup() const {
    TriangleSoup s;
    s.points.assign(static_cast<std::size_t>(1 + quadrants * n * (n + 1)), Vec3::Zero());
    for (int j = 0; j < quadrants; ++j)
      for (int x = 1; x <= n; ++x)
        for (int y = 0; y <= n; ++y) {
          const double theta = (j * M_PI / 2 + std::atan2(y, x)) * 4.0 / quadrants;
          s.points[static_cast<std::size_t>(index(j, x, y))] =
              std::hypot(x, y) * Vec3(std::cos(theta), std::sin(theta), 0);
        }
    for (int j = 0; j < quadrants; ++j)
      for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y) {
          s.triangles.push_back({index(j, x, y), index(j, x + 1, y), index(j, x + 1, y + 1)});
          s.triangles.push_back({index(j, x, y), index(j, x + 1, y + 1), index(j, x, y + 1)});
        }
    return s;
  }
  /// The chart of each triangle (in the order of soup()).
  FaceMap map() const {
    FaceMap m;
    for (int j = 0; j < quadrants; ++j)
      for (int x = 0; x < n; ++x)
        for (int y = 0; y < n; ++y)
          for (int below = 1; below >= 0; --below) {
            const bool below_diagonal = x > y || (x == y && below);
            const int turn = diagonal_cut && j == 0 && below_diagonal ? quadrants : j;
            Complex rot = 1.0;
            for (int k = 0; k < turn; ++k) rot *= Complex(0, 1);
            const Complex t = turn == shifted_turn ? shift : 0.0;
            const std::array<Complex, 3> local =
                below ? std::array<Complex, 3>{Complex(x, y), Complex(x + 1, y), Complex(x + 1, y + 1)}
                      : std::array<Complex, 3>{Complex(x, y), Complex(x + 1, y + 1), Complex(x, y + 1)};
            CornerValues c;
            for (std::size_t i = 0; i < 3; ++i) c[i] = scale * rot * local[i] + t;
            m.corners.push_back(c);
          }
    return m;
  }
};

/// The number of quads at each point.
std::vector<int> quads_at_points(const LatticeQuads& q) {
  std::vector<int> count(q.points.size(), 0);
  for (const auto& quad : q.quads)
    for (int v : quad) ++count[static_cast<std::size_t>(v)];
  return count;
}

/// The points on an edge of one quad only.
std::set<int> quad_boundary_points(const LatticeQuads& q) {
  std::map<std::pair<int, int>, int> uses;
  for (const auto& quad : q.quads)
    for (std::size_t i = 0; i < 4; ++i) ++uses[std::minmax(quad[i], quad[(i + 1) % 4])];
  std::set<int> boundary;
  for (const auto& [edge, count] : uses)
    if (count == 1) boundary.insert({edge.first, edge.second});
  return boundary;
}

/// Every directed quad edge at most once: neighbouring quads run their common edge
/// in opposite directions (the quads are consistently oriented).
bool consistently_oriented(const LatticeQuads& q) {
  std::set<std::pair<int, int>> directed;
  for (const auto& quad : q.quads)
    for (std::size_t i = 0; i < 4; ++i)
      if (!directed.insert({quad[i], quad[(i + 1) % 4]}).second) return false;
  return true;
}

/// The image of point v in the chart of the triangle that locates it.
Complex image_of_point(const LatticeQuads& q, const FaceMap& m, std::size_t v) {
  const SurfaceLocation& loc = q.locations[v];
  Complex z = 0.0;
  for (std::size_t i = 0; i < 3; ++i) z += loc.barycentric[i] * m.corners[static_cast<std::size_t>(loc.face)][i];
  return z;
}

/// What every fan extraction must give: cells^2 quads per copy (`cells` on a side), chi
/// 1, the centre in `quadrants` quads and every other interior point in 4, the quads
/// consistently oriented, every point at a lattice point of its triangle's chart
/// and at the barycentric combination of the triangle's 3D corners, nothing dropped.
void check_fan(const ConeFan& fan, int cells, const LatticeQuads& q, const ExtractionReport& report) {
  const TriangleSoup soup = fan.soup();
  const FaceMap m = fan.map();
  CHECK(q.quads.size() == static_cast<std::size_t>(fan.quadrants * cells * cells));
  CHECK(q.points.size() == static_cast<std::size_t>(1 + fan.quadrants * cells * (cells + 1)));
  CHECK(euler_characteristic(q) == 1);
  CHECK(report.incomplete_cells == 0);
  CHECK(report.degenerate_cells == 0);
  CHECK(report.bad_triangles == 0);
  CHECK(report.seam_mismatches == 0);
  CHECK(consistently_oriented(q));
  const std::vector<int> valence = quads_at_points(q);
  const std::set<int> boundary = quad_boundary_points(q);
  CHECK(boundary.size() == static_cast<std::size_t>(2 * fan.quadrants * cells));  // the outer loop
  int centres = 0;
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    const SurfaceLocation& loc = q.locations[v];
    if (loc.kind == SurfaceLocation::Kind::vertex && loc.a == 0) {
      ++centres;
      CHECK(valence[v] == fan.quadrants);
      CHECK(q.points[v].norm() == 0.0);
    } else if (!boundary.count(static_cast<int>(v))) {
      CHECK(valence[v] == 4);
    }
    const Complex z = image_of_point(q, m, v);
    CHECK(std::abs(z.real() - std::round(z.real())) < 1e-9);
    CHECK(std::abs(z.imag() - std::round(z.imag())) < 1e-9);
    Vec3 p = Vec3::Zero();
    const Triangle& t = soup.triangles[static_cast<std::size_t>(loc.face)];
    for (std::size_t i = 0; i < 3; ++i) p += loc.barycentric[i] * soup.points[static_cast<std::size_t>(t[i])];
    CHECK((p - q.points[v]).norm() < 1e-12);
  }
  CHECK(centres == 1);
}

}  // namespace

TEST_CASE("a grid whose lattice points are all mesh vertices gives one quad per cell") {
  // grid(n): the unit square with n x n cells split in two; scale n puts every
  // lattice point on a vertex and every grid line on mesh edges
  const TriangleSoup soup = test::grid(6);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, affine_map(soup, 6.0, 0.0), report);
  CHECK(q.quads.size() == 36);
  CHECK(q.points.size() == 49);
  CHECK(report.incomplete_cells == 0);
  CHECK(report.degenerate_cells == 0);
  CHECK(euler_characteristic(q) == 1);
  for (const SurfaceLocation& loc : q.locations) CHECK(loc.kind == SurfaceLocation::Kind::vertex);
}

TEST_CASE("a rotated and shifted grid: lattice points inside triangles and on edges") {
  const TriangleSoup soup = test::grid(7);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  // 5 x 5 cells turned by 90 degrees, the lattice shifted by half a cell in U:
  // integer points fall on edges and inside triangles; the image is [-5, 0] x [0, 5]
  // shifted, so exactly 4 x 5 cells are complete
  ExtractionReport report;
  const LatticeQuads q =
      extract_lattice_quads(soup, adjacency, affine_map(soup, Complex(0, 5.0), Complex(0.5, 0)), report);
  CHECK(q.quads.size() == 20);
  CHECK(report.incomplete_cells == 10);  // the half cells along two sides
  std::map<SurfaceLocation::Kind, int> kinds;
  for (const SurfaceLocation& loc : q.locations) ++kinds[loc.kind];
  CHECK(kinds[SurfaceLocation::Kind::face] + kinds[SurfaceLocation::Kind::edge] > 0);
  // corners map back to the square: |x|, |y| in [0, 1] and spacing 1/5
  for (const auto& quad : q.quads) {
    const Vec3 e = q.points[static_cast<std::size_t>(quad[1])] - q.points[static_cast<std::size_t>(quad[0])];
    CHECK(e.norm() == doctest::Approx(0.2).epsilon(1e-8));
  }
}

TEST_CASE("charts that differ by an integer translation across a cut give the same quads") {
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap cut = affine_map(soup, 4.0, 0.0);
  // move the triangles of the right half by (7, -3): a seam along x = 1/2
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    double x = 0;
    for (int v : soup.triangles[f]) x += soup.points[static_cast<std::size_t>(v)].x() / 3;
    if (x > 0.5)
      for (Complex& z : cut.corners[f]) z += Complex(7, -3);
  }
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, cut, report);
  CHECK(q.quads.size() == 16);
  CHECK(q.points.size() == 25);
  CHECK(report.seam_mismatches == 0);
  CHECK(euler_characteristic(q) == 1);
}

TEST_CASE("a folded triangle is reported, never extracted") {
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = affine_map(soup, 4.0, 0.0);
  // pull one interior vertex across its neighbours
  const int v = 12;  // (2/4, 2/4)... any interior vertex of grid(4)
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (soup.triangles[f][i] == v) m.corners[f][static_cast<std::size_t>(i)] += Complex(1.6, 0.0);
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, m, report);
  CHECK(report.bad_triangles > 0);
  CHECK(q.quads.size() < 16);
}

TEST_CASE("a map blown up over millions of cells is refused triangle by triangle, not enumerated") {
  // grid(4) scaled so that each triangle spans (2^12 / 4)^2 / 2 ~ 500000 cells
  const TriangleSoup soup = test::grid(4);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, adjacency, affine_map(soup, 4096.0, 0.0), report);
  CHECK(report.bad_triangles == soup.triangles.size());
  CHECK(q.quads.empty());
  // just under the limit, the same triangles are extracted: (2^7 / 4)^2 = 1024 cells per square
  const LatticeQuads fine = extract_lattice_quads(soup, adjacency, affine_map(soup, 128.0, 0.0), report);
  CHECK(report.bad_triangles == 0);
  CHECK(fine.quads.size() == 128u * 128u);
}

TEST_CASE("stray boundary points: the quads' own boundary off the boundary of S") {
  // 3 x 3 quads on the unit square, its outer ring on boundary loop 0
  const LatticeQuads full = test::grid_quads(test::grid(3), 3);
  const std::vector<int> loop_of = test::unit_square_boundary(full);
  CHECK(stray_boundary_points(full, loop_of).empty());
  // without the middle quad, its 4 corners (interior points of S) are on a hole
  // the input does not have
  LatticeQuads holed = full;
  holed.quads.erase(holed.quads.begin() + 4);
  const std::vector<int> stray = stray_boundary_points(holed, loop_of);
  CHECK(stray.size() == 4);
  for (int v : stray) CHECK(loop_of[static_cast<std::size_t>(v)] < 0);
  // without a corner quad: only its inner corner is off the square's boundary
  LatticeQuads notched = full;
  notched.quads.erase(notched.quads.begin());
  CHECK(stray_boundary_points(notched, loop_of).size() == 1);
}

TEST_CASE("a valence-3 cone: charts a quarter turn apart across the cut, lattice points on vertices") {
  // three quadrants of [-2, 2]^2 (the square minus x > 0, y < 0), the positive x
  // axis glued to the negative y axis: 3 n^2 quads, the centre in 3 of them
  const ConeFan fan{3, 2};
  const TriangleSoup soup = fan.soup();
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, surface_adjacency(soup), fan.map(), report);
  check_fan(fan, 2, q, report);
  CHECK(q.quads.size() == 12);
  CHECK(q.points.size() == 19);
  for (std::size_t v = 0; v < q.points.size(); ++v) {
    const SurfaceLocation& loc = q.locations[v];
    REQUIRE(loc.kind == SurfaceLocation::Kind::vertex);
    CHECK(q.points[v] == soup.points[static_cast<std::size_t>(loc.a)]);
  }
}

TEST_CASE("a valence-5 cone: five quadrants, the cut's charts a quarter turn the other way") {
  const ConeFan fan{5, 3};
  const TriangleSoup soup = fan.soup();
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, surface_adjacency(soup), fan.map(), report);
  check_fan(fan, 3, q, report);
  CHECK(q.quads.size() == 45);
  CHECK(q.points.size() == 61);
}

TEST_CASE("cones whose quarter-turn seam crosses the cells: lattice points inside triangles and on the seam") {
  // n = 5 triangle squares per quadrant at scale 3/5: 3 x 3 cells per quadrant,
  // lattice points on vertices (the corners), on edges (the diagonals, the sides)
  // and inside triangles; the seam runs along quadrant 0's diagonal, through the
  // cells (k, k), with a quarter turn and a translation (7, -3) on its far side
  for (const int quadrants : {3, 5}) {
    CAPTURE(quadrants);
    const ConeFan fan{quadrants, 5, 0.6, true, quadrants, Complex(7, -3)};
    const TriangleSoup soup = fan.soup();
    ExtractionReport report;
    const LatticeQuads q = extract_lattice_quads(soup, surface_adjacency(soup), fan.map(), report);
    check_fan(fan, 3, q, report);
    std::map<SurfaceLocation::Kind, int> kinds;
    for (const SurfaceLocation& loc : q.locations) ++kinds[loc.kind];
    // on vertices: the centre, and per copy the lattice points (3, 0) and (3, 3) of
    // its chart, local (5, 0) and (5, 5) ((0, 3) is the next copy's (3, 0))
    CHECK(kinds[SurfaceLocation::Kind::vertex] == 1 + 2 * quadrants);
    CHECK(kinds[SurfaceLocation::Kind::edge] > 0);
    CHECK(kinds[SurfaceLocation::Kind::face] > 0);
    // the lattice point (1, 1) of copy 0 is on the seam, 2/3 of the way along the
    // diagonal edge from local (1, 1) to (2, 2)
    const int a = fan.index(0, 1, 1), b = fan.index(0, 2, 2);
    const Vec3 expected =
        soup.points[static_cast<std::size_t>(a)] / 3 + 2 * soup.points[static_cast<std::size_t>(b)] / 3;
    int found = 0;
    for (std::size_t v = 0; v < q.points.size(); ++v)
      if (q.locations[v].kind == SurfaceLocation::Kind::edge && q.locations[v].a == std::min(a, b) &&
          q.locations[v].b == std::max(a, b)) {
        ++found;
        CHECK((q.points[v] - expected).norm() < 1e-12);
      }
    CHECK(found == 1);
  }
}

TEST_CASE("a cone with the quarter-turn seam on grid lines and a translation on one copy") {
  // the lattice points of the seams are on mesh vertices and edges: each is one
  // point whatever the chart it is located in
  const ConeFan fan{3, 5, 0.6, false, 2, Complex(-4, 9)};
  const TriangleSoup soup = fan.soup();
  ExtractionReport report;
  const LatticeQuads q = extract_lattice_quads(soup, surface_adjacency(soup), fan.map(), report);
  check_fan(fan, 3, q, report);
  CHECK(q.quads.size() == 27);
  CHECK(q.points.size() == 37);
}

TEST_CASE("a seam that is not a quarter turn is a seam mismatch") {
  ConeFan fan{3, 4, 1.0, true};
  const TriangleSoup soup = fan.soup();
  FaceMap m = fan.map();
  // turn the far side of the diagonal seam (copy 0's triangles below its diagonal,
  // two per square in soup order) by a further 0.3 radians about the centre
  const Complex extra = std::polar(1.0, 0.3);
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      for (int upper = 0; upper < 2; ++upper)
        if (x > y || (x == y && !upper))
          for (Complex& z : m.corners[static_cast<std::size_t>(2 * (x * 4 + y) + upper)]) z *= extra;
  ExtractionReport report;
  extract_lattice_quads(soup, surface_adjacency(soup), m, report);
  CHECK(report.seam_mismatches > 0);
}
