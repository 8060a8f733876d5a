// The quadmesh program as a user runs it: exit codes, one-line messages on
// stderr that name the problem and where, and never a partial output file.
#include "io/read_surface.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace qm;

namespace {

using test::quadmesh;
using test::quoted;
using test::Run;
using test::slurp;

/// `quadmesh mesh INPUT -o OUT.msh` must fail with `status`, print one error line
/// containing `needle`, and leave no output file.
void expect_refusal(const std::string& input, int status, const std::string& needle) {
  CAPTURE(input);
  const std::string dir = test::scratch_dir("cli_refusal");
  const std::string output = dir + "/out.msh";
  const Run run = quadmesh("mesh " + quoted(input) + " -o " + quoted(output));
  CHECK(run.status == status);
  const auto lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: error: ", 0) == 0);
  CHECK(lines[0].find(needle) != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(output));
  CHECK(std::filesystem::is_empty(dir));
}

}  // namespace

TEST_CASE("info --json gives the MANIFEST numbers") {
  for (const char* name : {"kitten-2holes.obj", "pig.off", "hinge.stl"}) {
    CAPTURE(name);
    const Run run = quadmesh("info --json " + quoted(test::shared_mesh(name)));
    CHECK(run.status == 0);
    const auto j = nlohmann::json::parse(run.out);
    for (const auto& m : test::manifest()) {
      if (m.file != name) continue;
      CHECK(j["vertices"] == m.vertices);
      CHECK(j["faces"] == m.faces);
      CHECK(j["boundary_loops"] == m.boundary_loops);
      CHECK(j["genus"] == m.genus);
      CHECK(j["euler_characteristic"] == m.euler_characteristic);
      CHECK(j["manifold"] == true);
      CHECK(j["orientable"] == true);
      CHECK(j["components"] == 1);
      CHECK(j["supported"] == true);
      CHECK(j["reason"].get<std::string>().find("supported") != std::string::npos);
    }
  }
}

TEST_CASE("info in words, and its exit status follows the verdict") {
  const Run run = quadmesh("info " + quoted(test::shared_mesh("kitten-2holes.obj")));
  CHECK(run.status == 0);
  CHECK(run.out.find("genus 1 with 2 boundaries, chi = -2: supported; the doubled surface has "
                     "genus 3") != std::string::npos);

  const Run ogre = quadmesh("info --json " + quoted(test::shared_mesh("ogre-body-pinched.obj")));
  CHECK(ogre.status == 3);
  const auto j = nlohmann::json::parse(ogre.out);
  CHECK(j["manifold"] == false);
  CHECK(j["supported"] == false);
  CHECK(j["boundary_loops"] == 8);
  CHECK(j["genus"] == 1);
  CHECK(j["euler_characteristic"] == -8);
}

TEST_CASE("mesh: a closed surface passes every check, then 'not implemented yet' (exit 4)") {
  const std::string dir = test::scratch_dir("cli_closed");
  test::write_obj(test::torus(3, 1, 24, 12), dir + "/torus.obj");
  expect_refusal(dir + "/torus.obj", 4, "closed surfaces is not implemented yet");
}

/// The issue 4 acceptance, through the program: report, output file, groups, and
/// no warning.
void expect_quad_mesh(const std::string& input, const std::string& size, int chi, int loops,
                      const std::vector<std::string>& curve_groups) {
  CAPTURE(input);
  const std::string dir = test::scratch_dir("cli_mesh");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(input) + " -o " + quoted(output) + " --size " + size +
                           " --report " + quoted(report));
  REQUIRE(run.status == 0);
  CHECK(run.out.find("irregular vertices") != std::string::npos);  // the summary
  CHECK(run.err.find("] extracting the quads") != std::string::npos);  // progress lines
  const auto j = nlohmann::json::parse(slurp(report));
  const auto& q = j["quality"];
  CHECK(q["triangles"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(run.err.find("warning: ") == std::string::npos);
  // the criteria as the report states them (pipeline/acceptance_criteria.h)
  const auto& criteria = j["acceptance"];
  CHECK(q["hausdorff_rel"].get<double>() <= criteria["max_hausdorff_relative"].get<double>());
  CHECK(q["euler_characteristic"] == chi);
  CHECK(q["boundary_loops"] == loops);
  CHECK(q["irregular_interior"] == j["expected"]["irregular_interior"]);
  CHECK(q["min_scaled_jacobian"].get<double>() >= criteria["min_scaled_jacobian"].get<double>());
  CHECK(q["angle_dev_mean"].get<double>() <= criteria["max_mean_angle_deviation_deg"].get<double>());
  const double quads = q["quads"].get<double>(), target = j["expected"]["quads"].get<double>();
  CHECK(std::abs(quads - target) <= 0.15 * target);
  // the stages of the route kept: the Abel differential's quantization, or the cones' seamless map
  const bool cones = j["singularities"]["route"] == "cones";
  for (const char* key : {cones ? "cone_map" : "quantization", "extraction", "total"})
    CHECK(j["timings"].contains(key));
  // the forms, and their residual, wherever the Abel route ran (not where the cones were kept before it)
  const bool abel_ran = !j["singularities"]["abel_size_band_share"].is_null();
  CHECK(j["timings"].contains("forms") == abel_ran);
  CHECK(j["form"]["hodge_star_squared"].is_null() == !abel_ran);
  // the file read back by another command, with its physical groups
  const Run back = quadmesh("quality " + quoted(output) + " --json");
  REQUIRE(back.status == 0);
  CHECK(nlohmann::json::parse(back.out)["quads"] == q["quads"]);
  const std::string msh = slurp(output);
  const std::string names = msh.substr(msh.find("$PhysicalNames"), msh.find("$EndPhysicalNames") - msh.find("$PhysicalNames"));
  CHECK(names.find("\"surface\"") != std::string::npos);
  for (const std::string& group : curve_groups) CHECK(names.find("\"" + group + "\"") != std::string::npos);
}

TEST_CASE("mesh: pure quads with the input's topology, quality and groups (plate, kitten)" *
          doctest::test_suite("slow")) {
  expect_quad_mesh(test::example("plate-two-holes.geo"), "2", -1, 3, {"hole_left", "hole_right", "outer"});
  // kitten's ears: 1.5% of the diagonal after chord refinement; corners moved onto
  // their tips (extract/quad_fitting.h) bring that under 1%
  expect_quad_mesh(test::shared_mesh("kitten-2holes.obj"), "1.5%", -2, 2, {"boundary_0", "boundary_1"});
}

/// `quadmesh mesh INPUT` (output and report in `dir`), with `-q` and `--report`: it
/// exits 0 and writes the mesh; the run and the report.
struct WrittenMesh {
  Run run;
  nlohmann::json report;
};
WrittenMesh mesh_input(const std::string& dir, const std::string& input, const std::string& size,
                       const std::string& more_options = "") {
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(input) + " -o " + quoted(output) + " --size " + size + " -q --report " +
                           quoted(report) + more_options);
  CHECK(run.status == 0);
  CHECK(std::filesystem::exists(output));
  return {run, std::filesystem::exists(report) ? nlohmann::json::parse(slurp(report)) : nlohmann::json()};
}

