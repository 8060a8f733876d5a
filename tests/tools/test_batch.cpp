// quadmesh batch: the list's rows, and the tool as a user runs it: every row is in
// the summary, a crashing row is a row, a killed batch resumes with the rows it
// had not finished, --row and --collect give the summary of the whole run.
#include "tests/support/run_quadmesh.h"
#include "tests/support/test_meshes.h"
#include "tools/batch/batch_list.h"
#include "tools/batch/batch_summary.h"
#include "tools/common/usage_error.h"

#include <doctest/doctest.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <thread>

using namespace qm;
namespace fs = std::filesystem;

namespace {

/// A list of the small examples at a coarse size: fast rows.
std::string small_list(const std::string& dir) {
  return test::write_text(dir, "list.csv",
                          fmt::format("file,size,options\n"
                                      "# small examples, coarse\n"
                                      "{},10%,\n"
                                      "{},8%,--no-smoothing\n"
                                      "{},10%,--max-deviation off\n"
                                      "{},6%,\n",
                                      test::example("annulus.geo"), test::example("plate-two-holes.geo"),
                                      test::example("plate-v-hole.geo"), test::example("annulus.geo")));
}

nlohmann::json summary(const std::string& out) { return nlohmann::json::parse(test::slurp(out + "/summary.json")); }

/// The summary's rows without the seconds: what two runs of one list share.
nlohmann::json figures(nlohmann::json rows) {
  for (auto& row : rows) row.erase("seconds");
  return rows;
}

std::size_t finished_rows(const std::string& out) {
  std::size_t n = 0;
  for (const auto& entry : fs::directory_iterator(out + "/parts"))
    if (entry.path().string().size() > 9 &&
        entry.path().string().compare(entry.path().string().size() - 9, 9, ".row.json") == 0)
      ++n;
  return n;
}

}  // namespace

TEST_CASE("parse_batch_list: header, comments, quotes, relative files, sizes, unique names") {
  const std::string text =
      "file,size,options\n"
      "\n"
      "# a comment\n"
      "a/plate.geo,5%,--no-smoothing --form 2\n"
      "b/plate.geo\n"
      "\"c, d.obj\",2.5,\n";
  const std::vector<tools::BatchRow> rows = tools::parse_batch_list(text, "/lists/parts.csv", "3%");
  REQUIRE(rows.size() == 3);
  CHECK(rows[0].index == 1);
  CHECK(rows[0].file == "/lists/a/plate.geo");
  CHECK(rows[0].size == "5%");
  CHECK(rows[0].options == std::vector<std::string>{"--no-smoothing", "--form", "2"});
  CHECK(rows[0].name == "plate-1");
  CHECK(rows[1].name == "plate-2");
  CHECK(rows[1].size == "3%");
  CHECK(rows[2].file == "/lists/c, d.obj");
  CHECK(rows[2].name == "c__d");
  CHECK(rows[2].size == "2.5");
  CHECK(tools::rows_from_json(nlohmann::ordered_json(tools::rows_json(rows)), "x").size() == 3);

  CHECK_THROWS_WITH_AS(tools::parse_batch_list("a.obj,fast\n", "l.csv", ""),
                       "l.csv:1: size 'fast' is not a positive length or a percentage such as 5%",
                       tools::UsageError);
  CHECK_THROWS_WITH_AS(tools::parse_batch_list("a.obj,1%,-o x.msh\n", "l.csv", ""),
                       "l.csv:1: option -o: batch names each row's outputs itself", tools::UsageError);
  CHECK_THROWS_AS(tools::parse_batch_list("a.obj,1%,,x\n", "l.csv", ""), tools::UsageError);
  CHECK_THROWS_AS(tools::parse_batch_list("\"a.obj,1%\n", "l.csv", ""), tools::UsageError);
}

