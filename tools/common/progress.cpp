#include "tools/common/progress.h"

#include <fmt/format.h>

#include <cstdio>

namespace qm::tools {

double Progress::elapsed() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void Progress::stage(const std::string& what) const {
  if (quiet_) return;
  fmt::print(stderr, "[{:7.2f} s] {}\n", elapsed(), what);
  std::fflush(stderr);
}

}  // namespace qm::tools