/// The same on a .geo text written to `dir`.
WrittenMesh mesh_geo(const std::string& dir, const std::string& geo, const std::string& size,
                     const std::string& more_options = "") {
  return mesh_input(dir, test::write_text(dir, "input.geo", geo), size, more_options);
}

TEST_CASE("mesh --singularities abel: quads far from the input on a long end are written, with one warning line that "
          "names the place" *
          doctest::test_suite("slow")) {
  // an L-plate whose arm is two widths long: the form decays along it, the quads at
  // its end are 20 times the size and 17% of the diagonal from it
  const WrittenMesh m = mesh_geo(test::scratch_dir("cli_far"),
      "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 80, 40};\n"
      "Rectangle(100) = {40, 20, 0, 80, 40};\n"
      "BooleanDifference{ Surface{1}; Delete; }{ Surface{100}; Delete; }\n"
      "Disk(2) = {35.06, 10.41, 0, 4.16};\nDisk(3) = {32.09, 26.76, 0, 4.78};\n"
      "BooleanDifference{ Surface{1}; Delete; }{ Surface{2:3}; Delete; }\n",
      "1.5%", " --singularities abel");
  const auto lines = m.run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: warning: the quads are up to ", 0) == 0);
  CHECK(lines[0].find(" asked (--max-deviation)") != std::string::npos);
  CHECK(lines[0].find(" times --size: the differential is small there") != std::string::npos);
  const auto& q = m.report["quality"];
  CHECK(q["hausdorff_rel"].get<double>() > m.report["acceptance"]["max_hausdorff_relative"].get<double>());
  // the place: the arm's end (x = 80)
  REQUIRE(q["hausdorff_at"].size() == 3);
  CHECK(q["hausdorff_at"][0].get<double>() > 60.0);
  const std::size_t at = lines[0].find(" near (");
  REQUIRE(at != std::string::npos);
  CHECK(std::atof(lines[0].c_str() + at + std::string(" near (").size()) > 60.0);
}

TEST_CASE("mesh: inverted quads are written, with one warning line that names the first, even with -q" *
          doctest::test_suite("slow")) {
  // bunny-open at 1.2% without refinement and without smoothing (which mends
  // them): quads turn over where the scan's hole boundary zigzags back on itself
  const std::string dir = test::scratch_dir("cli_inverted");
  const std::string output = dir + "/out.msh";
  const Run run = quadmesh("mesh " + quoted(test::shared_mesh("bunny-open.obj")) + " -o " + quoted(output) +
                           " --size 1.2% --max-deviation off --no-smoothing --singularities abel -q");
  CHECK(run.status == 0);
  CHECK(std::filesystem::exists(output));
  // Verdict's inverted (a corner re-entrant against the quad's own normal) and
  // turned over against the neighbours: one each here
  CHECK(run.out.find(" 1 inverted, 1 flipped)") != std::string::npos);
  const auto lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: warning: ", 0) == 0);
  CHECK(std::atoi(lines[0].c_str() + std::string("quadmesh: warning: ").size()) >= 1);
  CHECK(lines[0].find(" inverted quads and 1 turned over against their neighbours (min Verdict scaled Jacobian -") !=
        std::string::npos);
  CHECK(lines[0].find("the first near (") != std::string::npos);
}

TEST_CASE("mesh: a coarse plate whose first rounding drops cells is rounded again: no gap, no warning" *
          doctest::test_suite("slow")) {
  // a 120 x 40 plate with six holes and rounded corners, meshed coarsely (2.5%):
  // beside one hole the untangling left a fold it could not remove, and the cells
  // over it were dropped (a gap and a warning); the same form rounded at a nearby
  // scale left none. Since close boundary zeros of one loop are kept apart (not
  // merged), the first rounding leaves none either; the rounding retries are
  // tested in test_mesh_quads ("rounded again at a nearby scale")
  const WrittenMesh m = mesh_geo(test::scratch_dir("cli_dropped"),
      "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0, 0, 0, 120, 40, 6.66667};\n"
      "Disk(2) = {49.03, 18.53, 0, 7.14};\nDisk(3) = {15.99, 15.23, 0, 4.78};\n"
      "Disk(4) = {89.74, 26.40, 0, 6.88};\nDisk(5) = {33.22, 28.93, 0, 7.16};\n"
      "Disk(6) = {74.47, 18.22, 0, 7.33};\nDisk(7) = {108.26, 11.42, 0, 3.95};\n"
      "BooleanDifference{ Surface{1}; Delete; }{ Surface{2:7}; Delete; }\n",
      "2.5%");
  const auto& j = m.report;
  CHECK(j["extraction"]["incomplete_cells"].get<int>() + j["extraction"]["degenerate_cells"].get<int>() == 0);
  CHECK(j["extraction"]["stray_boundary_points"].get<int>() == 0);
  CHECK(j["quality"]["euler_characteristic"].get<int>() == -5);
  CHECK(j["quality"]["boundary_loops"].get<int>() == 7);
  for (const std::string& line : m.run.error_lines()) CHECK(line.find("could not be made into quads") == std::string::npos);
}

