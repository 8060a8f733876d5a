// The quadmesh program under careless and hostile use (issue 22): outputs that
// collide with the input or each other, option values no mesh can have, work
// that would take gigabytes, and the messages and exit codes of README's table.
// Each case: the exit status, exactly one error line naming the problem, and no
// output file left.
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

using namespace qm;
using test::quadmesh;
using test::quoted;
using test::Run;

namespace fs = std::filesystem;

namespace {

/// A small annulus (1 symmetric form): meshed in a fraction of a second.
std::string annulus_obj(const std::string& dir) {
  const std::string path = dir + "/annulus.obj";
  test::write_obj(test::annulus(1, 2, 4, 16), path);
  return path;
}

/// The one error line of a refused run: status, "quadmesh: error: " and `needle`.
void expect_one_error(const Run& run, int status, const std::string& needle) {
  CHECK(run.status == status);
  const auto lines = run.error_lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: error: ", 0) == 0);
  CHECK(lines[0].find(needle) != std::string::npos);
  CHECK(lines[0].size() < 260);
}

/// Files in `dir` other than `keep` (temporaries included).
std::set<std::string> files_besides(const std::string& dir, const std::set<std::string>& keep) {
  std::set<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir))
    if (!keep.count(entry.path().filename().string())) out.insert(entry.path().filename().string());
  return out;
}

}  // namespace

TEST_CASE("outputs: -o, --report and the input are different files, the paths usable, every output or none") {
  const std::string dir = test::scratch_dir("hostile_outputs");
  const std::string input = annulus_obj(dir);
  const std::string original = test::slurp(input);
  fs::create_directory(dir + "/sub");
  fs::create_directory(dir + "/folder.msh");
  fs::create_symlink(input, dir + "/link.obj");
  const std::string mesh = "mesh " + quoted(input) + " --size 25% ";
  const std::set<std::string> setup = {"annulus.obj", "sub", "folder.msh", "link.obj"};

  // the report over the mesh, in plain, ./ and .. forms
  for (const std::string& report : {dir + "/out.msh", dir + "/./out.msh", dir + "/sub/../out.msh"}) {
    CAPTURE(report);
    expect_one_error(quadmesh(mesh + "-o " + quoted(dir + "/out.msh") + " --report " + quoted(report)), 2,
                     "the same file as -o");
  }
  // the mesh over the input, directly, through ./ and through a symlink
  for (const std::string& output : {input, dir + "/./annulus.obj", dir + "/sub/../link.obj"}) {
    CAPTURE(output);
    expect_one_error(quadmesh(mesh + "-o " + quoted(output)), 2, "the same file as the input");
  }
  expect_one_error(quadmesh(mesh + "-o " + quoted(dir + "/out.obj") + " --report " + quoted(dir + "/link.obj")), 2,
                   "--report " + dir + "/link.obj: the same file as the input");
  CHECK(test::slurp(input) == original);

  // a folder as the output, and a folder nobody can write in: before any work
  // (no progress line: the input is not even read)
  const Run folder = quadmesh(mesh + "-o " + quoted(dir + "/folder.msh"));
  expect_one_error(folder, 2, "-o " + dir + "/folder.msh: is a folder, not a file");
  CHECK(folder.err.find("] reading") == std::string::npos);
  expect_one_error(quadmesh(mesh + "-o " + quoted(dir + "/out.msh") + " --report /proc/report.json"), 2,
                   "--report /proc/report.json: cannot write in the folder /proc");
  CHECK(files_besides(dir, setup).empty());

  // the mesh is written, then the report cannot be (a file size limit of 2 KB,
  // SIGXFSZ ignored: the write fails): exit 2 and neither file is left
  const Run full = test::shell_with_quadmesh("trap '' XFSZ; ulimit -f 2; QUADMESH " + mesh + "-q -o " +
                                             quoted(dir + "/out.obj") + " --report " + quoted(dir + "/report.json"));
  expect_one_error(full, 2, dir + "/report.json: cannot write the report; no output was written");
  CHECK(files_besides(dir, setup).empty());

  // forms -o and compare --out: the same checks
  expect_one_error(quadmesh("forms " + quoted(input) + " -o " + quoted(dir + "/folder.msh")), 2, "is a folder");
  expect_one_error(quadmesh("compare " + quoted(input) + " --out " + quoted(input)), 2,
                   "exists and is not a folder");
  const std::string msh_input = dir + "/sub/input.msh";
  std::ofstream(msh_input) << "not read";
  expect_one_error(quadmesh("forms " + quoted(msh_input) + " -o " + quoted(dir + "/sub/../sub/input.msh")), 2,
                   "the same file as the input");
  expect_one_error(quadmesh("compare " + quoted(msh_input) + " --out " + quoted(dir + "/sub")), 2,
                   "compare writes input.msh there, which is the input");
  CHECK(test::slurp(msh_input) == "not read");
  CHECK(files_besides(dir, setup).empty());
}

