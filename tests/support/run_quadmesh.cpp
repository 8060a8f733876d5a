#include "tests/support/run_quadmesh.h"

#include "io/child_process.h"
#include "tests/support/test_meshes.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace qm::test {

std::vector<std::string> Run::error_lines() const {
  std::vector<std::string> lines;
  std::istringstream in(err);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line[0] != '[') lines.push_back(line);
  return lines;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string quoted(const std::string& path) { return "'" + path + "'"; }

std::string address_space_bound(std::size_t kib) {
  return io::address_space_limits_work() ? "ulimit -v " + std::to_string(kib) + "; " : "";
}

int sanitizer_slowdown() { return io::address_space_limits_work() ? 1 : 10; }

Run shell_with_quadmesh(const std::string& command) {
  static int counter = 0;
  // per process: test programs (and other checkouts' runs) share the temp dir
  const std::string dir = scratch_dir("cli_io_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  std::string line = command;
  const std::string word = "QUADMESH";
  const std::string program = quoted(QM_QUADMESH_BIN);
  for (auto at = line.find(word); at != std::string::npos; at = line.find(word, at + program.size()))
    line.replace(at, word.size(), program);
  const std::string full = "( " + line + " ) >'" + dir + "/out' 2>'" + dir + "/err' </dev/null";
  const int raw = std::system(full.c_str());
  Run run;
  run.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  run.out = slurp(dir + "/out");
  run.err = slurp(dir + "/err");
  std::error_code ignored;
  std::filesystem::remove_all(dir, ignored);
  return run;
}

Run quadmesh(const std::string& args) { return shell_with_quadmesh("QUADMESH " + args); }

}  // namespace qm::test