TEST_CASE("mesh: quads whose boundary strays from the input's are written with one warning line naming the first" *
          doctest::test_suite("slow")) {
  // a 150 x 50 plate with six holes at 1.2% (p7 of scripts/plate-sweep): a hole 4.15
  // from the plate's edge, with two boundary zeros on its far side; the rounding
  // leaves Abel quads whose boundary cuts across that hole's arc, with the input's
  // Euler characteristic and loops (at 1.5% it meets every criterion). On the CAD
  // triangulation of before issue 21 (a third of the quad size: 1.2% of Gmsh's
  // 158.1138832614 diagonal / 3, to the last digit: a size 1e-6 larger leaves no
  // stray point); the default one gives none there. By default the cones' quads
  // are kept there (the test after this one)
  const WrittenMesh m = mesh_geo(test::scratch_dir("cli_stray"), test::edge_hole_plate_geo(), "1.2%",
                                 " --cad-mesh-size 0.6324555330456047 --singularities abel");
  const int stray = m.report["extraction"]["stray_boundary_points"].get<int>();
  CHECK(stray > 0);
  CHECK(m.report["quality"]["euler_characteristic"].get<int>() == -5);
  CHECK(m.report["quality"]["boundary_loops"].get<int>() == 7);
  // one line for the strays among the warnings (the gap's dropped cells and the
  // deviation have their own)
  int stray_lines = 0;
  for (const std::string& line : m.run.error_lines()) {
    if (line.find("points of the quads' boundary are not on the input's boundary") == std::string::npos) continue;
    ++stray_lines;
    CHECK(line.rfind("quadmesh: warning: " + std::to_string(stray) +
                         " points of the quads' boundary are not on the input's boundary, the first near (",
                     0) == 0);
  }
  CHECK(stray_lines == 1);
}

TEST_CASE("mesh by default: cones nearer the surface than the Abel quads are kept, the warning naming both "
          "distances" *
          doctest::test_suite("slow")) {
  // kitten with two holes four rings wide at 2%: the cones' quads are sound with
  // every quad in the size band and every corner right, 1.3% of the diagonal from
  // the surface; the Abel quads have about half in the band and lie 2.1% away. Both
  // miss the 1% criterion, and the nearer, better result is the one written. (The
  // holes five rings wide showed it until a folded map was made again with its
  // short boundary segments held: its cones now meet every criterion at 2%. A plate
  // with six holes near its edges at 1.2% showed it until its cones' pairs went
  // past one that made the sizes worse)
  const std::string dir = test::scratch_dir("cli_nearer_cones");
  const std::string input = dir + "/kitten-cut.obj";
  test::write_obj(test::cut_holes(io::read_surface(test::shared_mesh("kitten.off")).soup, {1852, 2292}, 4), input);
  const WrittenMesh m = mesh_input(dir, input, "2%");
  REQUIRE(m.run.status == 0);
  const auto& sg = m.report["singularities"];
  CHECK(sg["route"] == "cones");
  CHECK(sg["cone_route_failure"] == "");
  const double cones = m.report["quality"]["hausdorff_rel"].get<double>();
  const double abel = sg["abel_distance_relative"].get<double>();
  CHECK(cones > m.report["acceptance"]["max_hausdorff_relative"].get<double>());
  CHECK(abel > cones);
  CHECK(sg["size_band_share"].get<double>() >= 0.95);
  CHECK(sg["abel_size_band_share"].get<double>() < 0.7);
  CHECK(m.report["extraction"]["stray_boundary_points"].get<int>() == 0);
  CHECK(m.report["quality"]["euler_characteristic"].get<int>() == -2);
  CHECK(m.report["quality"]["boundary_loops"].get<int>() == 2);
  const auto lines = m.run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: warning: the quads are up to ", 0) == 0);
  CHECK(lines[0].find(fmt::format(" asked (--max-deviation) (the cones' quads are kept: the Abel quads are {:.2g}% of "
                                  "the diagonal from it): ",
                                  100 * abel)) != std::string::npos);
}

TEST_CASE("mesh --singularities abel: an L-bracket with a long arm fails fast, naming the long end (the Abel "
          "route's limit)" *
          doctest::test_suite("slow")) {
  // 200 x 40 with an arm 100 long and 20 wide: every symmetric form decays like
  // exp(-pi x / 20) along it. One basis form was almost 0 along a hole and was
  // scaled a thousandfold to give that loop 4 edges: the lattice took 15 GB.
  const std::string dir = test::scratch_dir("cli_long_arm");
  const std::string bracket = test::write_text(dir, "bracket.geo", test::long_arm_bracket_geo());
  const std::string output = dir + "/out.msh";
  // on the CAD triangulation of before issue 21 (a third of the quad size: 1.5% of
  // the 204 diagonal / 3); on the default one the arm's quads conform, 19 times the
  // size, with a warning naming the long end (README Limits)
  const Run run = quadmesh("mesh " + quoted(bracket) + " -o " + quoted(output) +
                           " --size 1.5% --cad-mesh-size 1.02 --singularities abel -q");
  CHECK(run.status == 1);
  const auto lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: error: the quad mesh would not be conforming", 0) == 0);
  // the place is in the arm (x > 100)
  const std::size_t at = lines[0].find("times --size near (");
  REQUIRE(at != std::string::npos);
  CHECK(std::atof(lines[0].c_str() + at + std::string("times --size near (").size()) > 100.0);
  CHECK(lines[0].find("a long end or a protrusion") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(output));
}

TEST_CASE("mesh: bad options are usage errors, before any work") {
  const std::string dir = test::scratch_dir("cli_mesh_options");
  const std::string input = test::example("annulus.geo");
  for (const char* options : {"--size -1", "--size 1.5%%", "--form 0", "--form x", "--quads 0", "--tip-angle 90", "--singularities x", "--bogus"}) {
    CAPTURE(options);
    const Run run = quadmesh("mesh " + quoted(input) + " -o " + quoted(dir + "/out.msh") + " " + std::string(options));
    CHECK(run.status == 2);
    CHECK_FALSE(std::filesystem::exists(dir + "/out.msh"));
    // one line naming the option, like every other error
    const auto lines = run.error_lines();
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].rfind("quadmesh: error: ", 0) == 0);
    const std::string option = std::string(options).substr(0, std::string(options).find(' '));
    CHECK(lines[0].find(option) != std::string::npos);
  }
  const Run coeffs = quadmesh("mesh " + quoted(input) + " -o " + quoted(dir + "/out.msh") + " --coeffs 1,2");
  CHECK(coeffs.status == 3);
  CHECK(coeffs.error_lines().size() == 1);
  CHECK(coeffs.error_lines()[0].find("--coeffs has 2 values but the surface has 1 symmetric forms") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir + "/out.msh"));
}

