// Quad-mesh quality (method.md section 10) on meshes whose numbers are known by
// construction: grids, sheared grids, a cylinder, a flipped quad, a 3-5 pair,
// and Hausdorff distances between shifted copies.
#include "io/read_polygon_mesh.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "libquadmesh/quality/quad_quality.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>

using namespace qm;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// n x m cells, point (i, j) at place(i, j), quads CCW in the (i, j) plane.
PolygonMesh quad_grid(int n, int m, const std::function<Vec3(int, int)>& place) {
  PolygonMesh mesh;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= n; ++i)
      mesh.points.push_back(place(i, j));
  const auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < n; ++i)
      mesh.faces.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return mesh;
}

PolygonMesh unit_grid(int n, int m) {
  return quad_grid(n, m, [](int i, int j) { return Vec3(i, j, 0); });
}

/// The quads split into triangles, along 0-2 or along 1-3.
TriangleSoup triangulated(const PolygonMesh& mesh, bool along_13) {
  TriangleSoup soup;
  soup.points = mesh.points;
  for (const std::vector<int>& f : mesh.faces) {
    if (along_13) {
      soup.triangles.push_back({f[1], f[2], f[3]});
      soup.triangles.push_back({f[1], f[3], f[0]});
    } else {
      soup.triangles.push_back({f[0], f[1], f[2]});
      soup.triangles.push_back({f[0], f[2], f[3]});
    }
  }
  return soup;
}

}  // namespace

