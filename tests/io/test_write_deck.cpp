// Solver decks (.inp .bdf .unv): every deck written is read back by an
// independent reader (deck_reader.h) and checked for compact node numbers, the
// 2D elements only with the expected type, a node set (and in .inp an
// element-edge surface) per group, and positive element Jacobians.
#include "io/deck_element.h"
#include "io/write_mesh.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/quality/curved_jacobian.h"
#include "tests/io/deck_fixture.h"
#include "tests/io/deck_reader.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <sstream>

using namespace qm;

namespace {

test::DeckRead read_deck(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return ext == ".inp" ? test::read_inp(path) : ext == ".bdf" ? test::read_bdf(path) : test::read_unv(path);
}

/// The group's points (corners and edge nodes), as deck ids: every point is used,
/// so the deck numbers point k as k + 1.
std::vector<int> expected_set(const io::LineGroup& g) {
  std::set<int> ids;
  for (const auto& e : g.edges) ids.insert({e[0] + 1, e[1] + 1});
  for (int m : g.mids) ids.insert(m + 1);
  return {ids.begin(), ids.end()};
}

double xy_area(const std::vector<Vec3>& p) {
  double a = 0;
  for (std::size_t i = 0; i < 4; ++i) a += p[i].x() * p[(i + 1) % 4].y() - p[(i + 1) % 4].x() * p[i].y();
  return a / 2;
}

/// Checks the deck at `path` against `mesh`, written with element `type`.
void check_deck(const std::string& path, const io::OutputMesh& mesh, const std::string& type, bool plane) {
  CAPTURE(path);
  const test::DeckRead deck = read_deck(path);
  CHECK(deck.line_elements == 0);
  // nodes 1..N, all of them
  REQUIRE(deck.nodes.size() == mesh.points.size());
  CHECK(deck.nodes.begin()->first == 1);
  CHECK(deck.nodes.rbegin()->first == static_cast<int>(mesh.points.size()));
  for (std::size_t k = 0; k < mesh.points.size(); ++k)
    CHECK((deck.nodes.at(static_cast<int>(k) + 1) - mesh.points[k]).norm() < 1e-8);
  // the faces as elements of the type, each with a positive Jacobian
  REQUIRE(deck.elements.size() == mesh.faces.size());
  for (const test::DeckElementRead& e : deck.elements) {
    CHECK(e.type == type);
    CHECK(e.nodes.size() == mesh.faces.front().size());
    const std::vector<Vec3> p = test::element_points(deck, e);
    std::vector<int> local(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) local[i] = static_cast<int>(i);
    CHECK(jacobian_ratio(p, local) > 0.3);
    if (plane) CHECK(xy_area(p) > 0);  // counter-clockwise seen from +z, whatever the faces' order
  }
  // a node set per group
  for (const io::LineGroup& g : mesh.line_groups) {
    CAPTURE(g.name);
    REQUIRE(deck.node_sets.count(g.name) == 1);
    std::vector<int> got = deck.node_sets.at(g.name);
    std::sort(got.begin(), got.end());
    CHECK(got == expected_set(g));
  }
  if (path.substr(path.size() - 4) == ".bdf") return;  // Nastran: the elements' PID says the part
  const auto sets = deck.element_sets.find("surface");
  REQUIRE(sets != deck.element_sets.end());
  CHECK(sets->second.size() == mesh.faces.size());
}

/// In .inp, the surface of each group: one side per edge, each side's corners in
/// the group's node set (sides S1-S4 of plane elements, S3-S6 of shells).
void check_surfaces(const std::string& path, const io::OutputMesh& mesh, bool shell) {
  const test::DeckRead deck = test::read_inp(path);
  std::map<int, const test::DeckElementRead*> by_id;
  for (const auto& e : deck.elements) by_id[e.id] = &e;
  for (const io::LineGroup& g : mesh.line_groups) {
    CAPTURE(g.name);
    REQUIRE(deck.surfaces.count(g.name) == 1);
    const auto& sides = deck.surfaces.at(g.name);
    CHECK(sides.size() == g.edges.size());
    const std::vector<int>& set = deck.node_sets.at(g.name);
    for (const auto& [element, label] : sides) {
      const int s = std::stoi(label.substr(1)) - (shell ? 3 : 1);
      REQUIRE(s >= 0);
      REQUIRE(s < 4);
      const auto& nodes = by_id.at(element)->nodes;
      for (int v : {nodes[static_cast<std::size_t>(s)], nodes[static_cast<std::size_t>((s + 1) % 4)]})
        CHECK(std::find(set.begin(), set.end(), v) != set.end());
    }
  }
}

}  // namespace