TEST_CASE("mesh refuses bad files with exit 3") {
  const std::string dir = test::scratch_dir("cli_bad_files");
  std::ofstream(dir + "/empty.obj");
  expect_refusal(dir + "/empty.obj", 3, "empty.obj: empty file");
  expect_refusal(dir + "/missing.obj", 3, "missing.obj: no such file");

  std::ofstream(dir + "/nan.obj") << "v 0 0 0\nv 1 0 0\nv 0 NaN 0\nf 1 2 3\n";
  expect_refusal(dir + "/nan.obj", 3, "nan.obj: line 3: coordinate 'NaN' is not a finite number");

  std::ofstream(dir + "/cut.off") << "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n";
  expect_refusal(dir + "/cut.off", 3, "cut.off: the file ends after 1 of 2 faces");

  {
    std::ofstream noise(dir + "/noise.stl", std::ios::binary);
    for (int i = 0; i < 1000; ++i) noise.put(static_cast<char>((i * 7919) & 0xff));
  }
  expect_refusal(dir + "/noise.stl", 3, "noise.stl:");

  expect_refusal(test::shared_mesh("ogre-body-pinched.obj"), 3, "non-manifold vertex 16156 at (");
}

TEST_CASE("mesh refuses surfaces the method does not apply to with exit 4") {
  const std::string dir = test::scratch_dir("cli_unsupported");
  test::write_obj(test::disk(3, 12), dir + "/disk.obj");
  expect_refusal(dir + "/disk.obj", 4, "chi = 1: not supported: a disk carries no holomorphic");
  test::write_obj(test::sphere(), dir + "/sphere.obj");
  expect_refusal(dir + "/sphere.obj", 4, "a sphere carries no holomorphic 1-form");
  test::write_obj(test::moebius(16), dir + "/moebius.obj");
  expect_refusal(dir + "/moebius.obj", 4, "non-orientable");
  test::write_obj(test::two_components(), dir + "/two.obj");
  expect_refusal(dir + "/two.obj", 4, "2 connected components");
  test::write_obj(test::bow_tie(), dir + "/bowtie.obj");
  expect_refusal(dir + "/bowtie.obj", 3, "non-manifold vertex 1 at (0, 0, 0)");  // OBJ counts from 1
}

TEST_CASE("--largest-component proceeds with the largest piece") {
  const std::string dir = test::scratch_dir("cli_largest");
  TriangleSoup soup = test::annulus(1, 2, 4, 16);
  const TriangleSoup small = test::disk(2, 6);
  const int offset = static_cast<int>(soup.points.size());
  for (const Vec3& p : small.points) soup.points.push_back(p + Vec3(10, 0, 0));
  for (const Triangle& t : small.triangles)
    soup.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  test::write_obj(soup, dir + "/pieces.obj");
  // without it: refused (exit 4), with the remedy said as the flag, not as the
  // library's largest_component()
  const Run refused = quadmesh("mesh " + quoted(dir + "/pieces.obj") + " -o " + quoted(dir + "/out.msh"));
  CHECK(refused.status == 4);
  REQUIRE(refused.error_lines().size() == 1);
  CHECK(refused.error_lines()[0].find("keep the largest (--largest-component)") != std::string::npos);
  const Run info = quadmesh("info --json --largest-component " + quoted(dir + "/pieces.obj"));
  CHECK(info.status == 0);
  const auto j = nlohmann::json::parse(info.out);
  CHECK(j["components"] == 1);
  CHECK(j["components_dropped"] == 1);
  CHECK(j["case"] == "annulus");
}

TEST_CASE("usage errors exit 2 before any work") {
  CHECK(quadmesh("").status == 2);
  CHECK(quadmesh("frobnicate x.obj").status == 2);
  CHECK(quadmesh("mesh " + quoted(test::shared_mesh("pig.off"))).status == 2);  // no -o
  CHECK(quadmesh("mesh " + quoted(test::shared_mesh("pig.off")) + " -o x.msh --size -1").status == 2);
  const Run bad_ext = quadmesh("mesh " + quoted(test::shared_mesh("pig.off")) + " -o /tmp/out.xyz");
  CHECK(bad_ext.status == 2);
  CHECK(bad_ext.err.find("unknown output format '.xyz'") != std::string::npos);
  const Run bad_dir =
      quadmesh("mesh " + quoted(test::shared_mesh("pig.off")) + " -o /nonexistent/dir/out.msh");
  CHECK(bad_dir.status == 2);
  CHECK(bad_dir.err.find("does not exist") != std::string::npos);
  const Run version = quadmesh("--version");
  CHECK(version.status == 0);
  CHECK(version.out.find("quadmesh") != std::string::npos);
}