TEST_CASE("corner helpers: scaled Jacobian, angle") {
  const Vec3 o(0, 0, 0), x(1, 0, 0), y(0, 2, 0), z(0, 0, 1);
  CHECK(corner_scaled_jacobian(y, o, x, z) == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(corner_scaled_jacobian(y, o, x, -z) == doctest::Approx(-1.0).epsilon(1e-15));
  CHECK(corner_scaled_jacobian(x, o, y, z) == doctest::Approx(-1.0).epsilon(1e-15));
  CHECK(corner_scaled_jacobian(o, o, x, z) == 0.0);
  const Vec3 at60(std::cos(kPi / 3), std::sin(kPi / 3), 0);
  CHECK(std::abs(corner_scaled_jacobian(at60, o, x, z) - std::sin(kPi / 3)) < 1e-15);
  CHECK(std::abs(corner_angle_deg(y, o, x) - 90.0) < 1e-12);
  CHECK(std::abs(corner_angle_deg(at60, o, x) - 60.0) < 1e-12);
  CHECK(std::abs(corner_angle_deg(-x, o, x) - 180.0) < 1e-12);
}

TEST_CASE("unit-square grid: perfect scores, a disk") {
  const int n = 5, m = 3;
  const QuadQuality q = quad_quality(unit_grid(n, m), nullptr);
  CHECK(q.vertices == static_cast<std::size_t>((n + 1) * (m + 1)));
  CHECK(q.quads == static_cast<std::size_t>(n * m));
  CHECK(q.triangles == 0);
  CHECK(q.other_faces == 0);
  CHECK(q.inverted == 0);
  CHECK(q.flipped == 0);
  CHECK(q.min_scaled_jacobian == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(q.mean_scaled_jacobian == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(q.p01_scaled_jacobian == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(q.min_normal_consistency == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(std::abs(q.min_angle - 90) < 1e-12);
  CHECK(std::abs(q.max_angle - 90) < 1e-12);
  CHECK(q.min_warpage == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(q.skew_max < 1e-15);
  CHECK(q.taper_max < 1e-15);
  CHECK(std::isnan(q.triangle_min_scaled_jacobian));
  CHECK(q.angle_dev_mean < 1e-12);
  CHECK(q.angle_dev_rms < 1e-12);
  CHECK(q.angle_dev_p99 < 1e-12);
  CHECK(q.angle_dev_max < 1e-12);
  CHECK(q.aspect_ratio_mean == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(q.aspect_ratio_max == doctest::Approx(1.0).epsilon(1e-15));
  CHECK(q.irregular_interior == 0);
  CHECK(q.irregular_boundary == 0);
  CHECK(q.valence_interior == std::map<int, std::size_t>{{4, (n - 1) * (m - 1)}});
  // 4 corners with one quad, the other boundary points with two
  CHECK(q.valence_boundary == std::map<int, std::size_t>{{1, 4}, {2, 2 * (n - 1) + 2 * (m - 1)}});
  CHECK(q.euler_characteristic == 1);
  CHECK(q.boundary_loops == 1);
  CHECK(q.manifold);
  CHECK(q.consistently_oriented);
  CHECK(q.edge_length_min == 1.0);
  CHECK(q.edge_length_mean == 1.0);
  CHECK(q.edge_length_max == 1.0);
  CHECK(q.boundary_alignment_mean < 1e-12);
  CHECK(q.boundary_alignment_max < 1e-12);
  CHECK(std::isnan(q.hausdorff_rel));
  CHECK(std::isnan(q.hausdorff_forward_rel));
  CHECK(std::isnan(q.hausdorff_backward_rel));
}

TEST_CASE("grid sheared by an angle a: scaled Jacobian cos a, angle deviation a, skew sin a") {
  for (const double a_deg : {5.0, 20.0, 45.0}) {
    CAPTURE(a_deg);
    const double a = a_deg * kPi / 180;
    // unit edges (1, 0) and (sin a, cos a): corner angles 90 - a and 90 + a
    const QuadQuality q = quad_quality(
        quad_grid(4, 4,
                  [a](int i, int j) { return Vec3(i + j * std::sin(a), j * std::cos(a), 0); }),
        nullptr);
    CHECK(q.inverted == 0);
    CHECK(std::abs(q.min_scaled_jacobian - std::cos(a)) < 1e-9);
    CHECK(std::abs(q.mean_scaled_jacobian - std::cos(a)) < 1e-9);
    CHECK(std::abs(q.p01_scaled_jacobian - std::cos(a)) < 1e-9);
    CHECK(std::abs(q.angle_dev_mean - a_deg) < 1e-9);
    CHECK(std::abs(q.angle_dev_rms - a_deg) < 1e-9);
    CHECK(std::abs(q.angle_dev_p99 - a_deg) < 1e-9);
    CHECK(std::abs(q.angle_dev_max - a_deg) < 1e-9);
    // Verdict: longest edge * perimeter / (2 * twice the area) = 4 / (4 cos a)
    CHECK(std::abs(q.aspect_ratio_max - 1 / std::cos(a)) < 1e-12);
    CHECK(std::abs(q.skew_max - std::sin(a)) < 1e-12);
    CHECK(q.taper_max < 1e-12);
    CHECK(std::abs(q.min_angle - (90 - a_deg)) < 1e-9);
    CHECK(std::abs(q.max_angle - (90 + a_deg)) < 1e-9);
    CHECK(q.irregular_interior == 0);
    // the slanted sides meet the bottom and top rows at 90 - a / 90 + a
    CHECK(std::abs(q.boundary_alignment_max - a_deg) < 1e-9);
  }
}

TEST_CASE("a quad with its corners reversed is flipped (not Verdict-inverted) and breaks the orientation") {
  PolygonMesh mesh = unit_grid(3, 3);
  std::vector<int>& middle = mesh.faces[4];  // the cell (1, 1): all its corners interior
  std::reverse(middle.begin(), middle.end());
  const QuadQuality q = quad_quality(mesh, nullptr);
  // Verdict measures a quad against its own normal: a square is a square
  CHECK(q.inverted == 0);
  CHECK(q.min_scaled_jacobian == doctest::Approx(1.0).epsilon(1e-15));
  // against its neighbours it is turned over
  CHECK(q.flipped == 1);
  CHECK(q.min_normal_consistency == doctest::Approx(-1.0).epsilon(1e-15));
  CHECK(sound_scaled_jacobians(mesh)[4] == doctest::Approx(-1.0).epsilon(1e-15));
  CHECK_FALSE(q.consistently_oriented);
  CHECK(q.manifold);
  CHECK(q.euler_characteristic == 1);
  CHECK(q.boundary_loops == 1);

  PolygonMesh corner = unit_grid(3, 3);
  std::reverse(corner.faces[0].begin(), corner.faces[0].end());
  const QuadQuality c = quad_quality(corner, nullptr);
  CHECK(c.flipped >= 1);
  CHECK_FALSE(c.consistently_oriented);
}

TEST_CASE("cylinder: chi 0, two boundary loops, planar rectangles, normal consistency cos(pi / sectors)") {
  const int sectors = 12, rings = 3;
  PolygonMesh mesh;
  for (int k = 0; k <= rings; ++k)
    for (int j = 0; j < sectors; ++j) {
      const double t = 2 * kPi * j / sectors;
      mesh.points.emplace_back(std::cos(t), std::sin(t), 0.5 * k);
    }
  const auto id = [&](int k, int j) { return k * sectors + j % sectors; };
  for (int k = 0; k < rings; ++k)
    for (int j = 0; j < sectors; ++j)
      mesh.faces.push_back({id(k, j), id(k, j + 1), id(k + 1, j + 1), id(k + 1, j)});
  const QuadQuality q = quad_quality(mesh, nullptr);
  CHECK(q.euler_characteristic == 0);
  CHECK(q.boundary_loops == 2);
  CHECK(q.manifold);
  CHECK(q.consistently_oriented);
  CHECK(q.irregular_interior == 0);
  CHECK(q.irregular_boundary == 0);
  CHECK(q.valence_interior == std::map<int, std::size_t>{{4, (rings - 1) * sectors}});
  CHECK(q.valence_boundary == std::map<int, std::size_t>{{2, 2 * sectors}});
  // every quad is a planar rectangle (Verdict: 1); the vertex normals are radial,
  // each quad's normal is radial at its middle
  CHECK(std::abs(q.min_scaled_jacobian - 1) < 1e-12);
  CHECK(std::abs(q.min_warpage - 1) < 1e-12);
  CHECK(std::abs(q.min_normal_consistency - std::cos(kPi / sectors)) < 1e-9);
  CHECK(q.boundary_alignment_max < 1e-9);
}

TEST_CASE("a valence-3 / valence-5 pair: two irregular interior vertices") {
  // 4 x 4 grid; the cells (1, 0) and (2, 0) share the edge (2, 0)-(2, 1). Rotating
  // that edge to (3, 0)-(1, 1) leaves (2, 1) with 3 edges and gives (1, 1) five.
  PolygonMesh mesh = quad_grid(4, 4, [](int i, int j) {
    if (i == 2 && j == 0) return Vec3(2, -0.3, 0);  // keep the new quads convex
    if (i == 2 && j == 1) return Vec3(2, 1.2, 0);
    return Vec3(i, j, 0);
  });
  const auto id = [](int i, int j) { return j * 5 + i; };
  mesh.faces[1] = {id(1, 0), id(2, 0), id(3, 0), id(1, 1)};
  mesh.faces[2] = {id(3, 0), id(3, 1), id(2, 1), id(1, 1)};
  const QuadQuality q = quad_quality(mesh, nullptr);
  CHECK(q.irregular_interior == 2);
  CHECK(q.valence_interior == std::map<int, std::size_t>{{3, 1}, {4, 7}, {5, 1}});
  CHECK(q.inverted == 0);
  CHECK(q.euler_characteristic == 1);
  CHECK(q.boundary_loops == 1);
  CHECK(q.manifold);
  CHECK(q.consistently_oriented);
}

TEST_CASE("cube: closed, chi 2, eight valence-3 vertices, normal consistency 1/sqrt(3)") {
  PolygonMesh cube;
  for (int k = 0; k < 8; ++k)
    cube.points.emplace_back(k & 1, (k >> 1) & 1, (k >> 2) & 1);
  // outward normals: -z, +z, -y, +y, -x, +x
  cube.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const QuadQuality q = quad_quality(cube, nullptr);
  CHECK(q.euler_characteristic == 2);
  CHECK(q.boundary_loops == 0);
  CHECK(q.manifold);
  CHECK(q.consistently_oriented);
  CHECK(q.irregular_interior == 8);
  CHECK(q.valence_interior == std::map<int, std::size_t>{{3, 8}});
  CHECK(q.valence_boundary.empty());
  // squares (Verdict: 1); the vertex normal is the diagonal direction: (face normal) . n = 1 / sqrt(3)
  CHECK(std::abs(q.min_scaled_jacobian - 1) < 1e-12);
  CHECK(std::abs(q.min_normal_consistency - 1 / std::sqrt(3.0)) < 1e-12);
  CHECK(q.inverted == 0);
  CHECK(std::isnan(q.boundary_alignment_mean));
}

TEST_CASE("two squares touching at one point: not manifold, two boundary loops") {
  PolygonMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
  mesh.faces = {{0, 1, 2, 3}, {2, 4, 5, 6}};
  const QuadQuality q = quad_quality(mesh, nullptr);
  CHECK_FALSE(q.manifold);
  CHECK(q.boundary_loops == 2);
  CHECK(q.euler_characteristic == 1);  // 7 - 8 + 2
}

TEST_CASE("mixed faces are counted; statistics are over quads") {
  PolygonMesh mesh;
  mesh.points = {{0, 0, 0},   {1, 0, 0},    {1, 1, 0},    {0, 1, 0}, {2, 0.5, 0},
                 {0.5, 2, 0}, {-1, 1.5, 0}, {-1, 0.5, 0}, {9, 9, 9}};  // the last one unreferenced
  mesh.faces = {{0, 1, 2, 3}, {1, 4, 2}, {3, 2, 5, 6, 7}};
  const QuadQuality q = quad_quality(mesh, nullptr);
  CHECK(q.vertices == 8);
  CHECK(q.quads == 1);
  CHECK(q.triangles == 1);
  CHECK(q.other_faces == 1);
  CHECK(q.min_scaled_jacobian == doctest::Approx(1.0).epsilon(1e-15));
  // the triangle (1, 0), (2, 0.5), (1, 1): sides sqrt(5)/2, sqrt(5)/2, 1, twice its area 1
  const double side = std::sqrt(5.0) / 2;
  CHECK(std::abs(q.triangle_min_scaled_jacobian - 2 / std::sqrt(3.0) / (side * side)) < 1e-12);
  CHECK(std::abs(q.triangle_min_angle - 2 * std::atan(0.5) * 180 / kPi) < 1e-12);
  CHECK(std::abs(q.triangle_max_angle - std::atan(2.0) * 180 / kPi) < 1e-12);
  CHECK(std::abs(q.triangle_aspect_ratio_max - std::sqrt(3.0) / 6 * side * (2 * side + 1)) < 1e-12);
  CHECK(q.euler_characteristic == 1);  // 8 - 10 + 3
  CHECK(q.boundary_loops == 1);
}

TEST_CASE("Hausdorff distance: own triangulation, shifted copy, a larger reference") {
  const int n = 6, m = 4;
  const PolygonMesh grid = unit_grid(n, m);
  const double diagonal = std::sqrt(double(n * n + m * m));

  SUBCASE("against its own triangulation: zero") {
    for (bool along_13 : {false, true}) {
      const TriangleSoup reference = triangulated(grid, along_13);
      const QuadQuality q = quad_quality(grid, &reference);
      CHECK(q.hausdorff_rel < 1e-12);
      CHECK(q.hausdorff_forward_rel < 1e-12);
      CHECK(q.hausdorff_backward_rel < 1e-12);
    }
  }
  SUBCASE("against a copy moved by d along the normal: d / diagonal") {
    const double d = 0.37;
    TriangleSoup reference = triangulated(grid, true);
    for (Vec3& p : reference.points)
      p.z() += d;
    const QuadQuality q = quad_quality(grid, &reference);
    CHECK(std::abs(q.hausdorff_rel - d / diagonal) < 1e-9);
    CHECK(std::abs(q.hausdorff_forward_rel - d / diagonal) < 1e-9);
    CHECK(std::abs(q.hausdorff_backward_rel - d / diagonal) < 1e-9);

    const TriangleSoup own = triangulated(grid, false);
    const HausdorffDistance h =
        two_sided_hausdorff(own.points, own.triangles, reference.points, reference.triangles);
    CHECK(std::abs(h.forward - d) < 1e-12);
    CHECK(std::abs(h.backward - d) < 1e-12);
    CHECK(std::abs(h.value() - d) < 1e-12);
  }
  SUBCASE("a reference twice as large: only the backward direction sees it") {
    const TriangleSoup reference =
        triangulated(quad_grid(2 * n, 2 * m, [](int i, int j) { return Vec3(i, j, 0); }), false);
    const QuadQuality q = quad_quality(grid, &reference);
    // farthest reference point: the corner (2n, 2m), at distance |(n, m)| from the grid
    CHECK(q.hausdorff_forward_rel < 1e-12);
    CHECK(std::abs(q.hausdorff_backward_rel - 0.5) < 1e-9);
    CHECK(std::abs(q.hausdorff_rel - 0.5) < 1e-9);
    // and where: that corner (a vertex of the reference, hence a sample)
    CHECK((q.hausdorff_at - Vec3(2 * n, 2 * m, 0)).norm() < 1e-12);
    const FarthestSample far = farthest_sample({Vec3(1, 1, 0), Vec3(2 * n, 2 * m, 0), Vec3(n + 1, 0, 0)},
                                               grid.points, triangulated(grid, false).triangles);
    CHECK(far.point == Vec3(2 * n, 2 * m, 0));
    CHECK(std::abs(far.distance - std::sqrt(double(n * n + m * m))) < 1e-12);
  }
}

TEST_CASE("the farthest sample passes over the samples that cannot be it: the same sample and distance as every query") {
  // a bumpy sheet's samples against a flat one: many blocks of samples, most of
  // them near the reference, the farthest at one bump's top; and ties (a flat
  // sheet lifted: every sample at one distance, the first one farthest)
  const int n = 24, m = 18;
  const PolygonMesh flat = unit_grid(n, m);
  const TriangleSoup reference = triangulated(flat, false);
  for (const double bump : {0.8, 0.0}) {
    const PolygonMesh bumpy = quad_grid(n, m, [&](int i, int j) {
      const double r2 = (i - 17.0) * (i - 17.0) + (j - 5.0) * (j - 5.0);
      return Vec3(i, j, 0.25 + bump * std::exp(-r2 / 4) + 0.05 * std::sin(1.3 * i) * std::cos(0.7 * j) * (bump > 0));
    });
    const TriangleSoup sheet = triangulated(bumpy, true);
    const std::vector<Vec3> samples = surface_samples(sheet.points, sheet.triangles);
    REQUIRE(samples.size() > 4000);
    const TriangleTree tree(reference.points, reference.triangles);
    double worst = -1;
    Vec3 at = Vec3::Zero();
    for (const Vec3& s : samples) {
      const double d = tree.squared_distance(s);
      if (d > worst) {
        worst = d;
        at = s;
      }
    }
    const FarthestSample far = farthest_sample(samples, reference.points, reference.triangles);
    CHECK(far.distance == std::sqrt(worst));
    CHECK(far.point == at);
    if (bump > 0) CHECK(at.z() > 0.9);
    else CHECK(at == samples.front());
  }
}

TEST_CASE("surface samples: points, edge points, centroids and interior points") {
  TriangleSoup t;
  t.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};  // the last one unused
  t.triangles = {{0, 1, 2}};
  const std::vector<Vec3> samples = surface_samples(t.points, t.triangles);
  // 3 points, 3 edges x 3 points (k = 4), centroid, 3 interior lattice points
  CHECK(samples.size() == 3 + 9 + 1 + 3);
  for (const Vec3& s : samples)
    CHECK(s.x() + s.y() <= 1 + 1e-15);
  CHECK(bounding_box_diagonal(t.points, t.triangles) == doctest::Approx(std::sqrt(2.0)));
}

TEST_CASE("read_polygon_mesh: quads kept, unreferenced points dropped, bad files refused") {
  const std::string dir = test::scratch_dir("read_polygon_mesh");
  std::ofstream(dir + "/mixed.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 7 7 7\n"
                                       "f 1 2 3 4\nf 2 5 3\n";
  const PolygonMesh obj = io::read_polygon_mesh(dir + "/mixed.obj");
  CHECK(obj.points.size() == 5);
  REQUIRE(obj.faces.size() == 2);
  CHECK(obj.faces[0] == std::vector<int>{0, 1, 2, 3});
  CHECK(obj.faces[1] == std::vector<int>{1, 4, 2});

  // MSH 2.2: two quads, one triangle, one node no element uses
  std::ofstream(dir + "/mixed.msh")
      << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n7\n"
         "1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 1 1 0\n6 2 1 0\n7 9 9 9\n$EndNodes\n"
         "$Elements\n3\n1 3 2 1 1 1 2 5 4\n2 3 2 1 1 2 3 6 5\n3 2 2 1 1 1 5 4\n$EndElements\n";
  const PolygonMesh msh = io::read_polygon_mesh(dir + "/mixed.msh");
  CHECK(msh.points.size() == 6);
  CHECK(msh.faces.size() == 3);
  const QuadQuality q = quad_quality(msh, nullptr);
  CHECK(q.quads == 2);
  CHECK(q.triangles == 1);
  CHECK(q.min_scaled_jacobian == doctest::Approx(1.0));

  const auto refused = [](const std::string& path, const std::string& needle) {
    CAPTURE(path);
    try {
      io::read_polygon_mesh(path);
      FAIL("no error");
    } catch (const Error& e) {
      CHECK(e.code() == ErrorCode::bad_input);
      CHECK(std::string(e.what()).find(needle) != std::string::npos);
    }
  };
  refused(dir + "/missing.obj", "missing.obj: no such file");
  std::ofstream(dir + "/empty.off");
  refused(dir + "/empty.off", "empty.off: empty file");
  std::ofstream(dir + "/points.msh") << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n"
                                        "1 0 0 0\n$EndNodes\n";
  refused(dir + "/points.msh", "points.msh: no triangles or quads found");
}
