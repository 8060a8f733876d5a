// quadmesh compare: the child-process runner, and the tool as a user runs it:
// every method is a row, and a method that crashes is a row, not a failure.
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"
#include "tools/compare/child_process.h"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>

#include <csignal>
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

/// report.json has every method, in order, each row complete for its status.
nlohmann::json check_report(const std::string& dir) {
  namespace fs = std::filesystem;
  REQUIRE(fs::exists(dir + "/report.json"));
  const auto j = nlohmann::json::parse(slurp(dir + "/report.json"));
  CHECK(j["input"].is_string());
  CHECK(j["size"].get<double>() > 0);
  REQUIRE(j["methods"].size() == kMethods.size());
  for (std::size_t i = 0; i < kMethods.size(); ++i) {
    const auto& m = j["methods"][i];
    CAPTURE(m.dump());
    CHECK(m["name"] == kMethods[i]);
    const std::string status = m["status"];
    CHECK((status == "ok" || status == "crashed" || status == "timeout" || status == "failed"));
    CHECK(m["seconds"].get<double>() >= 0);
    if (status == "ok") {
      REQUIRE(m["quality"].is_object());
      for (const std::string& key : kQualityKeys)
        CHECK(m["quality"].contains(key));
      CHECK(m["quality"]["quads"].get<int>() > 0);
      CHECK(fs::exists(dir + "/" + m["mesh"].get<std::string>()));
    } else {
      CHECK(m["quality"].is_null());
      CHECK(!m["detail"].get<std::string>().empty());
    }
  }
  const std::string md = slurp(dir + "/report.md");
  for (const std::string& name : kMethods)
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
  CHECK(j["methods"][0]["status"] == "ok");
  for (int row = 1; row < 5; ++row) {
    CAPTURE(row);
    CHECK(j["methods"][row]["status"] == "timeout");
    // killed at the time limit, well before the fake's 60 s
    CHECK(j["methods"][row]["seconds"].get<double>() >= 2.0 * test::sanitizer_slowdown());
    CHECK(j["methods"][row]["seconds"].get<double>() < 10.0 * test::sanitizer_slowdown());
  }
}
