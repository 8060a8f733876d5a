// Hostile CAD input (issue 22): a .geo script must not run commands, write files,
// exit the program, read files outside its folder, hang or exhaust memory. Each
// test writes its own .geo and checks the library (qm::Error with one line) and
// the real program (exit status 3, exactly one stderr line, no output file).
#include "io/child_process.h"
#include "io/read_surface.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/long_edges.h"
#include "libquadmesh/pipeline/internal/retry_policy.h"
#include "libquadmesh/quality/hausdorff.h"
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>
#include <gmsh.h>

#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

using namespace qm;
namespace fs = std::filesystem;

namespace {

/// A 100 x 60 OpenCASCADE plate with one hole: a few hundred triangles at the
/// automatic size.
const std::string plate =
    "SetFactory(\"OpenCASCADE\");\n"
    "Rectangle(1) = {0, 0, 0, 100, 60};\n"
    "Disk(2) = {50, 30, 0, 10, 10};\n"
    "BooleanDifference{ Surface{1}; Delete; }{ Surface{2}; Delete; }\n";

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Run {
  int status = -1;
  double seconds = 0;
  std::string err;
  std::vector<std::string> lines() const {
    std::vector<std::string> result;
    std::istringstream in(err);
    for (std::string line; std::getline(in, line);) result.push_back(line);
    return result;
  }
};

/// Runs `quadmesh -q ARGS` through bash, after `prefix` (ulimit, timeout, ...).
Run quadmesh(const std::string& args, const std::string& prefix = "timeout 120 ") {
  static int counter = 0;
  const std::string dir = test::scratch_dir("cad_sandbox_run_" + std::to_string(counter++));
  const std::string script = test::write_text(
      dir, "run.sh",
      prefix + "'" + QM_QUADMESH_BIN + "' -q " + args + " >'" + dir + "/out' 2>'" + dir +
          "/err' </dev/null\n");
  const auto start = std::chrono::steady_clock::now();
  const int raw = std::system(("bash '" + script + "'").c_str());
  Run run;
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.err = slurp(dir + "/err");
  return run;
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

/// The program refused: status 3, one line "quadmesh: error: ..." holding `needle`,
/// and `output` not written.
void check_refused(const Run& run, const std::string& needle, const std::string& output) {
  CAPTURE(run.err);
  CHECK(run.status == 3);
  const auto lines = run.lines();
  REQUIRE(lines.size() == 1);
  CHECK(lines[0].rfind("quadmesh: error: ", 0) == 0);
  CHECK(lines[0].size() > std::string("quadmesh: error: ").size());
  CHECK(lines[0].find(needle) != std::string::npos);
  CHECK_FALSE(fs::exists(output));
}

/// The library's one-line error for reading `path`, or "" if it read.
std::string read_error(const std::string& path, const io::ReadOptions& options = {}) {
  try {
    io::read_surface(path, options);
  } catch (const Error& e) {
    CHECK(e.code() == ErrorCode::bad_input);
    const std::string message = e.what();
    CHECK(message.find('\n') == std::string::npos);
    return message;
  }
  return {};
}

bool contains(const std::string& text, const std::string& needle) {
  return text.find(needle) != std::string::npos;
}

io::ReadOptions allowing() {
  io::ReadOptions options;
  options.sandbox.allow_geo_commands = true;
  return options;
}

void check_same(const io::SurfaceFile& a, const io::SurfaceFile& b) {
  CHECK(a.format == b.format);
  CHECK(a.cad_mesh_size == b.cad_mesh_size);
  CHECK(a.polygons_split == b.polygons_split);
  CHECK(a.soup.points == b.soup.points);
  CHECK(a.soup.point_labels == b.soup.point_labels);
  CHECK(a.soup.triangles == b.soup.triangles);
  CHECK(a.soup.triangle_labels == b.soup.triangle_labels);
  REQUIRE(a.soup.cad.edges.size() == b.soup.cad.edges.size());
  for (std::size_t i = 0; i < a.soup.cad.edges.size(); ++i) {
    CHECK(a.soup.cad.edges[i].a == b.soup.cad.edges[i].a);
    CHECK(a.soup.cad.edges[i].b == b.soup.cad.edges[i].b);
    CHECK(a.soup.cad.edges[i].curve == b.soup.cad.edges[i].curve);
  }
  REQUIRE(a.soup.cad.groups.size() == b.soup.cad.groups.size());
  for (std::size_t i = 0; i < a.soup.cad.groups.size(); ++i) {
    CHECK(a.soup.cad.groups[i].tag == b.soup.cad.groups[i].tag);
    CHECK(a.soup.cad.groups[i].name == b.soup.cad.groups[i].name);
    CHECK(a.soup.cad.groups[i].curves == b.soup.cad.groups[i].curves);
  }
}

}  // namespace

TEST_CASE("SystemCall is refused unless --allow-geo-commands; comments and strings are not code") {
  const std::string dir = test::scratch_dir("cad_systemcall");
  const std::string marker = dir + "/MARKER";
  const std::string geo =
      test::write_text(dir, "plate.geo", plate + "SystemCall \"touch " + marker + "\";\n");
  const std::string output = dir + "/out.msh";

  const std::string message = read_error(geo);
  CHECK(message == geo + ": line 5: SystemCall runs a shell command; refused "
                         "(CadSandbox::allow_geo_commands allows it)");
  CHECK_FALSE(fs::exists(marker));

  check_refused(quadmesh("mesh " + quoted(geo) + " -o " + quoted(output)),
                "plate.geo: line 5: SystemCall runs a shell command; refused (--allow-geo-commands allows it)",
                output);
  CHECK_FALSE(fs::exists(marker));

  // allowed: the command runs and the plate meshes (option after the subcommand too)
  const Run allowed = quadmesh("mesh " + quoted(geo) + " -o " + quoted(output) +
                               " --allow-geo-commands");
  CAPTURE(allowed.err);
  CHECK(allowed.status == 0);
  CHECK(fs::exists(marker));
  CHECK(fs::exists(output));

  // the word in a comment, a block comment or a string is not a command
  const std::string quiet = test::write_text(
      dir, "quiet.geo",
      "// SystemCall \"touch " + marker + "2\";\n/* SystemCall \"x\";\n Exit; */\n" + plate +
          "Physical Curve('SystemCall \"x\"; Exit;') = {1};\n" +
          "Physical Curve(\"Save 'y'; // \") = {2};\n");
  CHECK(read_error(quiet).empty());
  CHECK_FALSE(fs::exists(marker + "2"));
}

TEST_CASE("writing, deleting and creating files is refused") {
  const std::string dir = test::scratch_dir("cad_writes");
  const std::string output = dir + "/out.msh";
  // absolute paths: Gmsh takes some of them relative to its working folder
  const std::string out = "\"" + dir + "/OUT.txt\"";
  const std::map<std::string, std::string> cases = {
      {"Printf(\"x\") > " + out + ";", "line 5: Printf writes to a file (>)"},
      {"Printf(\"x %g\", 2) >> " + out + ";", "line 5: Printf writes to a file (>>)"},
      {"Save " + out + ";", "line 5: Save writes a file"},
      {"Print " + out + ";", "line 5: Print writes a file"},
      {"CreateDir " + out + ";", "line 5: CreateDir creates a folder"},
      {"Delete File " + out + ";", "line 5: Delete File deletes a file"},
      {"NonBlockingSystemCall \"touch " + dir + "/OUT.txt\";", "line 5: NonBlockingSystemCall runs a shell"},
      {"Merge \"/etc/passwd\";", "line 5: Merge reads \"/etc/passwd\", outside the script's folder"},
      {"v() = ShapeFromFile(\"/tmp/../etc/x.brep\");", "line 5: ShapeFromFile reads"},
      {"Include StrCat(\"a\", \".geo\");", "line 5: Include of a computed path"},
  };
  for (const auto& [command, needle] : cases) {
    CAPTURE(command);
    const std::string geo = test::write_text(dir, "plate.geo", plate + command + "\n");
    CHECK(contains(read_error(geo), "plate.geo: " + needle));
    CHECK(contains(read_error(geo), "; refused (CadSandbox::allow_geo_commands allows it)"));
    CHECK_FALSE(fs::exists(dir + "/OUT.txt"));
  }
  // Printf without a file and Print.* options are fine
  const std::string fine = test::write_text(
      dir, "fine.geo", plate + "Printf(\"hello\");\nPrint.Width = 100;\nx = 2;\n");
  CHECK(read_error(fine).empty());

  const std::string geo = test::write_text(dir, "plate.geo", plate + "Printf(\"x\") > " + out + ";\n");
  check_refused(quadmesh("mesh " + quoted(geo) + " -o " + quoted(output)),
                "plate.geo: line 5: Printf writes to a file", output);
  CHECK_FALSE(fs::exists(dir + "/OUT.txt"));
  // allowed, Gmsh writes it (so the checks above can see a file written)
  CHECK(read_error(geo, allowing()).empty());
  CHECK(slurp(dir + "/OUT.txt") == "x\n");
}

TEST_CASE("includes: itself, a cycle, outside the folder, and the included script's commands") {
  const std::string dir = test::scratch_dir("cad_includes");
  const std::string output = dir + "/sub/out.msh";
  fs::create_directories(dir + "/sub");
  const std::string self = test::write_text(dir + "/sub", "self.geo", plate + "Include \"self.geo\";\n");
  CHECK(read_error(self) ==
        self + ": line 5: Include \"self.geo\" includes a script that is already being read (an "
               "include cycle); refused");
  // refused even when commands are allowed (Gmsh would recurse for half a minute)
  CHECK(contains(read_error(self, allowing()), "an include cycle"));
  check_refused(quadmesh("mesh " + quoted(self) + " -o " + quoted(output)),
                "self.geo: line 5: Include \"self.geo\" includes a script", output);

  test::write_text(dir + "/sub", "a.geo", "Include \"b.geo\";\n");
  test::write_text(dir + "/sub", "b.geo", "\nInclude \"a.geo\";\n");
  const std::string cycle = test::write_text(dir + "/sub", "top.geo", plate + "Include \"a.geo\";\n");
  CHECK(contains(read_error(cycle), "b.geo: line 2: Include \"a.geo\" includes a script"));

  test::write_text(dir, "other.geo", "x = 1;\n");
  const std::string outside =
      test::write_text(dir + "/sub", "plate.geo", plate + "Include \"../other.geo\";\n");
  CHECK(read_error(outside) ==
        outside + ": line 5: Include reads \"../other.geo\", outside the script's folder; refused "
                  "(CadSandbox::allow_geo_commands allows it)");
  check_refused(quadmesh("mesh " + quoted(outside) + " -o " + quoted(output)),
                "plate.geo: line 5: Include reads \"../other.geo\", outside the script's folder",
                output);
  CHECK(read_error(outside, allowing()).empty());

  // an included script in the same folder is read, and checked the same way
  test::write_text(dir + "/sub", "part.geo", "// the plate\n" + plate);
  const std::string includes = test::write_text(dir + "/sub", "main.geo", "Include \"part.geo\";\n");
  CHECK(read_error(includes).empty());
  test::write_text(dir + "/sub", "bad.geo", "x = 1;\nSystemCall \"true\";\n");
  const std::string bad = test::write_text(dir + "/sub", "main2.geo", plate + "Include \"bad.geo\";\n");
  CHECK(contains(read_error(bad), "bad.geo: line 2: SystemCall runs a shell command; refused"));
}

TEST_CASE("Exit: refused as a command; allowed, it must leave a surface mesh") {
  const std::string dir = test::scratch_dir("cad_exit");
  const std::string output = dir + "/out.msh";
  const std::string geo = test::write_text(dir, "plate.geo", plate + "Exit;\n");
  CHECK(read_error(geo) == geo + ": line 5: Exit ends the program; refused "
                                 "(CadSandbox::allow_geo_commands allows it)");
  check_refused(quadmesh("mesh " + quoted(geo) + " -o " + quoted(output)),
                "plate.geo: line 5: Exit ends the program", output);

  CHECK(read_error(geo, allowing()) == geo + ": the script exited before any surface was meshed");
  check_refused(quadmesh("--allow-geo-commands mesh " + quoted(geo) + " -o " + quoted(output)),
                "plate.geo: the script exited before any surface was meshed", output);

  // a script that meshes and then exits gives its mesh
  const std::string meshed = test::write_text(dir, "meshed.geo", plate + "Mesh 2;\nExit;\n");
  const io::SurfaceFile file = io::read_surface(meshed, allowing());
  CHECK(file.soup.triangles.size() > 100);
}

TEST_CASE("a script that loops forever ends at --cad-timeout") {
  const std::string dir = test::scratch_dir("cad_loop");
  const std::string output = dir + "/out.msh";
  const std::string geo = test::write_text(
      dir, "loop.geo", "x = 0;\nFor i In {1:2000000000}\n  x = x + i;\nEndFor\n" + plate);
  io::ReadOptions options;
  options.sandbox.timeout_seconds = 1;
  const auto start = std::chrono::steady_clock::now();
  CHECK(read_error(geo, options) ==
        geo + ": Gmsh did not finish within 1 s (CadSandbox::timeout_seconds): stopped; a script that "
              "loops or a mesh size far too small for the model does this");
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 20);

