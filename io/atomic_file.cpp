#include "io/atomic_file.h"

#include "libquadmesh/core/error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>

namespace qm::io {

void write_atomically(const std::string& path,
                      const std::function<void(const std::string&)>& write) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  fs::path temporary = target.parent_path() /
                       fmt::format(".{}.tmp-{}{}", target.stem().string(), ::getpid(),
                                   target.extension().string());
  try {
    write(temporary.string());
    std::error_code ec;
    if (!fs::exists(temporary, ec) || fs::file_size(temporary, ec) == 0)
      throw Error(ErrorCode::bad_input, fmt::format("{}: the writer produced no data", path));
    fs::rename(temporary, target, ec);
    if (ec) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write: {}", path, ec.message()));
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

}  // namespace qm::io
