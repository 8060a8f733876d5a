// quadmesh render: the picture of a small known mesh (which faces show, which
// vertices are marked, what the caption counts), the pure parts it is made of
// (the view, the visibility, the colours, the irregular vertices) and the
// command as a user runs it.
#include "libquadmesh/quality/quad_quality.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"
#include "tests/support/xml_check.h"
#include "tools/render/face_coloring.h"
#include "tools/render/irregular_vertices.h"
#include "tools/render/mesh_svg.h"
#include "tools/render/visible_faces.h"

#include <Eigen/Geometry>
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>

using namespace qm;
using namespace qm::tools;
using qm::test::parse_xml;
using qm::test::XmlElement;

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Appends `part` to `mesh` (its points after the mesh's).
void append(PolygonMesh& mesh, const PolygonMesh& part) {
  const int offset = static_cast<int>(mesh.points.size());
  mesh.points.insert(mesh.points.end(), part.points.begin(), part.points.end());
  for (std::vector<int> face : part.faces) {
    for (int& v : face) v += offset;
    mesh.faces.push_back(face);
  }
}

/// nx x ny unit quads at height z from (x0, y0), CCW seen from +z.
PolygonMesh grid(int nx, int ny, double z, double x0 = 0, double y0 = 0) {
  PolygonMesh m;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) m.points.emplace_back(x0 + i, y0 + j, z);
  const auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) m.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return m;
}

/// A regular k-gon of circumradius 1 centred at (x0, 0, 0), split into k quads
/// round its centre (point 0): the centre has valence k, every other vertex is
/// regular (the midpoints have two faces and 180 degrees, the corners one face).
/// Each quad's corner angles: 360/k at the centre, 90 at the midpoints, 180 - 360/k
/// at the corner.
PolygonMesh star(int k, double x0) {
  PolygonMesh m;
  m.points.emplace_back(x0, 0, 0);
  for (int i = 0; i < k; ++i) {  // corner 2i + 1, then the midpoint of corners i and i + 1
    const double a = 2 * kPi * i / k, b = 2 * kPi * (i + 1) / k;
    m.points.emplace_back(x0 + std::cos(a), std::sin(a), 0);
    m.points.emplace_back(x0 + (std::cos(a) + std::cos(b)) / 2, (std::sin(a) + std::sin(b)) / 2, 0);
  }
  for (int i = 0; i < k; ++i) {
    const int corner = 2 * i + 1, before = i == 0 ? 2 * k : 2 * i, after = 2 * i + 2;
    m.faces.push_back({0, before, corner, after});
  }
  return m;
}

/// The known mesh: a pentagon of 5 quads (centre valence 5, point 0), a triangle
/// of 3 quads (centre valence 3, point 11) and a unit square split into two
/// triangles (its two diagonal corners, points 18 and 20, have two faces where
/// one is regular: irregular boundary vertices), all in the plane z = 0.
PolygonMesh known_mesh() {
  PolygonMesh m = star(5, 0.0);
  append(m, star(3, 3.0));
  PolygonMesh square;
  square.points = {Vec3(5, -0.5, 0), Vec3(6, -0.5, 0), Vec3(6, 0.5, 0), Vec3(5, 0.5, 0)};
  square.faces = {{0, 1, 2}, {0, 2, 3}};
  append(m, square);
  return m;
}

std::vector<XmlElement> parsed(const std::string& svg) {
  std::vector<XmlElement> elements;
  std::string why;
  CHECK_MESSAGE(parse_xml(svg, elements, why), why);
  return elements;
}

std::size_t count_named(const std::vector<XmlElement>& elements, const std::string& name) {
  return static_cast<std::size_t>(
      std::count_if(elements.begin(), elements.end(), [&](const XmlElement& e) { return e.name == name; }));
}

std::string text_with_id(const std::vector<XmlElement>& elements, const std::string& id) {
  for (const XmlElement& e : elements) {
    const auto it = e.attributes.find("id");
    if (it != e.attributes.end() && it->second == id) return e.text;
  }
  return "";
}

MeshPicture picture_of(const PolygonMesh& mesh, const Vec3& toward, MeshPictureOptions options = {}) {
  const View view = view_toward(toward);
  return mesh_picture(mesh, quad_quality(mesh, nullptr), view, frame_fitting(mesh.points, view, 400, 400),
                      options);
}

void write_quad_obj(const PolygonMesh& mesh, const std::string& path) {
  std::ofstream out(path);
  for (const Vec3& p : mesh.points) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const auto& face : mesh.faces) {
    out << 'f';
    for (int v : face) out << ' ' << v + 1;
    out << '\n';
  }
}

}  // namespace