  const Run run = quadmesh("mesh " + quoted(geo) + " -o " + quoted(output) + " --cad-timeout 2",
                           "timeout 60 ");
  CHECK(run.status != 124);
  check_refused(run, "loop.geo: Gmsh did not finish within 2 s (--cad-timeout)", output);
  CHECK(run.seconds < 30);
}

TEST_CASE("at the time-out, what the script started is killed too") {
  const std::string dir = test::scratch_dir("cad_group");
  const std::string marker = dir + "/LATE";
  const std::string geo = test::write_text(
      dir, "slow.geo", plate + "SystemCall \"sleep 4; touch " + marker + "\";\n");
  io::ReadOptions options = allowing();
  options.sandbox.timeout_seconds = 1;
  CHECK(contains(read_error(geo, options), "slow.geo: Gmsh did not finish within 1 s"));
  sleep(6);
  CHECK_FALSE(fs::exists(marker));
}

TEST_CASE("a mesh size far too small ends at the time or memory limit") {
  const std::string dir = test::scratch_dir("cad_tiny");
  const std::string output = dir + "/out.msh";
  const std::string geo = test::write_text(
      dir, "tiny.geo", plate + "Mesh.MeshSizeMax = 1e-4;\nMesh 2;\n");
  const Run run = quadmesh("mesh " + quoted(geo) + " -o " + quoted(output) + " --cad-timeout 5",
                           test::address_space_bound(4000000) + "timeout 120 ");
  CHECK(run.status != 124);
  const bool limit_line = contains(run.err, "tiny.geo: Gmsh did not finish within 5 s (--cad-timeout)") ||
                          contains(run.err, "tiny.geo: Gmsh needed more than");
  CHECK(limit_line);
  check_refused(run, "tiny.geo: Gmsh", output);
  CHECK(run.seconds < 60);

  // a smaller memory limit than the time needs: the memory line (no such limit
  // under AddressSanitizer: io::address_space_limits_work)
  if (!io::address_space_limits_work()) return;
  const Run memory = quadmesh("mesh " + quoted(geo) + " -o " + quoted(output) +
                                  " --cad-timeout 100 --cad-memory 0.5",
                              "timeout 120 ");
  CHECK(memory.status != 124);
  check_refused(memory, "tiny.geo: Gmsh needed more than 0.5 GiB (--cad-memory)", output);
}