TEST_CASE("forms --json: dimension, zero orders, residuals; -o writes Gmsh views") {
  const std::string dir = test::scratch_dir("cli_forms");
  const std::string views = dir + "/views.msh";
  const Run run = quadmesh("forms --json " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " + quoted(views));
  CHECK(run.status == 0);
  const auto j = nlohmann::json::parse(run.out);
  CHECK(j["doubled_genus"] == 3);
  CHECK(j["symmetric_dimension"] == 3);
  CHECK(j["zero_order_sum_doubled"] == 4);  // -2 chi
  CHECK(j["residuals"]["boundary_imaginary"].get<double>() < 1e-8);
  CHECK(j["residuals"]["closedness"].get<double>() < 1e-12);
  CHECK(j["residuals"]["hodge_star_squared"].get<double>() < 0.1);
  int order_sum = 0;
  for (const auto& z : j["zeros"]) order_sum += z["order"].get<int>() * (z["on_boundary"].get<bool>() ? 1 : 2);
  CHECK(order_sum == 4);
  for (const char* stage : {"doubling", "factorization", "harmonic", "hodge_star", "symmetric_basis"})
    CHECK(j["timings"].contains(stage));

  const std::string text = slurp(views);
  auto count = [&](const std::string& needle) {
    std::size_t n = 0;
    for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
    return n;
  };
  CHECK(count("$ElementData\n") == 3);      // one vector field per symmetric form
  CHECK(count("$ElementNodeData\n") == 6);  // Re and Im of each integral
  CHECK(count("$Nodes\n") == 1);            // the mesh is written once
  CHECK(text.find("\"boundary_1\"") != std::string::npos);
  CHECK(text.find("\"bridge_1\"") != std::string::npos);  // kitten: 2 boundaries, genus 1
  CHECK(text.find("\"handle_0\"") != std::string::npos);
  CHECK(text.find("\"handle_1\"") != std::string::npos);
  CHECK(text.find("\"handle_2\"") == std::string::npos);
  CHECK(text.find("\"zeros\"") != std::string::npos);

  const Run bad = quadmesh("forms " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " + quoted(dir + "/v.vtk"));
  CHECK(bad.status == 2);
  CHECK(bad.err.find("must be a .msh file") != std::string::npos);
  const Run disk = quadmesh("forms " + quoted(test::shared_mesh("kitten-2holes.obj") + ".missing"));
  CHECK(disk.status == 3);
}

TEST_CASE("quality --json: counts and scaled Jacobian of a quad grid; a missing file exits 3") {
  const std::string dir = test::scratch_dir("cli_quality");
  {
    std::ofstream obj(dir + "/grid.obj");  // 3 x 2 unit squares
    for (int j = 0; j <= 2; ++j)
      for (int i = 0; i <= 3; ++i) obj << "v " << i << ' ' << j << " 0\n";
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const int a = j * 4 + i + 1;  // OBJ counts from 1
        obj << "f " << a << ' ' << a + 1 << ' ' << a + 5 << ' ' << a + 4 << '\n';
      }
  }
  const Run run = quadmesh("quality " + quoted(dir + "/grid.obj") + " --json");
  CHECK(run.status == 0);
  const auto j = nlohmann::json::parse(run.out);
  CHECK(j["quads"] == 6);
  CHECK(j["vertices"] == 12);
  CHECK(j["min_scaled_jacobian"].get<double>() == doctest::Approx(1.0).epsilon(1e-12));
  CHECK(j["euler_characteristic"] == 1);
  CHECK(j["boundary_loops"] == 1);
  CHECK(j["hausdorff_rel"].is_null());  // no reference
  CHECK(j["size_band_share"].is_null());  // no --size

  // against a target size: the unit squares are 2.5 x 0.4 and 1/1.5 x 1.5
  const Run small = quadmesh("quality " + quoted(dir + "/grid.obj") + " --json --size 0.4");
  REQUIRE(small.status == 0);
  const auto s = nlohmann::json::parse(small.out);
  CHECK(s["size_band_share"].get<double>() == 0.0);
  CHECK(s["size_ratio_max"].get<double>() == doctest::Approx(2.5).epsilon(1e-12));
  const Run fits = quadmesh("quality " + quoted(dir + "/grid.obj") + " --size 1.5");
  CHECK(fits.out.find("100.0% of the quads within [0.5, 2] x 1.5") != std::string::npos);
  // the grid as its own reference: its four corners are each in one quad
  const Run corners = quadmesh("quality " + quoted(dir + "/grid.obj") + " --json --reference " + quoted(dir + "/grid.obj"));
  REQUIRE(corners.status == 0);
  const auto c = nlohmann::json::parse(corners.out)["corners"];
  CHECK(c["convex"] == 4);
  CHECK(c["convex_wrong"] == 0);
  CHECK(c["concave"] == 0);
  CHECK(quadmesh("quality " + quoted(dir + "/grid.obj") + " --size -1").status == 2);

  const Run missing = quadmesh("quality " + quoted(dir + "/missing.obj"));
  CHECK(missing.status == 3);
  REQUIRE(missing.error_lines().size() == 1);
  CHECK(missing.error_lines()[0].find("missing.obj: no such file") != std::string::npos);
}

TEST_CASE("mesh and info: coordinates out of the computable range are refused before any work") {
  // the kitten scaled by 1e300 and by 1e-160, and moved 1e13 away: the first two
  // died in the forms stage (or failed to factor) after `info` said "supported"
  const std::string dir = test::scratch_dir("cli_coordinates");
  struct Case {
    const char* name;
    double factor, shift;
    const char* needle;
  };
  for (const Case& c : {Case{"huge", 1e300, 0, "has a coordinate of"}, Case{"tiny", 1e-160, 0, "across (bounding-box diagonal)"},
                        Case{"far", 1, 1e13, "from the origin"}}) {
    CAPTURE(c.name);
    std::ifstream in(test::shared_mesh("kitten-2holes.obj"));
    std::ofstream out(dir + "/" + c.name + ".obj");
    out.precision(17);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("v ", 0) == 0) {
        std::istringstream words(line.substr(2));
        double x, y, z;
        words >> x >> y >> z;
        out << "v " << x * c.factor + c.shift << ' ' << y * c.factor << ' ' << z * c.factor << '\n';
      } else {
        out << line << '\n';
      }
    }
    out.close();
    const std::string input = dir + "/" + c.name + ".obj";
    expect_refusal(input, 3, c.needle);
    const Run info = quadmesh("info " + quoted(input));
    CHECK(info.status == 3);
    CHECK(info.out.find(c.needle) != std::string::npos);
  }
}

