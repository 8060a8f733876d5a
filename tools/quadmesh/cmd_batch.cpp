// quadmesh batch LIST --out DIR [--jobs N] [--size H|P%] [--timeout S] [--row K]
// quadmesh batch LIST --out DIR --prepare
// quadmesh batch --collect DIR
// Every row of LIST (a CSV of file,size,options, or a folder's input files)
// meshed by `quadmesh mesh` in a child process of its own, N at once, with a time
// limit; a crash or a time-out is a row, never the batch's failure. A row is done
// when DIR/parts/NAME.row.json is there (written last, atomically, after the mesh
// and its report): a rerun runs only the rows not done. --row K runs one row (a
// Slurm array task), --collect DIR writes the summary of what the rows left
// (README "quadmesh batch").
//
// Test hook: QUADMESH_BATCH_CRASH=NAME[,NAME...] makes those rows' child
// processes raise SIGSEGV instead of running (tools/common/crash_hook.h).
#include "io/atomic_file.h"
#include "io/child_process.h"
#include "io/file_format.h"
#include "tools/batch/batch_list.h"
#include "tools/batch/batch_row.h"
#include "tools/batch/batch_summary.h"
#include "tools/common/crash_hook.h"
#include "tools/common/exit_codes.h"
#include "tools/common/output_paths.h"
#include "tools/common/progress.h"
#include "tools/common/usage_error.h"
#include "tools/quadmesh/commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <thread>

namespace qm::tools {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

Json read_json(const fs::path& path) {
  std::ifstream in(path);
  if (!in) return Json();
  return Json::parse(in, nullptr, false);  // discarded (not an object) when malformed
}

/// Writes `text` to `path` so that it appears complete or not at all.
void write_text_atomically(const fs::path& path, const std::string& text) {
  io::write_atomically(path.string(), [&](const std::string& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the file", path.string()));
  });
}

std::string dump(const Json& j) { return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"; }

/// The rows of LIST: a CSV file, or the input files of a folder sorted by name.
std::vector<BatchRow> load_rows(const std::string& list, const std::string& default_size) {
  std::error_code ec;
  if (fs::is_directory(list, ec)) {
    std::vector<std::string> files;
    for (const auto& entry : fs::directory_iterator(list, ec))
      if (entry.is_regular_file() && io::is_readable(io::format_of(entry.path().string())))
        files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    if (files.empty())
      throw UsageError(fmt::format("{}: the folder holds no input file ({})", list, io::readable_extensions()));
    return rows_for_files(files, default_size);
  }
  if (!fs::is_regular_file(list, ec))
    throw UsageError(fmt::format("{}: no such list file or folder", list));
  std::vector<BatchRow> rows = parse_batch_list(read_text(list), list, default_size);
  if (rows.empty()) throw UsageError(fmt::format("{}: the list has no rows", list));
  return rows;
}

/// The folder and its parts/ subfolder, created if need be.
void make_folders(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir / "parts", ec);
  if (ec || !fs::is_directory(dir / "parts"))
    throw UsageError(fmt::format("{}: cannot create the output folder{}", dir.string(),
                                 ec ? ": " + ec.message() : std::string()));
}

/// The row's result if a run (this one or an earlier one) finished it: its
/// NAME.row.json is there for these arguments, and an ok row's mesh and report too.
std::optional<RowResult> finished_row(const fs::path& dir, const BatchRow& row) {
  const RowFiles files = row_files(row);
  std::optional<RowResult> done = row_result_from_json(read_json(dir / files.result), row);
  if (done && done->status == "ok" && !(fs::exists(dir / files.mesh) && fs::exists(dir / files.report)))
    return std::nullopt;
  return done;
}

/// The first error line of a row's log ("quadmesh: error: ..."), or "".
std::string first_error_line(const fs::path& log) {
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("quadmesh: error: ", 0) == 0) return line.substr(17, 300);
  return {};
}

/// Runs one row in its child process and records its result (NAME.row.json last).
RowResult run_row(const fs::path& dir, const BatchRow& row, double timeout) {
  const RowFiles files = row_files(row);
  std::error_code ignored;
  fs::remove(dir / files.result, ignored);
  io::ChildOptions child;
  child.timeout_seconds = timeout;
  child.log_path = (dir / files.log).string();
  child.working_dir = dir.string();
  child.crash_on_purpose = crash_requested("QUADMESH_BATCH_CRASH", row.name);
  child.die_with_parent = true;
  // this very program, even when its file is replaced while the batch runs (a
  // rebuild, an upgrade): every row of a run meshes with one binary
  std::vector<std::string> argv = {"/proc/self/exe"};
  for (const std::string& a : row_arguments(row)) argv.push_back(a);
  const io::ChildResult ended = io::run_child(argv, child);
  const Json report = ended.status == io::ChildStatus::ok ? read_json(dir / files.report) : Json();
  const RowResult result = row_result(ended, first_error_line(dir / files.log), report);
  write_text_atomically(dir / files.result, dump(row_result_json(row, result)));
  return result;
}

