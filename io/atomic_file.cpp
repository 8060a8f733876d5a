#include "io/atomic_file.h"

#include "libquadmesh/core/error.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <filesystem>

namespace qm::io {

namespace {

namespace fs = std::filesystem;

/// Flushes the file's data to the disk, so that the rename never publishes an
/// empty file after a crash; false if the file cannot be opened or synced.
bool sync_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

/// `text` with every `from` replaced by `to`.
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); !from.empty() && at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

}  // namespace

AtomicFiles::~AtomicFiles() {
  if (!committed_) discard();
}

void AtomicFiles::discard() noexcept {
  std::error_code ignored;
  for (const Pending& p : pending_) fs::remove(p.temporary, ignored);
  for (const std::string& path : renamed_) fs::remove(path, ignored);
  pending_.clear();
  renamed_.clear();
}

void AtomicFiles::add(const std::string& path, const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  const fs::path temporary =
      target.parent_path() / fmt::format(".{}.tmp-{}-{}{}", target.stem().string(), ::getpid(), pending_.size(),
                                         target.extension().string());
  pending_.push_back({path, temporary.string()});
  try {
    write(temporary.string());
    std::error_code ec;
    if (!fs::exists(temporary, ec) || fs::file_size(temporary, ec) == 0)
      throw Error(ErrorCode::bad_input, fmt::format("{}: the writer produced no data", path));
    if (!sync_file(temporary))
      throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write it to the disk", path));
  } catch (const Error& e) {  // the user's message names the destination, not the temporary
    discard();
    throw Error(e.code(), replaced(e.what(), temporary.string(), path));
  } catch (...) {
    discard();
    throw;
  }
}

void AtomicFiles::commit() {
  for (const Pending& p : pending_) {
    std::error_code ec;
    fs::rename(p.temporary, p.path, ec);
    if (ec) {
      const std::string message = fmt::format("{}: cannot write: {}", p.path, ec.message());
      discard();
      throw Error(ErrorCode::bad_input, message);
    }
    renamed_.push_back(p.path);
  }
  committed_ = true;
  pending_.clear();
  renamed_.clear();
}

void write_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  AtomicFiles file;
  file.add(path, write);
  file.commit();
}

}  // namespace qm::io