TEST_CASE("option values: NaN, infinities, zero, negative and absurd values refused by the parser in one line") {
  const std::string dir = test::scratch_dir("hostile_values");
  const std::string input = annulus_obj(dir);
  const std::string mesh = "mesh " + quoted(input) + " -o " + quoted(dir + "/out.msh") + " ";
  const std::string forms = "forms " + quoted(input) + " ";
  const std::string compare = "compare " + quoted(input) + " --out " + quoted(dir + "/cmp") + " ";
  // the exact line of issue 22
  const Run inf = quadmesh(mesh + "--size inf");
  CHECK(inf.status == 2);
  CHECK(inf.err == "quadmesh: error: --size inf: must be a positive length or a percentage such as 1.5%\n");

  // each kind of bad value once or twice per option (a run costs 0.3 s)
  const std::map<std::string, std::vector<std::string>> values = {
      {mesh + "--size", {"nan", "-1", "1e300", "101%"}},
      {mesh + "--quads", {"0", "1.5", "99999999999999999999"}},
      {mesh + "--max-quads", {"0", "-1"}},
      {mesh + "--max-deviation", {"nan", "0", "200%"}},
      {mesh + "--corner-angle", {"nan", "-5", "1e300"}},
      {mesh + "--tip-angle", {"inf", "0"}},
      {mesh + "--coeffs", {"1,inf", "1e300"}},
      {mesh + "--msh-version", {"nan", "3"}},
      {mesh + "--form", {"0", "99999999999999999999"}},
      {mesh + "--cad-mesh-size", {"nan", "0"}},
      {forms + "--remesh-size", {"nan", "-1"}},
      {forms + "--max-triangles", {"0"}},
      {compare + "--timeout", {"nan", "-5", "1e300"}},
      {compare + "--size", {"inf"}},
  };
  for (const auto& [command, list] : values)
    for (const std::string& value : list) {
      const std::string option = command.substr(command.rfind(' ') + 1);
      CAPTURE(option);
      CAPTURE(value);
      const Run run = quadmesh(command + " " + quoted(value));
      const std::string shown = value == "1,inf" ? "inf" : value;
      expect_one_error(run, 2, option + " " + shown + ": must be");
      CHECK(run.err.find("] reading") == std::string::npos);  // refused by the parser
    }
  CHECK(files_besides(dir, {"annulus.obj"}).empty());
}