TEST_CASE("irregular_vertices: the vertices quad_quality counts, one by one") {
  const PolygonMesh mesh = known_mesh();
  const std::vector<IrregularVertex> irregular = irregular_vertices(mesh);
  REQUIRE(irregular.size() == 4);
  CHECK(irregular[0].vertex == 0);
  CHECK(irregular[0].valence == 5);
  CHECK_FALSE(irregular[0].boundary);
  CHECK(irregular[1].vertex == 11);
  CHECK(irregular[1].valence == 3);
  CHECK_FALSE(irregular[1].boundary);
  CHECK(irregular[2].vertex == 18);  // the split square's diagonal: 2 triangles where 90 degrees wants 1 face
  CHECK(irregular[2].boundary);
  CHECK(irregular[2].valence == 2);
  CHECK(irregular[2].regular == 1);
  CHECK(irregular[3].vertex == 20);

  // the same counts as the quality module, on meshes with many irregular vertices
  std::vector<PolygonMesh> meshes = {mesh, grid(4, 3, 0), star(6, 0), star(7, 1)};
  for (const TriangleSoup& soup : {test::annulus(1.0, 2.0, 3, 16), test::grid(5), test::torus(3, 1, 12, 8)}) {
    PolygonMesh triangles;
    triangles.points = soup.points;
    for (const Triangle& t : soup.triangles) triangles.faces.push_back({t[0], t[1], t[2]});
    meshes.push_back(triangles);
  }
  for (const PolygonMesh& m : meshes) {
    const QuadQuality q = quad_quality(m, nullptr);
    const auto found = irregular_vertices(m);
    const auto boundary = static_cast<std::size_t>(
        std::count_if(found.begin(), found.end(), [](const IrregularVertex& x) { return x.boundary; }));
    CHECK(found.size() - boundary == q.irregular_interior);
    CHECK(boundary == q.irregular_boundary);
  }
  CHECK(irregular_vertices(grid(4, 3, 0)).empty());
}

TEST_CASE("most_area_direction: a flat mesh's normal; two planes' area-weighted sum") {
  const Vec3 flat = most_area_direction(grid(3, 2, 1.0));
  CHECK((flat - Vec3::UnitZ()).norm() < 1e-12);

  // a 2 x 1 floor (normal +z, area 2) and a 1 x 1 wall in the plane y = 0 facing
  // -y (area 1): the most area shows from (0, -1, 2) / sqrt 5, sqrt 5 = 2.236 of it
  PolygonMesh l_shape = grid(2, 1, 0.0);
  PolygonMesh wall;
  wall.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 1)};
  wall.faces = {{0, 1, 2, 3}};  // (1,0,0) x (0,0,1) = -y
  append(l_shape, wall);
  const Vec3 d = most_area_direction(l_shape);
  CHECK((d - Vec3(0, -1, 2).normalized()).norm() < 1e-12);

  // a tilted plate shows its own normal
  PolygonMesh tilted = grid(3, 3, 0.0);
  const Eigen::Matrix3d turn = Eigen::AngleAxisd(0.7, Vec3(1, 2, 0).normalized()).toRotationMatrix();
  for (Vec3& p : tilted.points) p = turn * p;
  CHECK((most_area_direction(tilted) - turn * Vec3::UnitZ()).norm() < 1e-12);
}

TEST_CASE("view_toward: a right-handed frame with z up, y up seen from above") {
  const View top = view_toward(Vec3(0, 0, 5));
  CHECK((top.right - Vec3::UnitX()).norm() < 1e-15);
  CHECK((top.up - Vec3::UnitY()).norm() < 1e-15);
  const View side = view_toward(Vec3(1, -1, 0.5));
  CHECK(side.up.z() > 0.9);
  CHECK((side.right.cross(side.up) - side.toward_viewer).norm() < 1e-12);
  CHECK(std::abs(side.up.dot(side.toward_viewer)) < 1e-12);
}

TEST_CASE("visible_faces: faces behind nearer ones are left out, painted farthest first") {
  // a 4 x 4 grid at z = 0 over [0,4]^2; a 2 x 2 grid at z = -1 under its middle
  // (faces 16-19); one quad at z = -1 beside it (face 20)
  PolygonMesh mesh = grid(4, 4, 0.0);
  append(mesh, grid(2, 2, -1.0, 1, 1));
  append(mesh, grid(1, 1, -1.0, 5, 0));
  const auto shown = [&](const Vec3& toward) {
    const View view = view_toward(toward);
    const std::vector<DrawnFace> faces = visible_faces(mesh, view, frame_fitting(mesh.points, view, 300, 300));
    for (std::size_t i = 1; i < faces.size(); ++i) CHECK(faces[i - 1].depth <= faces[i].depth);
    std::set<int> ids;
    for (const DrawnFace& f : faces) ids.insert(f.face);
    return std::make_pair(ids, faces);
  };
  const auto [from_above, above_faces] = shown(Vec3::UnitZ());
  std::set<int> expected;
  for (int f = 0; f < 16; ++f) expected.insert(f);
  expected.insert(20);
  CHECK(from_above == expected);
  for (const DrawnFace& f : above_faces) CHECK(f.facing == doctest::Approx(1.0));

  // from below, the small grid hides the big one's middle four (5, 6, 9, 10); every back shows
  const auto [from_below, below_faces] = shown(-Vec3::UnitZ());
  expected = {0, 1, 2, 3, 4, 7, 8, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20};
  CHECK(from_below == expected);
  for (const DrawnFace& f : below_faces) CHECK(f.facing == doctest::Approx(-1.0));

  // seen edge-on, nothing has an area
  const View edge = view_toward(Vec3::UnitX());
  CHECK(visible_faces(grid(2, 2, 0.0), edge, frame_fitting(grid(2, 2, 0.0).points, edge, 100, 100)).empty());
}

