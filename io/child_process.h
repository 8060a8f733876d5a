// Running a program, or a function, in a child process with a time limit and an
// address-space limit: how `quadmesh compare` keeps a crashing or hanging mesher
// from taking the comparison down with it, and how readers run Gmsh on CAD input
// that may loop, exhaust memory or crash (io/gmsh_child.h).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace qm::io {

/// How a child process ended.
enum class ChildStatus {
  ok,       ///< exited with status 0
  failed,   ///< exited with a non-zero status (or could not be started)
  crashed,  ///< killed by a signal it did not ask for (SIGSEGV, SIGABRT, ...)
  timeout,  ///< still running at the deadline: killed with SIGKILL
};

/// False in a build with AddressSanitizer (scripts/sanitize, scripts/fuzz): it
/// reserves terabytes of address space as it starts, so an address-space limit
/// would stop every child at once. There the children run with the time limit
/// alone, and the tests that bound memory with `ulimit -v` leave the bound out.
constexpr bool address_space_limits_work() {
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

/// "ok", "failed", "crashed", "timeout" (the words of report.json).
const char* status_name(ChildStatus status);

struct ChildOptions {
  double timeout_seconds = 120.0;  ///< wall-clock limit; <= 0: none
  std::string log_path;            ///< stdout and stderr go here; empty: /dev/null
  std::string working_dir;         ///< the child's working folder; empty: ours
  /// Address-space limit of the child (RLIMIT_AS), in bytes; 0: none. Never
  /// raised above the limit this process already has. Not applied in a build
  /// with AddressSanitizer (address_space_limits_work()).
  std::uint64_t memory_limit_bytes = 0;
  /// Test hook: the child raises SIGSEGV instead of running the program, as a
  /// crashing mesher would.
  bool crash_on_purpose = false;
  /// run_child: the child gets SIGKILL when the thread that started it ends (this
  /// process killed, as a batch that is stopped and later resumed), so no orphan
  /// keeps writing into the outputs. run_in_child always does this.
  bool die_with_parent = false;
};

struct ChildResult {
  ChildStatus status = ChildStatus::failed;
  double seconds = 0.0;  ///< wall-clock time from the start to the end (or the kill)
  int exit_code = -1;    ///< the exit status when the child exited, else -1
  int signal = 0;        ///< the signal that ended it (SIGKILL after a time-out), else 0
  /// One line for a report: "exit status 4", "signal 11 (Segmentation fault)",
  /// "no result after 120 s", or "" when ok.
  std::string detail;
};

/// Runs `argv` (argv[0] looked up in PATH when it has no '/') with stdin from
/// /dev/null, in its own process group, without core dumps. Waits until it ends or
/// the deadline passes; at the deadline the whole process group gets SIGKILL.
/// A program that cannot be started ends as `failed` with exit status 127.
/// Precondition: argv is not empty.
ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options);

/// Runs `body` in a forked child (same limits, process group and /dev/null stdio as
/// run_child, and the child dies with this process): the child ends with
/// _exit(body()), or status 1 if body throws. Safe only while this process runs a
/// single thread (fork copies just the calling one), which is how quadmesh reads
/// its input. The exit status, signal or time-out comes back as for run_child.
ChildResult run_in_child(const std::function<int()>& body, const ChildOptions& options);

/// This program's own executable (/proc/self/exe), to run it as a child.
std::string own_executable();

}  // namespace qm::io