TEST_CASE("work limit: a size or count that implies too many quads is refused in a second, in little memory") {
  const std::string dir = test::scratch_dir("hostile_limit");
  const std::string kitten = quoted(test::shared_mesh("kitten-2holes.obj"));
  const std::string out = quoted(dir + "/out.msh");
  // 9 GB and 100 s to end in std::bad_alloc before the limit: now 2 GB of address
  // space and 60 s are ample (status 2, not 124 for the time-out, not a crash)
  for (const std::string request : {"--size 1e-9%", "--size 1e-7", "--quads 100000000"}) {
    CAPTURE(request);
    const auto start = std::chrono::steady_clock::now();
    const Run run = test::shell_with_quadmesh(test::address_space_bound(2000000) + "timeout 60 QUADMESH mesh " +
                                              kitten + " -o " + out + " " + request);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    expect_one_error(run, 2, "more than --max-quads 5000000");
    CHECK(run.error_lines()[0].find("raise --max-quads") != std::string::npos);
    CHECK(seconds < 10);
  }
  // CAD input is triangulated at a third of the quad size while it is read:
  // Gmsh was meshing the plate at 0.001 for minutes before any estimate
  {
    const auto start = std::chrono::steady_clock::now();
    const Run cad = test::shell_with_quadmesh(test::address_space_bound(2000000) + "timeout 60 QUADMESH mesh " +
                                              quoted(test::example("plate-two-holes.geo")) + " -o " + out +
                                              " --size 0.001");
    expect_one_error(cad, 2, "--size 0.001 implies about ");
    CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 10);
  }
  // the estimate is area / size^2: a limit below it refuses, naming both
  const Run low = quadmesh("mesh " + kitten + " -o " + out + " --size 1% --max-quads 1000");
  expect_one_error(low, 2, "--size 1% implies about ");
  CHECK(low.error_lines()[0].find("quads (surface area / size^2), more than --max-quads 1000") != std::string::npos);
  expect_one_error(quadmesh("mesh " + kitten + " -o " + out + " --quads 50 --max-quads 40"), 2,
                   "--quads 50 is more than --max-quads 40");
  // forms --remesh-size: the triangles it implies
  const Run remesh = test::shell_with_quadmesh(test::address_space_bound(2000000) + "timeout 60 QUADMESH forms " +
                                               kitten + " --remesh-size 1e-6");
  expect_one_error(remesh, 2, "--remesh-size 1e-06 implies about ");
  CHECK(remesh.error_lines()[0].find("more than --max-triangles 5000000") != std::string::npos);
  CHECK_FALSE(fs::exists(dir + "/out.msh"));
  // the default is stated in --help
  const Run help = quadmesh("mesh --help");
  CHECK(help.out.find("--max-quads") != std::string::npos);
  CHECK(help.out.find("5000000") != std::string::npos);
}