TEST_CASE("face_values: Verdict's figures of the known quads") {
  const PolygonMesh mesh = known_mesh();
  const std::vector<double> sj = face_values(mesh, FaceColoring::scaled_jacobian, 1.0);
  const std::vector<double> angle = face_values(mesh, FaceColoring::angle_deviation, 1.0);
  REQUIRE(sj.size() == 10);
  for (int f = 0; f < 5; ++f) {  // pentagon quads: corners 72, 90, 108, 90 degrees
    CHECK(sj[f] == doctest::Approx(std::sin(72 * kPi / 180)).epsilon(1e-12));
    CHECK(angle[f] == doctest::Approx(18.0).epsilon(1e-12));
  }
  for (int f = 5; f < 8; ++f) {  // triangle quads: corners 120, 90, 60, 90 degrees
    CHECK(sj[f] == doctest::Approx(std::sin(60 * kPi / 180)).epsilon(1e-12));
    CHECK(angle[f] == doctest::Approx(30.0).epsilon(1e-12));
  }
  // the right isosceles triangles: Verdict's triangle scaled Jacobian, 2/sqrt(3) sin 45 degrees
  CHECK(sj[8] == doctest::Approx(2 / std::sqrt(3.0) * std::sqrt(0.5)).epsilon(1e-12));
  CHECK(std::isnan(angle[8]));
  const std::vector<double> size = face_values(grid(1, 1, 0.0), FaceColoring::size, 0.5);
  CHECK(size[0] == doctest::Approx(2.0));
  CHECK(std::isnan(face_values(mesh, FaceColoring::none, 1.0)[0]));

  const ColorScale scale = color_scale(FaceColoring::scaled_jacobian);
  CHECK(hex(color_of(scale, 1.0)) == "#2c7bb6");
  CHECK(hex(color_of(scale, 0.5)) == "#ffffbf");
  CHECK(hex(color_of(scale, 0.0)) == "#40004b");  // inverted
  CHECK(hex(color_of(scale, 0.25)) == "#fdae61");
  CHECK(hex(color_of(color_scale(FaceColoring::size), 1.0)) == "#f7f7f7");
  CHECK(hex(color_of(color_scale(FaceColoring::size), 4.0)) == "#e66101");
}

TEST_CASE("mesh_picture of the known mesh: well-formed, one polygon per face, the irregular vertices marked, "
          "the counts in the caption") {
  const PolygonMesh mesh = known_mesh();
  MeshPictureOptions options;
  options.title = "known <mesh> & co";  // escaped
  const MeshPicture picture = picture_of(mesh, most_area_direction(mesh), options);
  const std::vector<XmlElement> svg = parsed(picture.svg);
  REQUIRE(!svg.empty());
  CHECK(svg[0].name == "svg");
  CHECK(picture.faces_drawn == 10);
  CHECK(count_named(svg, "polygon") == 10);
  CHECK(text_with_id(svg, "title") == "known <mesh> & co");

  std::map<int, int> marked;  // vertex -> valence
  for (const XmlElement& e : svg)
    if (e.name == "circle" && e.attributes.count("data-vertex"))
      marked[std::stoi(e.attributes.at("data-vertex"))] = std::stoi(e.attributes.at("data-valence"));
  CHECK(marked == std::map<int, int>{{0, 5}, {11, 3}});
  CHECK(picture.marked == 2);

  CHECK(text_with_id(svg, "caption-counts") == "8 quads, 2 triangles, 22 vertices; 10 faces shown");
  CHECK(text_with_id(svg, "caption-irregular") ==
        "irregular vertices: 2 interior (valence 3: 1, 5: 1), 2 boundary (not marked)");
  CHECK(text_with_id(svg, "caption-figures") == "scaled Jacobian (Verdict): min 0.866, mean 0.919; 0 inverted");
  CHECK(text_with_id(svg, "caption-view") == "seen from (0.000, 0.000, 1.000) (--view), hidden faces removed");
}

