// Running the quadmesh program as a user does (command-line tests): its exit
// status, stdout and stderr.
#pragma once

#include <string>
#include <vector>

namespace qm::test {

struct Run {
  int status = -1;  ///< the exit status; -1 when killed by a signal
  std::string out, err;
  /// stderr without the progress lines ("[   0.01 s] ...")
  std::vector<std::string> error_lines() const;
};

/// The whole text of a file ("" if it cannot be read).
std::string slurp(const std::string& path);
/// `path` in single quotes for a shell command line.
std::string quoted(const std::string& path);

/// Runs `QUADMESH_BIN args` through the shell (args are shell words), stdin from /dev/null.
Run quadmesh(const std::string& args);
/// Runs a shell command line in which the word QUADMESH stands for the program
/// (quoted): for limits (ulimit, timeout) around it.
Run shell_with_quadmesh(const std::string& command);
/// "ulimit -v KIB; ": a shell prefix that bounds the address space of what
/// follows; empty in a build with AddressSanitizer, which needs terabytes of it
/// (io::address_space_limits_work).
std::string address_space_bound(std::size_t kib);
/// How many times slower the program runs in this build: 10 with
/// AddressSanitizer, else 1. Time limits the program is given (--timeout) scale by it.
int sanitizer_slowdown();

}  // namespace qm::test