TEST_CASE("--cad-timeout and --cad-memory take positive finite numbers") {
  const std::string geo = test::example("plate-two-holes.geo");
  for (const char* bad : {"nan", "inf", "0", "-1", "-inf", "x"}) {
    CAPTURE(bad);
    for (const char* option : {"--cad-timeout", "--cad-memory"}) {
      const Run run = quadmesh(std::string("info ") + quoted(geo) + " " + option + " " + bad);
      CHECK(run.status == 2);
      REQUIRE(run.lines().size() == 1);
      CHECK(contains(run.lines()[0], option));
      CHECK(contains(run.lines()[0], "must be a positive number"));
    }
  }
  io::ReadOptions options;
  options.sandbox.timeout_seconds = std::numeric_limits<double>::quiet_NaN();
  CHECK(contains(read_error(geo, options), "CadSandbox::timeout_seconds must be a positive number"));
}

TEST_CASE("the bundled examples read as before (counts of the in-process reader)") {
  // Recorded with `quadmesh info --json` (faces, cad_curve_edges) with the
  // automatic CAD triangle size of issue 21 (0.75 x the quad size, 15 degrees of
  // bend per triangle at most); the child-process reader must give them exactly.
  struct Counts {
    std::size_t triangles, curve_edges;
  };
  const std::map<std::string, Counts> counts = {
      {"annulus.geo", {4479, 267}},
      {"curved-shell-holes.geo", {8465, 317}},
      {"l-plate-three-holes.geo", {4760, 306}},
      {"plate-two-holes.geo", {6178, 310}},
      {"plate-v-hole.geo", {6349, 323}},
  };
  for (const auto& [name, count] : counts) {
    CAPTURE(name);
    const io::SurfaceFile file = io::read_surface(test::example(name));
    CHECK(file.soup.triangles.size() == count.triangles);
    CHECK(file.soup.cad.edges.size() == count.curve_edges);
  }
}