TEST_CASE("decks: plane and shell, linear and quadratic, in .inp .bdf .unv read back with sets and types") {
  const std::string dir = test::scratch_dir("write_deck");
  struct Case {
    bool quadratic, clockwise;
    double bend;
    std::string inp;
    std::string unv;
  };
  for (const Case& c : {Case{false, false, 0, "CPS4", "44"}, Case{true, false, 0, "CPS8", "45"},
                       Case{false, true, 0, "CPS4", "44"}, Case{true, true, 0, "CPS8", "45"},
                       Case{false, false, 3, "S4", "94"}, Case{true, false, 3, "S8R", "95"}}) {
    CAPTURE(c.inp);
    CAPTURE(c.clockwise);
    test::RectangleDeckOptions o;
    o.quadratic = c.quadratic;
    o.clockwise = c.clockwise;
    o.bend_radius = c.bend;
    const io::OutputMesh mesh = test::rectangle_deck_mesh(o);
    const bool plane = c.bend == 0;
    io::write_mesh(dir + "/r.inp", mesh);
    check_deck(dir + "/r.inp", mesh, c.inp, plane);
    check_surfaces(dir + "/r.inp", mesh, !plane);
    io::write_mesh(dir + "/r.bdf", mesh);
    check_deck(dir + "/r.bdf", mesh, c.quadratic ? "CQUAD8" : "CQUAD4", false);
    io::write_mesh(dir + "/r.unv", mesh);
    check_deck(dir + "/r.unv", mesh, c.unv, plane);
  }
}

TEST_CASE("decks: --element-type picks the type, and one that does not fit is refused") {
  const std::string dir = test::scratch_dir("write_deck_types");
  const io::OutputMesh flat = test::rectangle_deck_mesh({});
  io::WriteOptions w;
  w.element_type = "s4r";
  io::write_mesh(dir + "/r.inp", flat, w);
  check_deck(dir + "/r.inp", flat, "S4R", false);
  check_surfaces(dir + "/r.inp", flat, true);
  w.element_type = "plane-strain";
  io::write_mesh(dir + "/r.unv", flat, w);
  check_deck(dir + "/r.unv", flat, "54", true);

  CHECK_THROWS_AS(io::check_element_request(dir + "/x.inp", 4, "CQUAD4"), Error);
  CHECK_THROWS_AS(io::check_element_request(dir + "/x.inp", 8, "CPS4"), Error);
  CHECK_THROWS_AS(io::check_element_request(dir + "/x.msh", 4, "S4"), Error);
  CHECK_THROWS_AS(io::check_element_request(dir + "/x.inp", 9, ""), Error);
  CHECK_THROWS_AS(io::check_element_request(dir + "/x.obj", 8, ""), Error);
  CHECK_THROWS_AS(io::check_element_request(dir + "/x.su2", 8, ""), Error);
  CHECK_NOTHROW(io::check_element_request(dir + "/x.msh", 9, ""));
  CHECK_NOTHROW(io::check_element_request(dir + "/x.bdf", 8, "cquad8"));
  CHECK_NOTHROW(io::check_element_request(dir + "/x.inp", 8, "S8R"));
  // a plane element for a bent part, and quadratic quads where the format has none
  test::RectangleDeckOptions bent;
  bent.bend_radius = 3;
  w.element_type = "CPS4";
  CHECK_THROWS_AS(io::write_mesh(dir + "/bent.inp", test::rectangle_deck_mesh(bent), w), Error);
  test::RectangleDeckOptions quadratic;
  quadratic.quadratic = true;
  CHECK_THROWS_AS(io::write_mesh(dir + "/q.obj", test::rectangle_deck_mesh(quadratic)), Error);
  CHECK_FALSE(std::filesystem::exists(dir + "/bent.inp"));
  CHECK_FALSE(std::filesystem::exists(dir + "/q.obj"));
}

TEST_CASE("decks: a triangle mesh gives triangles of the same kind; nodes no face uses are left out") {
  const std::string dir = test::scratch_dir("write_deck_triangles");
  io::OutputMesh mesh;
  mesh.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {5, 5, 5}};  // point 4 is used by no face
  mesh.faces = {{0, 1, 2}, {0, 2, 3}};
  io::write_mesh(dir + "/t.inp", mesh);
  const test::DeckRead deck = test::read_inp(dir + "/t.inp");
  CHECK(deck.nodes.size() == 4);
  REQUIRE(deck.elements.size() == 2);
  CHECK(deck.elements[0].type == "CPS3");
}

TEST_CASE("decks: quadratic quads in .msh are 8-node quads with 3-node boundary lines") {
  const std::string dir = test::scratch_dir("write_deck_msh");
  test::RectangleDeckOptions o;
  o.quadratic = true;
  io::WriteOptions v22;
  v22.msh_version = 2.2;
  io::write_mesh(dir + "/q.msh", test::rectangle_deck_mesh(o), v22);
  const std::string text = test::slurp(dir + "/q.msh");
  // MSH 2.2 element lines: id type ntags ...; type 16 = 8-node quad, 8 = 3-node line
  std::size_t quads = 0, lines = 0;
  std::istringstream in(text);
  std::string line;
  bool elements = false;
  while (std::getline(in, line)) {
    if (line == "$Elements") {
      elements = true;
      std::getline(in, line);
      continue;
    }
    if (line == "$EndElements") elements = false;
    if (!elements) continue;
    std::istringstream words(line);
    int id = 0, type = 0;
    words >> id >> type;
    quads += type == 16;
    lines += type == 8;
  }
  CHECK(quads == 8);
  CHECK(lines == 12);
}