TEST_CASE("mesh_picture: hidden faces are not drawn; colours are the scale's, shaded by the view") {
  PolygonMesh mesh = grid(4, 4, 0.0);
  append(mesh, grid(2, 2, -1.0, 1, 1));
  append(mesh, grid(1, 1, -1.0, 5, 0));
  const std::vector<XmlElement> svg = parsed(picture_of(mesh, Vec3::UnitZ()).svg);
  CHECK(count_named(svg, "polygon") == 17);
  // every quad is a unit square (scaled Jacobian 1) seen face-on: the scale's best colour, full light
  for (const XmlElement& e : svg)
    if (e.name == "polygon") CHECK(e.attributes.at("fill") == "#2c7bb6");
  // from an angle of 60 degrees the light is 0.55 + 0.45 cos 60 = 0.775 of it
  const std::vector<XmlElement> tilted = parsed(picture_of(grid(1, 1, 0.0), Vec3(0, -std::sqrt(3.0), 1)).svg);
  const Rgb best = color_of(color_scale(FaceColoring::scaled_jacobian), 1.0);
  for (const XmlElement& e : tilted)
    if (e.name == "polygon") CHECK(e.attributes.at("fill") == hex({0.775 * best.r, 0.775 * best.g, 0.775 * best.b}));
}

TEST_CASE("mesh_picture: edges of a median under 2.5 px on screen are not drawn, and the caption says so") {
  const PolygonMesh fine = grid(300, 300, 0.0);  // 400 px wide: 1.3 px per edge
  const std::vector<XmlElement> svg = parsed(picture_of(fine, Vec3::UnitZ()).svg);
  CHECK(count_named(svg, "polygon") == 90000);
  for (const XmlElement& e : svg)
    if (e.attributes.count("id") && e.attributes.at("id") == "faces") CHECK(e.attributes.at("stroke") == "none");
  CHECK(text_with_id(svg, "caption-view").find("; edges not drawn (median 1.3 px)") != std::string::npos);
  const std::vector<XmlElement> coarse = parsed(picture_of(grid(100, 100, 0.0), Vec3::UnitZ()).svg);  // 3.9 px
  for (const XmlElement& e : coarse)
    if (e.attributes.count("id") && e.attributes.at("id") == "faces") CHECK(e.attributes.at("stroke") == "#1a1a1a");
}

TEST_CASE("quadmesh render: the picture of a mesh file; bad input and bad options leave no file") {
  const std::string dir = test::scratch_dir("render_cli");
  const std::string input = dir + "/known.obj";
  write_quad_obj(known_mesh(), input);
  const std::string picture = dir + "/known.svg";
  const test::Run run = test::quadmesh("render " + test::quoted(input) + " -o " + test::quoted(picture) +
                                       " --color angle -q");
  CHECK(run.status == 0);
  CHECK(run.out.find("10 of 10 faces shown, 2 singular vertices marked") != std::string::npos);
  const std::vector<XmlElement> svg = parsed(test::slurp(picture));
  CHECK(count_named(svg, "polygon") == 10);
  CHECK(text_with_id(svg, "caption-figures").rfind("corner angle deviation |angle - 90|: mean ", 0) == 0);

  const auto refused = [&](const std::string& args, int status, const std::string& needle) {
    CAPTURE(args);
    const std::string out = dir + "/refused.svg";
    const test::Run r = test::quadmesh("render " + args);
    CHECK(r.status == status);
    const auto lines = r.error_lines();
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].find(needle) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(out));
    CHECK_FALSE(std::filesystem::exists(dir + "/refused.png"));
  };
  const std::string out = " -o " + test::quoted(dir + "/refused.svg");
  refused(test::quoted(input) + " -o " + test::quoted(dir + "/refused.png"), 2, "ending in .svg");
  refused(test::quoted(input) + out + " --view 0,0,0", 2, "--view 0,0,0: must be three finite numbers");
  refused(test::quoted(input) + out + " --view 1,2", 2, "--view 1,2");
  refused(test::quoted(input) + out + " --color rainbow", 2, "--color rainbow: must be one of sj, angle, size, none");
  std::filesystem::create_directory(dir + "/folder.svg");
  refused(test::quoted(input) + " -o " + test::quoted(dir + "/folder.svg"), 2, "is a folder, not a file");
  refused(test::quoted(input) + " -o " + test::quoted(dir + "/missing/refused.svg"), 2, "does not exist");
  const std::string broken = dir + "/broken.obj";
  std::ofstream(broken) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
  refused(test::quoted(broken) + out, 3, "broken.obj");
  const std::string nan_point = dir + "/nan.obj";
  std::ofstream(nan_point) << "v 0 0 0\nv 1 0 nan\nv 1 1 0\nf 1 2 3\n";
  refused(test::quoted(nan_point) + out, 3, "nan.obj");
}