TEST_CASE("the automatic CAD triangles are no wider than the quads (the input is meshed once)") {
  // quadmesh splits triangles wider than the quads and meshes both triangulations
  // when they cover long_edge_area_threshold of the area or more: the automatic
  // CAD size must stay under that, at the default size and at 1.5% and 0.75%.
  for (const char* name : {"plate-two-holes.geo", "curved-shell-holes.geo", "l-plate-three-holes.geo"})
    for (const double relative : {1.0 / 60.0, 0.015, 0.0075}) {
      CAPTURE(name);
      CAPTURE(relative);
      io::ReadOptions options;
      options.quad_size_relative = relative;
      const io::SurfaceFile file = io::read_surface(test::example(name), options);
      const double quad = relative * bounding_box_diagonal(file.soup.points, file.soup.triangles);
      CHECK(file.cad_mesh_size == doctest::Approx(0.75 * quad).epsilon(1e-3));  // Gmsh pads its box a little
      CHECK(long_edge_area_fraction(file.soup, quad) < long_edge_area_threshold);
      CHECK(long_edge_area_fraction(file.soup, 1.5 * quad) == 0.0);
    }
}

TEST_CASE("a .geo and a STEP through the child give the same SurfaceFile as in-process") {
  io::ReadOptions here;
  here.sandbox.in_process = true;
  const std::string geo = test::example("plate-two-holes.geo");
  const io::SurfaceFile child = io::read_surface(geo);
  check_same(child, io::read_surface(geo, here));
  std::vector<std::string> names;
  for (const auto& g : child.soup.cad.groups) names.push_back(g.name);
  CHECK(names == std::vector<std::string>{"hole_left", "hole_right", "outer"});
  CHECK(child.soup.cad.edges.size() > 50);

  // a STEP file, written by Gmsh in this process (the child then starts from a
  // process where Gmsh is initialized)
  const std::string dir = test::scratch_dir("cad_step");
  const std::string step = dir + "/plate.step";
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(geo);
  gmsh::write(step);
  gmsh::clear();
  REQUIRE(fs::exists(step));
  io::ReadOptions sized;
  sized.cad_mesh_size = 3.0;
  const io::SurfaceFile step_child = io::read_surface(step, sized);
  sized.sandbox.in_process = true;
  check_same(step_child, io::read_surface(step, sized));
  CHECK(step_child.cad_mesh_size == 3.0);
  CHECK(step_child.soup.triangles.size() > 100);

  // a Gmsh error travels back as before
  const std::string broken = test::write_text(dir, "broken.geo", "Point(1) = {0, 0, 0;\n");
  const std::string message = read_error(broken);
  CHECK(contains(message, "broken.geo: Gmsh could not read it: "));
  CHECK(message == read_error(broken, here));
}

