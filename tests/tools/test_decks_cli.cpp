// `quadmesh mesh` writing solver decks and quadratic quads: bad requests refused
// with one line before any work; the plate with two holes as .inp, order 1 and 2,
// read back and (when ccx is installed) solved as a user would.
#include "libquadmesh/quality/curved_jacobian.h"
#include "tests/io/deck_reader.h"
#include "tests/support/ccx_run.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>

using namespace qm;

namespace {

void expect_usage_error(const std::string& options, const std::string& output, const std::string& needle) {
  CAPTURE(options);
  const std::string dir = test::scratch_dir("decks_cli_refusal");
  const test::Run run =
      test::quadmesh("mesh " + test::quoted(test::example("plate-two-holes.geo")) + " -o " +
                     test::quoted(dir + "/" + output) + " " + options);
  CHECK(run.status == 2);
  const auto lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].find(needle) != std::string::npos);
  CHECK(std::filesystem::is_empty(dir));
}

}  // namespace

TEST_CASE("mesh: --order, --complete and --element-type that do not fit are refused with one line") {
  expect_usage_error("--order 3", "p.inp", "--order 3");
  expect_usage_error("--order 0", "p.msh", "--order 0");
  expect_usage_error("--complete", "p.msh", "--complete");
  expect_usage_error("--element-type CQUAD4", "p.inp", "--element-type CQUAD4");
  expect_usage_error("--element-type CPS4 --order 2", "p.inp", "--element-type CPS4");
  expect_usage_error("--element-type S4", "p.msh", "not a solver deck");
  expect_usage_error("--order 2", "p.obj", "cannot hold 8-node quads");
  expect_usage_error("--order 2", "p.su2", "cannot hold 8-node quads");
  expect_usage_error("--order 2 --complete", "p.inp", "cannot hold 9-node quads");
}

TEST_CASE("mesh: the plate with two holes as .inp, order 1 and 2, runs in ccx as written" *
          doctest::test_suite("slow")) {
  const std::string dir = test::scratch_dir("decks_cli_plate");
  for (int order : {1, 2}) {
    CAPTURE(order);
    const std::string inp = dir + "/p" + std::to_string(order) + ".inp";
    const std::string report = dir + "/p" + std::to_string(order) + ".json";
    const test::Run run = test::quadmesh("mesh -q " + test::quoted(test::example("plate-two-holes.geo")) + " -o " +
                                         test::quoted(inp) + " --order " + std::to_string(order) + " --report " +
                                         test::quoted(report));
    REQUIRE(run.status == 0);
    const test::DeckRead deck = test::read_inp(inp);
    CHECK(deck.line_elements == 0);
    for (const char* group : {"hole_left", "hole_right", "outer"}) CHECK(deck.node_sets.count(group) == 1);
    for (const char* group : {"hole_left", "hole_right", "outer"}) CHECK(deck.surfaces.count(group) == 1);
    for (const auto& e : deck.elements) {
      CHECK(e.type == (order == 1 ? "CPS4" : "CPS8"));
      std::vector<int> local(e.nodes.size());
      for (std::size_t i = 0; i < local.size(); ++i) local[i] = static_cast<int>(i);
      CHECK(jacobian_ratio(test::element_points(deck, e), local) > 0);
    }
    // every node of a hole's set near the CAD circle (radius 10; at order 1 the
    // corners lie on Gmsh's triangulation of it), and the edge nodes exactly on it
    std::map<int, const test::DeckElementRead*> by_id;
    for (const auto& e : deck.elements) by_id[e.id] = &e;
    for (const auto& [group, cx] : {std::pair<const char*, double>{"hole_left", 30}, {"hole_right", 70}}) {
      const auto radius = [cx = cx](const Vec3& p) { return std::hypot(p.x() - cx, p.y() - 30); };
      // order 2: corners too, moved from the triangulation's chords onto the curve
      for (int v : deck.node_sets.at(group))
        CHECK(radius(deck.nodes.at(v)) == doctest::Approx(10).epsilon(order == 1 ? 1e-2 : 1e-9));
      if (order == 1) continue;
      for (const auto& [element, label] : deck.surfaces.at(group)) {
        const int side = std::stoi(label.substr(1)) - 1;
        const int node = by_id.at(element)->nodes.at(static_cast<std::size_t>(4 + side));
        CHECK(radius(deck.nodes.at(node)) == doctest::Approx(10).epsilon(1e-9));
      }
    }
    const auto json = nlohmann::json::parse(test::slurp(report));
    if (order == 2) {
      CHECK(json["quality"]["min_jacobian_ratio"].get<double>() > 0);
      CHECK(json["order"]["nodes_on_cad_curves"].get<int>() > 0);
    }
    if (!test::ccx_installed()) continue;
    test::TensionStep step;
    step.fixed_x = "hole_left";  // held at the left hole, pulled at the right one
    step.fixed_y = "hole_left";
    step.loaded = "hole_right";
    const std::optional<double> energy = test::ccx_strain_energy(inp, "p" + std::to_string(order) + "_run", step);
    REQUIRE(energy.has_value());
    CHECK(*energy > 0);
  }
}
