// A deck of ours runs in CalculiX as written, once a user appends a material, a
// section and a step: a rectangle in uniform tension, whose strain energy
// sigma^2 / (2E) x volume every element type here reproduces exactly (the patch
// test), on distorted quads. Skipped (with a message) when ccx is not installed.
#include "io/write_mesh.h"
#include "tests/io/deck_fixture.h"
#include "tests/support/ccx_run.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

using namespace qm;

TEST_CASE("ccx solves a rectangle in tension on our decks to the exact strain energy") {
  if (!test::ccx_installed()) {
    MESSAGE("ccx is not installed: the deck is not solved (scripts/setup-deps installs calculix-ccx)");
    return;
  }
  const std::string dir = test::scratch_dir("deck_solve");
  test::TensionStep step;
  step.fixed_x = "left";
  step.fixed_y = "bottom";
  step.loaded = "right";
  // sigma^2 / (2 E) x area x thickness, for the 2 x 1 rectangle
  const double exact = step.traction * step.traction / (2 * step.young) * 2.0 * step.thickness;
  struct Case {
    std::string name;
    bool quadratic, clockwise;
    std::string element_type;
    bool shell;
  };
  for (const Case& c : {Case{"cps4", false, true, "", false}, Case{"cps8", true, false, "", false},
                       Case{"s4", false, false, "S4", true}, Case{"s8r", true, true, "S8R", true}}) {
    CAPTURE(c.name);
    test::RectangleDeckOptions o;
    o.quadratic = c.quadratic;
    o.clockwise = c.clockwise;
    io::WriteOptions w;
    w.element_type = c.element_type;
    const std::string part = dir + "/" + c.name + "_part.inp";
    io::write_mesh(part, test::rectangle_deck_mesh(o), w);
    step.shell = c.shell;
    const std::optional<double> energy = test::ccx_strain_energy(part, c.name, step);
    REQUIRE(energy.has_value());
    // CalculiX expands S4 into C3D8I, whose incompatible modes miss the patch test
    // on distorted quads by about 1e-4; the plane elements and S8R are exact
    CHECK(*energy == doctest::Approx(exact).epsilon(c.name == "s4" ? 1e-3 : 1e-6));
  }
}