TEST_CASE("a --size larger than half the model is refused at once, naming the diagonal and the % form") {
  const std::string dir = test::scratch_dir("hostile_large_size");
  const std::string out = quoted(dir + "/out.msh");
  // kitten-2holes' diagonal is 122.6; on bunny-open (diagonal 0.25) --size 1.5
  // meant as 1.5% ran every route on a lattice of a cell or two for minutes and failed
  const Run length = quadmesh("mesh " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " + out + " --size 100");
  expect_one_error(length, 2, "--size 100 is 0.815 times the model's bounding-box diagonal (122.6");
  const std::string line = length.error_lines()[0];
  CHECK(line.find("give a length below 61.3") != std::string::npos);
  CHECK(line.find("such as --size 1.5%") != std::string::npos);
  expect_one_error(quadmesh("mesh " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " + out + " --size 60%"),
                   2, "--size 60% is 0.6 times the model's bounding-box diagonal");
  // CAD input is refused before Gmsh triangulates it at that size
  expect_one_error(quadmesh("mesh " + quoted(test::example("plate-two-holes.geo")) + " -o " + out + " --size 1000"),
                   2, "--size 1000 is ");
  CHECK_FALSE(fs::exists(dir + "/out.msh"));
}

TEST_CASE("messages: --form counts from 1, unknown commands are named, quality refuses what info refuses") {
  const std::string dir = test::scratch_dir("hostile_messages");
  const Run form = quadmesh("mesh " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " +
                            quoted(dir + "/out.msh") + " --form 99");
  expect_one_error(form, 3, "--form 99: the surface has 3 symmetric forms (1 to 3)");
  CHECK(form.err.find("computing symmetric") == std::string::npos);  // told before the forms are computed
  const Run coeffs = quadmesh("mesh " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " +
                              quoted(dir + "/out.msh") + " --coeffs 1,2");
  expect_one_error(coeffs, 3, "--coeffs has 2 values but the surface has 3 symmetric forms");
  CHECK(coeffs.err.find("computing symmetric") == std::string::npos);
  expect_one_error(quadmesh("mesh " + quoted(test::shared_mesh("kitten-2holes.obj")) + " -o " +
                            quoted(dir + "/out.msh") + " --coeffs 0,0,-0"),
                   2, "--coeffs: all coefficients are 0");

  for (const std::string args : {"frobnicate x.obj", "-q frobnicate x.obj", "--cad-mesh-size 2 frobnicate"}) {
    CAPTURE(args);
    const Run run = quadmesh(args);
    CHECK(run.status == 2);
    CHECK(run.err ==
          "quadmesh: error: unknown command 'frobnicate' (commands: info, forms, mesh, quality, compare, batch, render)\n");
  }

  // NaN coordinates and duplicate faces: info refuses them (exit 3); quality too,
  // with info's reason, rather than "min n/a"
  std::ofstream(dir + "/nan.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 nan 0\nf 1 2 3 4\n";
  std::ofstream(dir + "/duplicate.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\n"
                                           "f 1 2 3 4\nf 2 5 6 3\nf 1 2 3 4\n";
  for (const std::string name : {"nan.obj", "duplicate.obj"}) {
    CAPTURE(name);
    const std::string path = dir + "/" + name;
    const Run info = quadmesh("info --json " + quoted(path));
    CHECK(info.status == 3);
    std::string reason;
    if (info.error_lines().empty())
      reason = nlohmann::json::parse(info.out)["reason"].get<std::string>();  // info's verdict
    else
      reason = info.error_lines()[0].substr(std::string("quadmesh: error: ").size());  // refused when read
    CAPTURE(reason);
    REQUIRE_FALSE(reason.empty());
    for (const std::string json : {"", " --json"}) {
      const Run quality = quadmesh("quality " + quoted(path) + json);
      expect_one_error(quality, 3, reason);
      CHECK(quality.out.empty());
    }
  }
}

TEST_CASE("README's exit-code table is what the program does: one real case per code") {
  const std::string readme = test::slurp(std::string(QM_EXAMPLES_DIR) + "/../README.md");
  const auto section = readme.find("### Exit codes");
  REQUIRE(section != std::string::npos);
  const std::string table = readme.substr(section, readme.find("\n#", section + 1) - section);
  std::map<int, std::string> codes;
  const std::regex row(R"(\n\| (\d+) \| ([^|\n]+) \|)");
  for (auto it = std::sregex_iterator(table.begin(), table.end(), row); it != std::sregex_iterator(); ++it)
    codes[std::stoi((*it)[1])] = (*it)[2];
  REQUIRE(codes.size() == 5);

  const std::string dir = test::scratch_dir("hostile_exit_codes");
  const std::string kitten = quoted(test::shared_mesh("kitten-2holes.obj"));
  test::write_obj(test::disk(3, 12), dir + "/disk.obj");
  // a long arm: every form decays along it and the quads cannot conform (README Limits);
  // on the triangulation the CAD reader made before issue 21 (a third of the quad
  // size: 6% of the 204 diagonal / 3) the rounding leaves folds it cannot remove
  const std::string bracket = test::write_text(dir, "bracket.geo", test::long_arm_bracket_geo());
  const std::string out = " -o " + quoted(dir + "/out.msh") + " -q";
  // per code: a word its meaning must have, and a run that must end with it
  const std::map<int, std::pair<std::string, std::string>> cases = {
      {0, {"success", "info " + kitten}},
      {1, {"numerical failure", "mesh " + quoted(bracket) + out + " --size 6% --cad-mesh-size 4.08"}},
      {2, {"the input or another output", "mesh " + kitten + out + " --report " + quoted(dir + "/out.msh")}},
      {3, {"bad input", "mesh " + quoted(dir + "/missing.obj") + out}},
      {4, {"unsupported", "mesh " + quoted(dir + "/disk.obj") + out}},
  };
  for (const auto& [code, meaning] : codes) {
    CAPTURE(code);
    CAPTURE(meaning);
    REQUIRE(cases.count(code) == 1);
    CHECK(meaning.find(cases.at(code).first) != std::string::npos);
    const Run run = quadmesh(cases.at(code).second);
    CHECK(run.status == code);
    CHECK(run.error_lines().size() == (code == 0 ? 0u : 1u));
  }
  CHECK_FALSE(fs::exists(dir + "/out.msh"));
}
