// quadmesh compare: the child-process runner, and the tool as a user runs it:
// every method is a row, and a method that crashes is a row, not a failure.
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"
#include "tools/compare/child_process.h"
#include "tools/compare/gmsh_version.h"
#include "tools/compare/methods.h"

#include <doctest/doctest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace qm;
using tools::ChildOptions;
using tools::ChildStatus;
using tools::run_child;

namespace {

const std::vector<std::string> kMethods = {"quadmesh", "gmsh-blossom-same-triangulation",
                                           "gmsh-frontal-blossom", "gmsh-frontal-blossom-full-quad",
                                           "gmsh-quad-frontal"};
const std::vector<std::string> kQualityKeys = {"quads",
                                               "triangles",
                                               "inverted",
                                               "min_scaled_jacobian",
                                               "mean_scaled_jacobian",
                                               "angle_dev_mean",
                                               "angle_dev_p99",
                                               "irregular_vertices",
                                               "boundary_loops",
                                               "euler_characteristic",
                                               "hausdorff_rel"};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// Runs `[env] quadmesh compare ARGS` with the report folder `dir`; returns the exit status.
int compare(const std::string& env, const std::string& args, const std::string& dir) {
  const std::string command = env + " '" + QM_QUADMESH_BIN + "' compare " + args + " --out '" +
                              dir + "' -q >'" + dir + ".out' 2>'" + dir + ".err' </dev/null";
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

const std::string kQuasiStructured = "gmsh-quasi-structured";

/// report.json has every method, in order, each row complete for its status:
/// the five that run with any Gmsh, and the quasi-structured one when `quasi`
/// (a Gmsh 4.9 or later), else listed as skipped. Every row with a mesh has its
/// picture in report.md, every row without says why in its cell.
nlohmann::json check_report(const std::string& dir, bool quasi = false) {
  namespace fs = std::filesystem;
  REQUIRE(fs::exists(dir + "/report.json"));
  const auto j = nlohmann::json::parse(slurp(dir + "/report.json"));
  const std::string md = slurp(dir + "/report.md");
  CHECK(j["input"].is_string());
  CHECK(j["size"].get<double>() > 0);
  std::vector<std::string> methods = kMethods;
  if (quasi) methods.push_back(kQuasiStructured);
  REQUIRE(j["methods"].size() == methods.size());
  if (quasi) {
    CHECK(j["skipped"].empty());
  } else {
    REQUIRE(j["skipped"].size() == 1);
    CHECK(j["skipped"][0]["name"] == kQuasiStructured);
    const std::string reason = j["skipped"][0]["reason"];
    CHECK(reason.find("quasi-structured quad mesher (Mesh.Algorithm = 11") != std::string::npos);
    CHECK(md.find("| `" + kQuasiStructured + "` | skipped |") != std::string::npos);
    CHECK(md.find("skipped: " + reason) != std::string::npos);
  }
  for (std::size_t i = 0; i < methods.size(); ++i) {
    const auto& m = j["methods"][i];
    CAPTURE(m.dump());
    CHECK(m["name"] == methods[i]);
    const std::string status = m["status"];
    CHECK((status == "ok" || status == "crashed" || status == "timeout" || status == "failed"));
    CHECK(m["seconds"].get<double>() >= 0);
    if (status == "ok") {
      REQUIRE(m["quality"].is_object());
      for (const std::string& key : kQualityKeys)
        CHECK(m["quality"].contains(key));
      // faces: quads, or only triangles from the fake Gmsh below (Debian's 4.8.4 meshes
      // Mesh.Algorithm 11 as triangles)
      CHECK(m["quality"]["quads"].get<int>() + m["quality"]["triangles"].get<int>() > 0);
      if (methods[i] != kQuasiStructured) CHECK(m["quality"]["quads"].get<int>() > 0);
      CHECK(fs::exists(dir + "/" + m["mesh"].get<std::string>()));
      const std::string picture = m["picture"];
      CHECK(picture == methods[i] + ".svg");
      CHECK(slurp(dir + "/" + picture).rfind("<svg", 0) == 0);
      CHECK(md.find("![" + methods[i] + "](" + picture + ")") != std::string::npos);
    } else {
      CHECK(m["quality"].is_null());
      CHECK(m["picture"].is_null());
      CHECK_FALSE(fs::exists(dir + "/" + methods[i] + ".svg"));
      CHECK(!m["detail"].get<std::string>().empty());
      CHECK(md.find("no mesh: " + status + ": " + m["detail"].get<std::string>()) != std::string::npos);
    }
  }
  for (const std::string& name : methods)
    CHECK(md.find("| `" + name + "` |") != std::string::npos);
  CHECK(md.find("angle-deviation.svg") != std::string::npos);
  CHECK(md.find("scaled-jacobian.svg") != std::string::npos);
  CHECK(md.find("**Verdict.**") != std::string::npos);
  for (const char* svg : {"/angle-deviation.svg", "/scaled-jacobian.svg"})
    CHECK(slurp(dir + svg).rfind("<svg", 0) == 0);
  CHECK(fs::exists(dir + "/input.msh"));
  return j;
}

}  // namespace

TEST_CASE("Gmsh versions: parsed from gmsh --version; the quasi-structured mesher from 4.9 on") {
  using tools::parse_gmsh_version;
  const auto v = parse_gmsh_version("4.15.2-git");
  REQUIRE(v);
  CHECK(v->major == 4);
  CHECK(v->minor == 15);
  CHECK(v->patch == 2);
  CHECK(parse_gmsh_version("4.8")->minor == 8);
  CHECK_FALSE(parse_gmsh_version("gmsh"));
  CHECK_FALSE(parse_gmsh_version(""));
  CHECK_FALSE(parse_gmsh_version("4"));
  CHECK(tools::quasi_structured_missing("4.9.0").empty());
  CHECK(tools::quasi_structured_missing("4.15.2-git").empty());
  CHECK(tools::quasi_structured_missing("5.0").empty());
  CHECK(tools::quasi_structured_missing("4.8.4") ==
        "Gmsh 4.8.4 lacks the quasi-structured quad mesher (Mesh.Algorithm = 11 came with Gmsh 4.9); give a newer "
        "Gmsh with --gmsh");
  CHECK(tools::quasi_structured_missing("").find("did not tell its version") != std::string::npos);
  CHECK_FALSE(tools::quasi_structured_missing("4.10.0").size());  // 4.10 is after 4.9, not before
}

TEST_CASE("comparison_methods: the quasi-structured mesher at twice the size, skipped before Gmsh 4.9") {
  tools::MethodSetup setup;
  setup.input = "/data/plate.step";
  setup.cad = true;
  setup.triangulation = "input.msh";
  setup.size = 1.5;
  setup.gmsh_version = "4.11.1";
  const auto methods = tools::comparison_methods(setup);
  REQUIRE(methods.size() == 6);
  for (std::size_t i = 0; i < kMethods.size(); ++i) CHECK(methods[i].name == kMethods[i]);
  const tools::Method& quasi = methods.back();
  CHECK(quasi.name == kQuasiStructured);
  CHECK(quasi.skipped_because.empty());
  CHECK(quasi.script.find("Merge \"/data/plate.step\";") != std::string::npos);
  CHECK(quasi.script.find("Mesh.Algorithm = 11;") != std::string::npos);
  CHECK(quasi.script.find("Mesh.MeshSizeMin = 3;") != std::string::npos);  // 2 x 1.5
  CHECK(quasi.script.find("Mesh.MeshSizeMax = 3;") != std::string::npos);
  CHECK(quasi.argv == std::vector<std::string>{"gmsh", "gmsh-quasi-structured.geo", "-", "-nopopup"});

  setup.gmsh_version = "4.8.4";
  const auto old = tools::comparison_methods(setup);
  REQUIRE(old.size() == 6);
  CHECK(old.back().skipped_because.find("Gmsh 4.8.4 lacks") == 0);
  for (std::size_t i = 0; i + 1 < old.size(); ++i) CHECK(old[i].skipped_because.empty());
}

TEST_CASE("run_child tells ok, failed, crashed and timeout apart") {
  ChildOptions options;
  options.timeout_seconds = 20;
  CHECK(run_child({"true"}, options).status == ChildStatus::ok);

  const auto failed = run_child({"sh", "-c", "exit 3"}, options);
  CHECK(failed.status == ChildStatus::failed);
  CHECK(failed.exit_code == 3);
  CHECK(failed.detail == "exit status 3");

  const auto segv = run_child({"sh", "-c", "kill -SEGV $$"}, options);
  CHECK(segv.status == ChildStatus::crashed);
  CHECK(segv.signal == SIGSEGV);

  ChildOptions hook = options;
  hook.crash_on_purpose = true;
  const auto hooked = run_child({"true"}, hook);
  CHECK(hooked.status == ChildStatus::crashed);
  CHECK(hooked.signal == SIGSEGV);

  const auto missing = run_child({"/nonexistent/program"}, options);
  CHECK(missing.status == ChildStatus::failed);
  CHECK(missing.exit_code == 127);

  // The time limit kills the whole process group (sh and its sleep).
  ChildOptions short_limit;
  short_limit.timeout_seconds = 0.3;
  const auto slow = run_child({"sh", "-c", "sleep 30; true"}, short_limit);
  CHECK(slow.status == ChildStatus::timeout);
  CHECK(slow.seconds >= 0.3);
  CHECK(slow.seconds < 5);
}

TEST_CASE("run_child writes the child's output to the log, in the working folder") {
  const std::string dir = test::scratch_dir("compare_child_log");
  ChildOptions options;
  options.log_path = dir + "/log.txt";
  options.working_dir = dir;
  CHECK(run_child({"sh", "-c", "echo out; echo err >&2; pwd"}, options).status == ChildStatus::ok);
  const std::string log = slurp(dir + "/log.txt");
  CHECK(log.find("out") != std::string::npos);
  CHECK(log.find("err") != std::string::npos);
  CHECK(log.find(std::filesystem::path(dir).filename().string()) != std::string::npos);
}

TEST_CASE("compare on a small discrete input: valid JSON with every row, exit 0") {
  const std::string dir = test::scratch_dir("compare_annulus");
  test::write_obj(test::annulus(1.0, 2.0, 6, 48), dir + "/annulus.obj");
  const std::string out = dir + "/report";
  CHECK(compare("", "'" + dir + "/annulus.obj' --size 8% --timeout 60", out) == 0);
  const auto j = check_report(out);
  const auto& ours = j["methods"][0];
  CHECK(ours["status"] == "ok");
  CHECK(ours["quality"]["triangles"] == 0);
  CHECK(ours["quality"]["euler_characteristic"] == 0);
  CHECK(ours["quality"]["boundary_loops"] == 2);
  CHECK(j["methods"][2]["status"] == "ok");  // Gmsh's Frontal-Delaunay + Blossom
  // every picture from the same view: the annulus lies in the plane z = 0
  CHECK(j["view"][2].get<double>() == doctest::Approx(1.0));
  const std::string picture = slurp(out + "/quadmesh.svg");
  const int quads = ours["quality"]["quads"];
  CHECK(picture.find("<text id=\"caption-counts\" x=\"10.0\" y=") != std::string::npos);
  CHECK(picture.find(">" + std::to_string(quads) + " quads, 0 triangles, ") != std::string::npos);
}

TEST_CASE("a Gmsh that says 4.9 or later gets the quasi-structured row; its script asks for Mesh.Algorithm 11") {
  const std::string dir = test::scratch_dir("compare_quasi");
  test::write_obj(test::annulus(1.0, 2.0, 4, 32), dir + "/annulus.obj");
  // Debian's Gmsh under a newer version's name: what matters here is the row and
  // its script, not the Gmsh that meshes it
  const std::string fake = dir + "/gmsh-4.11";
  std::ofstream(fake) << "#!/bin/sh\n[ \"$1\" = --version ] && { echo 4.11.1 >&2; exit 0; }\nexec gmsh \"$@\"\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const std::string out = dir + "/report";
  // given as a path relative to where compare starts: every method runs in the output folder
  CHECK(compare("cd '" + dir + "' &&", "annulus.obj --size 10% --timeout 60 --gmsh ./gmsh-4.11", out) == 0);
  const auto j = check_report(out, true);
  CHECK(j["gmsh_version"] == "4.11.1");
  CHECK(j["methods"][2]["status"] == "ok");  // the fake was found from the output folder
  for (std::size_t row = 1; row < j["methods"].size(); ++row) CHECK(j["methods"][row]["detail"] != "exit status 127");
  CHECK(j["methods"][5]["name"] == kQuasiStructured);
  const std::string script = slurp(out + "/gmsh-quasi-structured.geo");
  CHECK(script.find("Mesh.Algorithm = 11;") != std::string::npos);
  const double size = j["size"];
  CHECK(script.find(fmt::format("Mesh.MeshSizeMin = {:.17g};", 2 * size)) != std::string::npos);
  CHECK(slurp(out + "/report.md").find("Every Gmsh row ran `./gmsh-4.11`, Gmsh 4.11.1.") != std::string::npos);
}

TEST_CASE("a method killed by a signal is a `crashed` row; the tool still exits 0") {
  const std::string out = test::scratch_dir("compare_crash") + "/report";
  const int status = compare("QUADMESH_COMPARE_CRASH=quadmesh,gmsh-frontal-blossom",
                             "'" + test::example("annulus.geo") + "' --size 12% --timeout 60", out);
  CHECK(status == 0);
  const auto j = check_report(out);
  for (int row : {0, 2}) {
    CAPTURE(row);
    CHECK(j["methods"][row]["status"] == "crashed");
    CHECK(j["methods"][row]["quality"].is_null());
    CHECK(j["methods"][row]["detail"].get<std::string>().find("signal 11") != std::string::npos);
  }
  CHECK(j["methods"][1]["status"] == "ok");
  CHECK(j["methods"][3]["status"] == "ok");
  CHECK(slurp(out + "/report.md").find("crashed") != std::string::npos);
}

TEST_CASE("a method that outlives --timeout is a `timeout` row, killed; the tool exits 0") {
  const std::string dir = test::scratch_dir("compare_timeout");
  test::write_obj(test::annulus(1.0, 2.0, 4, 32), dir + "/annulus.obj");
  // A stand-in for Gmsh that answers --version and then never finishes a mesh.
  const std::string fake = dir + "/slow-gmsh";
  std::ofstream(fake)
      << "#!/bin/sh\n[ \"$1\" = --version ] && { echo 0.0-slow >&2; exit 0; }\nsleep 60\n";
  std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
  const std::string out = dir + "/report";
  const std::string timeout = std::to_string(2 * test::sanitizer_slowdown());  // under the fake's 60 s
  CHECK(compare("", "'" + dir + "/annulus.obj' --size 10% --timeout " + timeout + " --gmsh '" + fake + "'",
                out) == 0);
  const auto j = check_report(out);
  CHECK(j["gmsh_version"] == "0.0-slow");
  CHECK(j["skipped"][0]["reason"].get<std::string>().find("Gmsh 0.0-slow lacks") == 0);
  CHECK(j["methods"][0]["status"] == "ok");
  for (int row = 1; row < 5; ++row) {
    CAPTURE(row);
    CHECK(j["methods"][row]["status"] == "timeout");
    // killed at the time limit, well before the fake's 60 s
    CHECK(j["methods"][row]["seconds"].get<double>() >= 2.0 * test::sanitizer_slowdown());
    CHECK(j["methods"][row]["seconds"].get<double>() < 10.0 * test::sanitizer_slowdown());
  }
}

TEST_CASE("with a real Gmsh 4.9 or later (QUADMESH_TEST_GMSH), the quasi-structured row is a quad mesh" *
          doctest::test_suite("slow")) {
  const char* gmsh = std::getenv("QUADMESH_TEST_GMSH");
  if (gmsh == nullptr || *gmsh == '\0') {
    MESSAGE("QUADMESH_TEST_GMSH is not set: no Gmsh 4.9 or later to run (e.g. ../shared/tools/gmsh-4.15.2/bin/gmsh)");
    return;
  }
  const std::string out = test::scratch_dir("compare_real_quasi") + "/report";
  CHECK(compare("", "'" + test::example("plate-two-holes.geo") + "' --size 3% --timeout 120 --gmsh '" + gmsh + "'",
                out) == 0);
  const auto j = check_report(out, true);
  const auto& quasi = j["methods"][5];
  CHECK(quasi["status"] == "ok");
  CHECK(quasi["quality"]["triangles"] == 0);
  CHECK(quasi["quality"]["quads"].get<int>() > 100);
  CHECK(quasi["quality"]["boundary_loops"] == 3);
  // its mean edge against the target size: the doubled size undoes its splitting (0.97 on this plate)
  CHECK(quasi["quality"]["edge_length_mean"].get<double>() / j["size"].get<double>() ==
        doctest::Approx(1.0).epsilon(0.25));
}