/// The rows' results, running those not finished, `jobs` at once.
std::vector<RowResult> run_rows(const fs::path& dir, const std::vector<BatchRow>& rows,
                                const std::vector<std::size_t>& which, int jobs, double timeout, bool quiet) {
  std::vector<RowResult> results(rows.size());
  std::vector<std::size_t> to_run;
  std::size_t earlier = 0;
  for (std::size_t i : which) {
    if (auto done = finished_row(dir, rows[i])) {
      results[i] = *done;
      ++earlier;
      if (!quiet) fmt::print(stderr, "[{}/{}] {}: done earlier ({})\n", rows[i].index, rows.size(), rows[i].name,
                             done->status);
    } else {
      to_run.push_back(i);
    }
  }
  std::atomic<std::size_t> next{0};
  std::mutex print;
  const auto worker = [&] {
    for (std::size_t k; (k = next++) < to_run.size();) {
      const BatchRow& row = rows[to_run[k]];
      results[to_run[k]] = run_row(dir, row, timeout);
      const RowResult& r = results[to_run[k]];
      if (quiet) continue;
      const std::lock_guard<std::mutex> lock(print);
      fmt::print(stderr, "[{}/{}] {}: {} after {:.2f} s{}\n", row.index, rows.size(), row.name, r.status, r.seconds,
                 r.detail.empty() ? "" : ": " + r.detail);
    }
  };
  std::vector<std::thread> threads;
  for (int t = 0; t < std::min<int>(jobs, static_cast<int>(to_run.size())); ++t) threads.emplace_back(worker);
  for (std::thread& t : threads) t.join();
  fmt::print("{} rows: {} run now, {} done earlier\n", which.size(), to_run.size(), earlier);
  return results;
}

/// summary.json and summary.md, together or not at all; the totals on stdout.
void write_summary(const fs::path& dir, const std::vector<BatchRow>& rows, const std::vector<RowResult>& results) {
  try {
    io::AtomicFiles files;
    const std::string json = dump(summary_json(rows, results));
    const std::string md = summary_markdown(rows, results);
    const auto add = [&](const fs::path& path, const std::string& text) {
      files.add(path.string(), [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary);
        out << text;
        out.close();
        if (!out) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the file", path.string()));
      });
    };
    add(dir / "summary.json", json);
    add(dir / "summary.md", md);
    files.commit();
  } catch (const Error& e) {
    throw UsageError(fmt::format("{}; no summary was written", e.what()));
  }
  const BatchTotals t = batch_totals(results);
  fmt::print("{}: {} rows: {} ok, {} failed, {} unsupported, {} crashed, {} timeout, {} missing; {} quads\n",
             (dir / "summary.json").string(), t.rows, t.ok, t.failed, t.unsupported, t.crashed, t.timeout, t.missing,
             t.quads);
}

/// --collect DIR: the summary from DIR/list.json and the rows' results.
int collect(const fs::path& dir) {
  const fs::path list = dir / "list.json";
  if (!fs::is_regular_file(list))
    throw UsageError(fmt::format("--collect {}: no list.json there (a batch or a --row run writes it)", dir.string()));
  const std::vector<BatchRow> rows = rows_from_json(read_json(list), list.string());
  std::vector<RowResult> results(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (auto done = finished_row(dir, rows[i])) results[i] = *done;
  write_summary(dir, rows, results);
  return exit_ok;
}

}  // namespace

int run_batch(const BatchOptions& options, const CommonOptions& common) {
  if (!options.collect_dir.empty()) {
    if (!options.list.empty() || !options.out_dir.empty() || options.row > 0 || options.prepare)
      throw UsageError("--collect DIR takes no LIST, --out or --row: it reads DIR/list.json");
    return collect(options.collect_dir);
  }
  if (options.list.empty() || options.out_dir.empty())
    throw UsageError("batch needs LIST and --out DIR (or --collect DIR)");
  if (options.row > 0 && options.jobs > 1) throw UsageError("--row K runs one row: --jobs does not apply");
  const fs::path dir = options.out_dir;
  check_output_folder({"--out", dir.string()});
  const std::vector<BatchRow> rows = load_rows(options.list, options.size);
  if (options.row > rows.size())
    throw UsageError(fmt::format("--row {}: {} has {} rows", options.row, options.list, rows.size()));
  make_folders(dir);
  // --row K: the array's tasks start together, on several hosts of a shared file
  // system; list.json comes from --prepare (scripts/cluster), or the first task
  const bool write_list = options.row == 0 || !fs::exists(dir / "list.json");
  try {
    if (write_list) write_text_atomically(dir / "list.json", dump(rows_json(rows)));
  } catch (const Error& e) {
    if (options.row == 0) throw UsageError(e.what());  // a task that lost the race uses the other's
  }
  if (options.prepare) {
    fmt::print("{}\n", rows.size());
    return exit_ok;
  }
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (options.row == 0 || i + 1 == options.row) which.push_back(i);
  const std::vector<RowResult> results = run_rows(dir, rows, which, options.jobs, options.timeout, common.quiet);
  if (options.row == 0) write_summary(dir, rows, results);
  return exit_ok;
}

}  // namespace qm::tools