TEST_CASE("batch_totals count every status") {
  std::vector<tools::RowResult> results(4);
  results[0].status = "ok";
  results[0].quads = 10;
  results[1].status = "crashed";
  results[2].status = "unsupported";
  const tools::BatchTotals t = tools::batch_totals(results);
  CHECK(t.rows == 4);
  CHECK(t.ok == 1);
  CHECK(t.crashed == 1);
  CHECK(t.unsupported == 1);
  CHECK(t.missing == 1);
  CHECK(t.quads == 10);
}

TEST_CASE("a row that crashes is a row; the batch writes its summary and exits 0") {
  const std::string dir = test::scratch_dir("batch_crash");
  const std::string list = small_list(dir), out = dir + "/out";
  // the hook's variable is set for the batch alone (its name holds the word the helper replaces)
  setenv("QUADMESH_BATCH_CRASH", "plate-two-holes", 1);
  const test::Run run =
      test::quadmesh("batch " + test::quoted(list) + " --out " + test::quoted(out) + " --jobs 2 -q");
  unsetenv("QUADMESH_BATCH_CRASH");
  REQUIRE_MESSAGE(run.status == 0, run.err);
  const nlohmann::json j = summary(out);
  REQUIRE(j["rows"].size() == 4);
  CHECK(j["totals"]["rows"] == 4);
  CHECK(j["totals"]["ok"] == 3);
  CHECK(j["totals"]["crashed"] == 1);
  CHECK(j["rows"][1]["name"] == "plate-two-holes");
  CHECK(j["rows"][1]["status"] == "crashed");
  CHECK(j["rows"][1]["detail"].get<std::string>().find("signal 11") != std::string::npos);
  CHECK(j["rows"][1]["quads"] == 0);
  std::size_t quads = 0;
  for (const auto& row : j["rows"]) {
    if (row["status"] != "ok") continue;
    CHECK(row["quads"].get<std::size_t>() > 0);
    CHECK(row["min_scaled_jacobian"].get<double>() > 0);
    CHECK(fs::exists(out + "/" + row["mesh"].get<std::string>()));
    quads += row["quads"].get<std::size_t>();
  }
  CHECK(j["totals"]["quads"] == quads);
  CHECK(test::slurp(out + "/summary.md").find("| 2 | plate-two-holes | crashed |") != std::string::npos);
}