TEST_CASE("mesh --singularities auto: a plate whose corners get two quads each from the Abel route gets one, "
          "eight valence-5 cones inside, every quad in the size band" *
          doctest::test_suite("slow")) {
  const std::string dir = test::scratch_dir("cli_singularities");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(test::example("plate-two-holes.geo")) + " -o " + quoted(output) +
                           " --size 1.5% --singularities auto -q --report " + quoted(report));
  REQUIRE(run.status == 0);
  CHECK(run.err.empty());
  const auto j = nlohmann::json::parse(slurp(report));
  const auto& s = j["singularities"];
  CHECK(s["mode"] == "auto");
  CHECK(s["route"] == "cones");
  // four right corners (one quad each) leave -8 quarter turns inside: eight valence-5 cones
  int corners = 0, fives = 0;
  for (const auto& c : s["cones"]) {
    corners += c["on_boundary"].get<bool>() && c["quads"] == 1;
    fives += !c["on_boundary"].get<bool>() && c["quads"] == 5;
  }
  CHECK(corners == 4);
  CHECK(fives == 8);
  CHECK(s["size_band_share"].get<double>() >= 0.9);
  // the plate has CAD corners, which the Abel quads split in two: the cone route
  // ran first and sufficed, so there are no Abel quads to measure
  CHECK(s["abel_size_band_share"].is_null());
  const auto& q = j["quality"];
  CHECK(q["euler_characteristic"] == -1);
  CHECK(q["boundary_loops"] == 3);
  CHECK(q["triangles"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(q["irregular_interior"] == 8);
  CHECK(q["irregular_interior"] == j["expected"]["irregular_interior"]);
  CHECK(q["irregular_boundary"] == 0);  // every corner in one quad, every other boundary point in two
  CHECK(q["corners"]["convex"] == 4);   // the plate's corners, taken from the input
  CHECK(q["corners"]["convex_wrong"] == 0);
  CHECK(q["size_band_share"].get<double>() == doctest::Approx(s["size_band_share"].get<double>()).epsilon(1e-12));
  CHECK(q["size_ratio_max"].get<double>() <= 3.0);
  const auto& criteria = j["acceptance"];
  CHECK(q["min_scaled_jacobian"].get<double>() >= criteria["min_scaled_jacobian"].get<double>());
  CHECK(q["angle_dev_mean"].get<double>() <= criteria["max_mean_angle_deviation_deg"].get<double>());
  CHECK(q["hausdorff_rel"].get<double>() <= criteria["max_hausdorff_relative"].get<double>());
}

TEST_CASE("mesh reports a cone on the boundary away from the corners with its own reason" *
          doctest::test_suite("slow")) {
  // examples/link-lightening-hole.geo (a hole 1.4 quads across in the shaft): the
  // route's boundary_cone_placement puts four valence-5 cones on the hole's boundary
  const nlohmann::json j =
      mesh_input(test::scratch_dir("cli_boundary_cones"), test::example("link-lightening-hole.geo"), "1.5%").report;
  const auto& s = j["singularities"];
  CHECK(s["route"] == "cones");
  int corners = 0, on_hole = 0;
  for (const auto& c : s["cones"]) {
    if (!c["on_boundary"].get<bool>()) continue;
    const double x = c["position"][0].get<double>() - 96, y = c["position"][1].get<double>();
    const bool hole = std::abs(std::hypot(x, y) - 2.5) < 1e-6;
    on_hole += hole;
    corners += !hole && c["reason"] == "corner: one quad per 90 degrees of its angle";
    if (hole) CHECK(c["reason"].get<std::string>().find("on the boundary: no room inside") != std::string::npos);
  }
  CHECK(corners == 4);
  CHECK(on_hole == 4);
  CHECK(j["quality"]["size_band_share"].get<double>() >= 0.95);
}

TEST_CASE("mesh --cone-placement cross-field: the smoothest cross field's singularities as the interior cones, "
          "reported as such") {
  const std::string dir = test::scratch_dir("cli_cone_placement");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(test::example("l-plate-long-arm.geo")) + " -o " + quoted(output) +
                           " --size 1.5% --singularities auto --cone-placement cross-field -q --report " +
                           quoted(report));
  REQUIRE(run.status == 0);
  const auto j = nlohmann::json::parse(slurp(report));
  const auto& s = j["singularities"];
  CHECK(s["route"] == "cones");
  CHECK(s["cone_placement"] == "cross-field");
  // five convex corners and the concave one leave 4 chi - 5 + 1 = -4 quarter turns inside
  int turns = 0, interior = 0;
  for (const auto& c : s["cones"]) {
    if (c["on_boundary"].get<bool>()) continue;
    ++interior;
    turns += 4 - c["quads"].get<int>();
    CHECK(c["reason"] == "a singularity of the smoothest boundary-aligned cross field");
  }
  CHECK(turns == -4);
  const auto& q = j["quality"];
  CHECK(q["euler_characteristic"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(q["irregular_interior"] == interior);
  CHECK(q["corners"]["convex_wrong"] == 0);
  CHECK(q["corners"]["concave_wrong"] == 0);
  CHECK(q["size_band_share"].get<double>() >= 0.9);
  // an unknown placement is refused by the parser
  const Run bad = quadmesh("mesh " + quoted(test::example("l-plate-long-arm.geo")) + " -o " + quoted(dir + "/x.msh") +
                           " --cone-placement spiral");
  CHECK(bad.status != 0);
  CHECK(!std::filesystem::exists(dir + "/x.msh"));
}

TEST_CASE("mesh --singularities auto: a T-plate the Abel route folds meshes with cones, every corner right" *
          doctest::test_suite("slow")) {
  const std::string dir = test::scratch_dir("cli_singularities_t");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run abel = quadmesh("mesh " + quoted(test::example("t-plate-two-holes.geo")) + " -o " + quoted(output) +
                            " --size 1.5% --singularities abel -q");
  CHECK(abel.status == 1);  // the web is a long end: the Abel quads fold there
  const Run run = quadmesh("mesh " + quoted(test::example("t-plate-two-holes.geo")) + " -o " + quoted(output) +
                           " --size 1.5% --singularities auto -q --report " + quoted(report));
  REQUIRE(run.status == 0);
  const auto j = nlohmann::json::parse(slurp(report));
  CHECK(j["singularities"]["route"] == "cones");
  const auto& q = j["quality"];
  CHECK(q["euler_characteristic"] == -1);
  CHECK(q["boundary_loops"] == 3);
  CHECK(q["triangles"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(q["corners"]["convex"] == 6);
  CHECK(q["corners"]["convex_wrong"] == 0);
  CHECK(q["corners"]["concave"] == 2);
  CHECK(q["corners"]["concave_wrong"] == 0);
  CHECK(q["irregular_interior"] == 8);
  CHECK(q["min_scaled_jacobian"].get<double>() >= 0.3);
  CHECK(q["angle_dev_mean"].get<double>() <= 5.0);
  CHECK(q["hausdorff_rel"].get<double>() <= 0.01);
  CHECK(q["size_band_share"].get<double>() >= 0.9);
  // the first lattice leaves a flange corner's quad at 3.09 x the size: a finer one
  // is tried and kept
  CHECK(q["size_ratio_max"].get<double>() <= 3.0);
}

TEST_CASE("mesh: a CAD part whose quads come out inverted on Gmsh's first triangulation is meshed on a finer one" *
          doctest::test_suite("slow")) {
  // the hat channel at 1.5%: two bolt holes in its top 4.2 apart (0.95 quads). On
  // Gmsh's triangles of 0.75 x the quad size every cone map folds across them and
  // the Abel quads kept have an inverted quad and 21% of them in the size band;
  // on triangles of 0.6 x the quad size the cones' quads meet every criterion
  const std::string dir = test::scratch_dir("cli_cad_retry_inverted");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(test::example("hat-channel-holes.geo")) + " -o " +
                           quoted(output) + " --size 1.5% --report " + quoted(report));
  REQUIRE(run.status == 0);
  const std::vector<std::string> lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: warning: Gmsh's triangulation of the part (triangles up to", 0) == 0);
  CHECK(lines[0].find("gave inverted quads; these are meshed on a finer one") != std::string::npos);
  CHECK(lines[0].find("0.6 x the quad size: --cad-mesh-size") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(report));
  const auto& q = j["quality"];
  CHECK(j["singularities"]["route"] == "cones");
  CHECK(q["euler_characteristic"] == -6);
  CHECK(q["boundary_loops"] == 8);
  CHECK(q["inverted"] == 0);
  CHECK(q["flipped"] == 0);
  CHECK(q["min_scaled_jacobian"].get<double>() >= 0.3);
  CHECK(q["angle_dev_mean"].get<double>() <= 5.0);
  CHECK(q["hausdorff_rel"].get<double>() <= 0.01);
  CHECK(q["size_band_share"].get<double>() >= 0.9);
  CHECK(q["size_ratio_max"].get<double>() <= 3.0);
}

TEST_CASE("mesh: a CAD part whose quads fold on Gmsh's first triangulation is meshed on a finer one, with a warning" *
          doctest::test_suite("slow")) {
  // the rod end at 3% of the diagonal: on Gmsh's triangles of 0.75 x the quad size
  // every cone placement folds and so do the Abel quads (exit 1 before); on
  // triangles of 0.6 x the quad size the cones are sound
  const std::string dir = test::scratch_dir("cli_cad_retry");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(test::example("rod-end.geo")) + " -o " + quoted(output) +
                           " --size 3% --report " + quoted(report));
  REQUIRE(run.status == 0);
  const std::vector<std::string> lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: warning: Gmsh's triangulation of the part (triangles up to", 0) == 0);
  CHECK(lines[0].find("0.6 x the quad size: --cad-mesh-size") != std::string::npos);
  const auto j = nlohmann::json::parse(slurp(report));
  const auto& q = j["quality"];
  CHECK(q["euler_characteristic"] == -1);
  CHECK(q["boundary_loops"] == 3);
  CHECK(q["triangles"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(q["min_scaled_jacobian"].get<double>() >= 0.3);
  // the size the warning names gives these quads directly, without a warning
  const std::string named = "--cad-mesh-size ";
  const std::size_t at = lines[0].find(named) + named.size();
  const std::string size = lines[0].substr(at, lines[0].find(')', at) - at);
  const Run given = quadmesh("mesh " + quoted(test::example("rod-end.geo")) + " -o " + quoted(dir + "/given.msh") +
                             " --size 3% --cad-mesh-size " + size + " -q");
  CHECK(given.status == 0);
  CHECK(given.error_lines().empty());
}

TEST_CASE("mesh (auto): a 16-degree notch's tip is a lattice point in four quads, the quads' boundary goes round it" *
          doctest::test_suite("slow")) {
  // the plate turns 343.7 degrees round the tip of plate-v-hole's triangular hole:
  // a boundary cone of four quads whose two sides lie on one lattice line. Its
  // position along that line is rounded too; when it was not, the tip fell 0.09
  // quads short of a lattice point and the quads' boundary ran past it into the
  // plate (one stray point), so the Abel quads were kept (7 corners wrong)
  const WrittenMesh m = mesh_input(test::scratch_dir("cli_v_notch"), test::example("plate-v-hole.geo"), "1.5%");
  REQUIRE(m.run.status == 0);
  CHECK(m.run.error_lines().empty());
  const auto& j = m.report;
  CHECK(j["singularities"]["route"] == "cones");
  bool tip = false;
  for (const auto& cone : j["singularities"]["cones"]) {
    const auto& at = cone["position"];
    if (std::abs(at[0].get<double>() - 50) < 1e-9 && std::abs(at[1].get<double>() - 30) < 1e-9) {
      tip = true;
      CHECK(cone["quads"] == 4);
      CHECK(cone["on_boundary"] == true);
    }
  }
  CHECK(tip);
  CHECK(j["extraction"]["stray_boundary_points"] == 0);
  const auto& q = j["quality"];
  CHECK(q["euler_characteristic"] == -1);
  CHECK(q["boundary_loops"] == 3);
  CHECK(q["inverted"] == 0);
  CHECK(q["corners"]["convex"] == 4);
  CHECK(q["corners"]["concave"] == 2);
  CHECK(q["corners"]["other"] == 1);
  CHECK(q["corners"]["convex_wrong"].get<int>() + q["corners"]["concave_wrong"].get<int>() +
            q["corners"]["other_wrong"].get<int>() ==
        0);
  CHECK(q["min_scaled_jacobian"].get<double>() >= 0.3);
  CHECK(q["hausdorff_rel"].get<double>() <= 0.01);
  CHECK(q["size_band_share"].get<double>() >= 0.9);
  CHECK(q["size_ratio_max"].get<double>() <= 3.0);
}

TEST_CASE("mesh --singularities auto: kitten's coarse hole polygons get every corner right, the quads in the band" *
          doctest::test_suite("slow")) {
  // its two holes are polygons of 19 and 21 edges of 0.65 to 2.7 quads, with corners
  // of 104 and 264 degrees next to each other: quantization must keep consecutive
  // corners off one lattice point
  const std::string dir = test::scratch_dir("cli_singularities_kitten");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " + quoted(output) +
                           " --size 1.5% --singularities auto -q --report " + quoted(report));
  REQUIRE(run.status == 0);
  const auto j = nlohmann::json::parse(slurp(report));
  CHECK(j["singularities"]["route"] == "cones");
  const auto& q = j["quality"];
  CHECK(q["euler_characteristic"] == -2);
  CHECK(q["boundary_loops"] == 2);
  CHECK(q["triangles"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(q["corners"]["convex"].get<int>() + q["corners"]["concave"].get<int>() >= 8);
  CHECK(q["corners"]["convex_wrong"] == 0);
  CHECK(q["corners"]["concave_wrong"] == 0);
  CHECK(q["corners"]["other_wrong"] == 0);
  CHECK(q["irregular_interior"].get<int>() <= 24);
  CHECK(q["min_scaled_jacobian"].get<double>() >= 0.3);
  CHECK(q["angle_dev_mean"].get<double>() <= 5.0);
  CHECK(q["hausdorff_rel"].get<double>() <= 0.01);
  CHECK(q["size_band_share"].get<double>() >= 0.9);
  CHECK(q["size_ratio_max"].get<double>() <= 3.0);
}

TEST_CASE("mesh by default (auto): where the cones do not help, the Abel quads with one warning line saying why" *
          doctest::test_suite("slow")) {
  // pig at 2% of the diagonal: every cone placement's map folds (docs/cones.md
  // "Next"), so the Abel quads stay
  const std::string dir = test::scratch_dir("cli_default_fallback");
  const std::string output = dir + "/out.msh", report = dir + "/report.json";
  const Run run = quadmesh("mesh " + quoted(test::shared_mesh("pig.off")) + " -o " + quoted(output) +
                           " --size 2% -q --report " + quoted(report));
  REQUIRE(run.status == 0);
  CHECK(std::filesystem::exists(output));
  const auto j = nlohmann::json::parse(slurp(report));
  CHECK(j["singularities"]["mode"] == "auto");
  CHECK(j["singularities"]["route"] == "abel");
  const std::string failure = j["singularities"]["cone_route_failure"].get<std::string>();
  CHECK(failure.rfind("the cones' quads were not better (not sound: ", 0) == 0);
  int cone_lines = 0;
  for (const std::string& line : run.error_lines()) {
    if (line.find("quarter-turn cones did not help") == std::string::npos) continue;
    ++cone_lines;
    // what the Abel quads miss (every corner's quad count wrong, two thirds of them in the band), then why
    const auto& q = j["quality"];
    const int corners = q["corners"]["convex"].get<int>() + q["corners"]["concave"].get<int>() +
                        q["corners"]["other"].get<int>();
    const double largest = q["size_ratio_max"].get<double>();
    CHECK(line.rfind(fmt::format("quadmesh: warning: the Abel quads put {} of the input's {} corners in the wrong "
                                 "number of quads ({:.0f}% of them within [0.5, 2] x --size{}); quarter-turn cones did "
                                 "not help: ",
                                 corners, corners, 100 * j["singularities"]["abel_size_band_share"].get<double>(),
                                 largest > 3 ? fmt::format(", the largest {:.1f} x", largest) : std::string()),
                     0) == 0);
    CHECK(line.find(failure + "; the Abel result is kept") != std::string::npos);
  }
  CHECK(cone_lines == 1);
  // a differential chosen by hand (--form) is the Abel route: no cones tried, no such line
  const Run form = quadmesh("mesh " + quoted(test::shared_mesh("pig.off")) + " -o " + quoted(output) +
                            " --size 2% --form 1 -q --report " + quoted(report));
  REQUIRE(form.status == 0);
  CHECK(nlohmann::json::parse(slurp(report))["singularities"]["mode"] == "abel");
  for (const std::string& line : form.error_lines()) CHECK(line.find("quarter-turn cones") == std::string::npos);
}

TEST_CASE("mesh: an input far finer than the quads is meshed on a working triangulation, measured against the input") {
  const std::string dir = test::scratch_dir("cli_coarsen");
  const TriangleSoup fine = test::annulus(1.0, 2.0, 50, 300);  // 30000 triangles, edges 0.02 to 0.04
  const std::string input = dir + "/annulus.obj";
  test::write_obj(fine, input);
  auto mesh = [&](const std::string& more) {
    const std::string output = dir + "/out.msh", report = dir + "/report.json";
    const Run run = quadmesh("mesh " + quoted(input) + " -o " + quoted(output) + " --size 0.25 -q --report " +
                             quoted(report) + more);
    CHECK(run.status == 0);
    REQUIRE(std::filesystem::exists(report));
    return nlohmann::json::parse(slurp(report));
  };
  const nlohmann::json coarse = mesh("");
  CHECK(coarse["coarsened_from_triangles"] == 30000);
  CHECK(coarse["surface_triangles"].get<std::size_t>() * 4 < 30000);
  const nlohmann::json& q = coarse["quality"];
  CHECK(q["triangles"] == 0);
  CHECK(q["inverted"] == 0);
  CHECK(q["euler_characteristic"] == 0);
  CHECK(q["boundary_loops"] == 2);
  CHECK(q["min_scaled_jacobian"].get<double>() > 0.9);  // an annulus: a polar grid
  // against the input as read: the inscribed polygons are within the chords' sagitta
  CHECK(q["hausdorff_rel"].get<double>() < 0.005);
  const nlohmann::json as_is = mesh(" --no-coarsening");
  CHECK(as_is["coarsened_from_triangles"] == 0);
  CHECK(as_is["surface_triangles"].get<std::size_t>() >= 30000);
  CHECK(as_is["quality"]["quads"].get<double>() == doctest::Approx(q["quads"].get<double>()).epsilon(0.1));
  // 8-node quads: the edge nodes go onto the input (here the plane), not only the working surface
  const nlohmann::json quadratic = mesh(" --order 2");
  CHECK(quadratic["order"]["nodes_per_quad"] == 8);
  CHECK(quadratic["coarsened_from_triangles"] == 30000);
}