TEST_CASE("a Gmsh crash ends with one line") {
  io::ReadOptions options;
  options.sandbox.crash_on_purpose = true;
  const std::string geo = test::example("annulus.geo");
  CHECK(read_error(geo, options) == geo + ": Gmsh crashed (signal 11)");
  CHECK(read_error(test::shared_mesh("hinge.stl"), options) ==
        test::shared_mesh("hinge.stl") + ": Gmsh crashed (signal 11)");
}

TEST_CASE("run_in_child: exit status, crash, time-out and the address-space limit") {
  io::ChildOptions options;
  options.timeout_seconds = 20;
  CHECK(io::run_in_child([] { return 0; }, options).status == io::ChildStatus::ok);
  CHECK(io::run_in_child([] { return 5; }, options).exit_code == 5);
  const auto crash = io::run_in_child([] { raise(SIGSEGV); return 0; }, options);
  CHECK(crash.status == io::ChildStatus::crashed);
  CHECK(crash.signal == SIGSEGV);
  options.timeout_seconds = 0.3;
  CHECK(io::run_in_child([] { for (;;) pause(); return 0; }, options).status ==
        io::ChildStatus::timeout);
  if (!io::address_space_limits_work()) return;
  options.timeout_seconds = 20;
  options.memory_limit_bytes = std::uint64_t{1} << 30;
  const auto big = io::run_in_child(
      [] { return std::malloc(std::size_t{3} << 30) == nullptr ? 7 : 0; }, options);
  CHECK(big.exit_code == 7);
}
