// Where the parameterization branches (param/branch_points.h), on a planar disk
// mapped by A z^2 + t: it branches at the centre whatever the cone list says.
#include "libquadmesh/param/branch_points.h"
#include "libquadmesh/param/untangle.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

/// The disk of radius 1 (12 rings, 32 sectors), or its upper half (y >= 0), whose
/// centre is then on the boundary.
TriangleSoup disk(bool upper_half) {
  const TriangleSoup full = test::disk(12, 32);
  if (!upper_half) return full;
  TriangleSoup half;
  std::vector<int> index(full.points.size(), -1);
  for (const Triangle& t : full.triangles) {
    bool keep = true;
    for (int v : t) keep = keep && full.points[static_cast<std::size_t>(v)].y() >= -1e-12;
    if (!keep) continue;
    Triangle u;
    for (int i = 0; i < 3; ++i) {
      int& k = index[static_cast<std::size_t>(t[i])];
      if (k < 0) {
        k = static_cast<int>(half.points.size());
        half.points.push_back(full.points[static_cast<std::size_t>(t[i])]);
      }
      u[i] = k;
    }
    half.triangles.push_back(u);
  }
  return half;
}

FaceMap squared_map(const TriangleSoup& soup, double a, Complex c, Complex t) {
  FaceMap m;
  for (const Triangle& tri : soup.triangles) {
    CornerValues v;
    for (int i = 0; i < 3; ++i) {
      const Vec3& p = soup.points[static_cast<std::size_t>(tri[i])];
      const Complex z(p.x(), p.y());
      v[static_cast<std::size_t>(i)] = a * (z - c) * (z - c) + t;
    }
    m.corners.push_back(v);
  }
  return m;
}

int vertex_at(const TriangleSoup& soup, double x, double y) {
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (std::abs(soup.points[v].x() - x) < 1e-9 && std::abs(soup.points[v].y() - y) < 1e-9) return static_cast<int>(v);
  return -1;
}

/// The image of v, the same in every corner (the map has no cut).
Complex image_of(const TriangleSoup& soup, const FaceMap& m, int v) {
  Complex z;
  bool seen = false;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      if (soup.triangles[f][i] == v) {
        const Complex w = m.corners[f][static_cast<std::size_t>(i)];
        if (seen) CHECK(std::abs(w - z) < 1e-12);
        z = w;
        seen = true;
      }
  return z;
}

double frac(double x) { return std::abs(x - std::round(x)); }

}  // namespace

TEST_CASE("a branch point beside the cone: found, moved onto the lattice, and made the zero") {
  const TriangleSoup soup = disk(false);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = squared_map(soup, 20.0, Complex(0, 0), Complex(0.3, 0.4));
  const FaceMap before = m;
  REQUIRE(count_flipped(m) == 0);
  const int b = vertex_at(soup, 0, 0);
  // the cone list says the zero is one vertex to the right
  const int listed = vertex_at(soup, 0.2, 0);
  const std::vector<ZeroVertex> cones{{listed, 1, false, false}};

  const std::vector<double> angle = image_angles(soup, m);
  CHECK(angle[static_cast<std::size_t>(b)] == doctest::Approx(4 * M_PI));
  CHECK(angle[static_cast<std::size_t>(listed)] == doctest::Approx(2 * M_PI));
  const std::vector<HiddenCone> hidden = hidden_cones(soup, adjacency, m, cones);
  REQUIRE(hidden.size() == 1);
  CHECK(hidden[0].vertex == b);
  CHECK(hidden[0].expected == doctest::Approx(2 * M_PI));

  std::vector<char> pinned(soup.points.size(), 0);
  const SnapReport report = snap_hidden_cones(soup, adjacency, m, cones, pinned);
  CHECK(report.hidden == 1);
  CHECK(report.snapped == 1);
  const Complex at = image_of(soup, m, b);
  CHECK(frac(at.real()) < 1e-12);
  CHECK(frac(at.imag()) < 1e-12);
  CHECK(at == Complex(0.0, 0.0));  // (0.3, 0.4) rounds to the origin
  CHECK(pinned[static_cast<std::size_t>(b)] == 1);
  // a translation near b, blended out: still no fold, still branched at b
  CHECK(count_flipped(m) == 0);
  CHECK(image_angles(soup, m)[static_cast<std::size_t>(b)] == doctest::Approx(4 * M_PI));
  // the blend reaches max(3 |delta|, 1/2) = 1.5 image units (|z| < 0.28); nothing
  // beyond |z| = 0.5 (5 units) moves
  std::size_t far = 0;
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (soup.points[v].norm() > 0.5) {
      ++far;
      CHECK(image_of(soup, m, static_cast<int>(v)) == image_of(soup, before, static_cast<int>(v)));
    }
  CHECK(far > 100);

  // the cones as the map has them: the listed one is an ordinary vertex, b the zero
  const std::vector<ZeroVertex> mapped = mapped_cones(soup, adjacency, m, cones);
  REQUIRE(mapped.size() == 1);
  CHECK(mapped[0].vertex == b);
  CHECK(mapped[0].order == 1);
  CHECK(!mapped[0].on_boundary);
  CHECK(!mapped[0].corner);
}

TEST_CASE("a branch point on the boundary moves along it: U onto the lattice, V kept") {
  // A z^2 is real on the straight edge of the half disk: it stays at V = 0
  const TriangleSoup soup = disk(true);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = squared_map(soup, 20.0, Complex(0, 0), Complex(0.3, 0.0));
  const FaceMap before = m;
  REQUIRE(count_flipped(m) == 0);
  const int b = vertex_at(soup, 0, 0);
  CHECK(image_angles(soup, m)[static_cast<std::size_t>(b)] == doctest::Approx(2 * M_PI));
  std::vector<char> pinned(soup.points.size(), 0);
  const SnapReport report = snap_hidden_cones(soup, adjacency, m, {}, pinned);
  CHECK(report.snapped == 1);
  CHECK(image_of(soup, m, b) == Complex(0.0, 0.0));
  for (std::size_t v = 0; v < soup.points.size(); ++v)
    if (std::abs(soup.points[v].y()) < 1e-12) {
      CHECK(std::abs(image_of(soup, m, static_cast<int>(v)).imag()) < 1e-12);
      CHECK(image_of(soup, m, static_cast<int>(v)).imag() == image_of(soup, before, static_cast<int>(v)).imag());
    }
  CHECK(count_flipped(m) == 0);
  const std::vector<ZeroVertex> mapped = mapped_cones(soup, adjacency, m, {});
  REQUIRE(mapped.size() == 1);
  CHECK(mapped[0].on_boundary);
  CHECK(mapped[0].order == 1);  // on the double: 2 pi (m + 1) there
}

TEST_CASE("a cone where the map branches as it should is left alone") {
  const TriangleSoup soup = disk(false);
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  FaceMap m = squared_map(soup, 20.0, Complex(0, 0), Complex(0.3, 0.4));
  const FaceMap before = m;
  const std::vector<ZeroVertex> cones{{vertex_at(soup, 0, 0), 1, false, false}};
  CHECK(hidden_cones(soup, adjacency, m, cones).empty());
  std::vector<char> pinned(soup.points.size(), 0);
  CHECK(snap_hidden_cones(soup, adjacency, m, cones, pinned).snapped == 0);
  CHECK(m.corners == before.corners);
  const std::vector<ZeroVertex> mapped = mapped_cones(soup, adjacency, m, cones);
  REQUIRE(mapped.size() == 1);
  CHECK(mapped[0].vertex == cones[0].vertex);
}