TEST_CASE("a killed batch, run again, redoes only the rows it had not finished") {
  const std::string dir = test::scratch_dir("batch_resume");
  const std::string list = small_list(dir), out = dir + "/out";
  // the batch in the background, one row at a time; killed once the first row is done
  const std::string pid_file = dir + "/pid";
  const test::Run started = test::shell_with_quadmesh("QUADMESH batch " + test::quoted(list) + " --out " +
                                                      test::quoted(out) + " --jobs 1 -q >/dev/null 2>&1 & echo $! >" +
                                                      test::quoted(pid_file));
  REQUIRE(started.status == 0);
  const pid_t pid = static_cast<pid_t>(std::stol(test::slurp(pid_file)));
  for (int k = 0; k < 6000 && !(fs::exists(out + "/parts") && finished_rows(out) >= 1); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  REQUIRE(kill(pid, SIGKILL) == 0);
  for (int k = 0; k < 500 && kill(pid, 0) == 0; ++k) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  const std::size_t done = finished_rows(out);
  REQUIRE(done >= 1);
  REQUIRE_MESSAGE(done < 4, "the batch finished before it was killed");
  CHECK(!fs::exists(out + "/summary.json"));

  const test::Run rerun = test::quadmesh("batch " + test::quoted(list) + " --out " + test::quoted(out) + " --jobs 2 -q");
  REQUIRE_MESSAGE(rerun.status == 0, rerun.err);
  CHECK(rerun.out.find(fmt::format("4 rows: {} run now, {} done earlier", 4 - done, done)) != std::string::npos);
  const nlohmann::json j = summary(out);
  REQUIRE(j["rows"].size() == 4);
  CHECK(j["totals"]["ok"] == 4);

  // a third run has nothing left to do, and its summary is the same
  const test::Run again = test::quadmesh("batch " + test::quoted(list) + " --out " + test::quoted(out) + " -q");
  CHECK(again.out.find("4 rows: 0 run now, 4 done earlier") != std::string::npos);
  CHECK(summary(out) == j);
}

TEST_CASE("--row K then --collect: the same summary as one batch, row for row") {
  const std::string dir = test::scratch_dir("batch_rows");
  const std::string list = small_list(dir), whole = dir + "/whole", rows = dir + "/rows";
  REQUIRE(test::quadmesh("batch " + test::quoted(list) + " --out " + test::quoted(whole) + " --jobs 2 -q").status == 0);
  for (int k : {3, 1, 4, 2})
    REQUIRE(test::quadmesh(fmt::format("batch {} --out {} --row {} -q", test::quoted(list), test::quoted(rows), k))
                .status == 0);
  CHECK(!fs::exists(rows + "/summary.json"));
  const test::Run collected = test::quadmesh("batch --collect " + test::quoted(rows) + " -q");
  REQUIRE_MESSAGE(collected.status == 0, collected.err);
  CHECK(figures(summary(rows)["rows"]) == figures(summary(whole)["rows"]));

  // a row never run is `missing` in the collected summary
  const std::string partial = dir + "/partial";
  REQUIRE(test::quadmesh("batch " + test::quoted(list) + " --out " + test::quoted(partial) + " --row 2 -q").status == 0);
  REQUIRE(test::quadmesh("batch --collect " + test::quoted(partial) + " -q").status == 0);
  CHECK(summary(partial)["totals"]["missing"] == 3);
  CHECK(summary(partial)["totals"]["ok"] == 1);

  CHECK(test::quadmesh(fmt::format("batch {} --out {} --row 5 -q", test::quoted(list), test::quoted(rows))).status ==
        2);
  CHECK(test::quadmesh("batch --collect " + test::quoted(dir) + " -q").status == 2);
}

TEST_CASE("batch over the shared meshes and the examples, two at a time: every row present" *
          doctest::test_suite("slow")) {
  const std::string dir = test::scratch_dir("batch_shared");
  std::string text = "file,size,options\n";
  std::size_t rows = 0;
  for (const std::string& folder : {fs::path(test::shared_mesh("MANIFEST.md")).parent_path().string(),
                                    fs::path(test::example("annulus.geo")).parent_path().string()}) {
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.is_regular_file() && std::set<std::string>{".obj", ".off", ".stl", ".geo"}.count(entry.path().extension().string()))
        files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    for (const std::string& file : files) {
      text += fmt::format("\"{}\",5%,\n", file);
      ++rows;
    }
  }
  const std::string list = test::write_text(dir, "list.csv", text), out = dir + "/out";
  const test::Run run = test::quadmesh("batch " + test::quoted(list) + " --out " + test::quoted(out) + " --jobs 2 -q");
  REQUIRE_MESSAGE(run.status == 0, run.err);
  const nlohmann::json j = summary(out);
  REQUIRE(j["rows"].size() == rows);
  CHECK(j["totals"]["rows"] == rows);
  CHECK(j["totals"]["missing"] == 0);
  std::size_t ok = 0;
  for (const auto& row : j["rows"]) {
    const std::string name = row["name"];
    CAPTURE(name);
    if (name == "kitten" || name == "fertility" || name == "hinge" || name == "assembly-five-parts")
      CHECK(row["status"] == "unsupported");  // closed surfaces; several components without --each-component
    else if (name == "ogre-body-pinched")
      CHECK(row["status"] == "failed");  // bad input: exit 3
    else
      CHECK(row["status"] != "missing");
    ok += row["status"] == "ok" ? 1 : 0;
  }
  CHECK(j["totals"]["ok"] == ok);
}
