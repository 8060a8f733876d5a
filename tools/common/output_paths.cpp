#include "tools/common/output_paths.h"

#include "io/write_mesh.h"
#include "libquadmesh/core/error.h"
#include "tools/common/usage_error.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>

namespace qm::tools {

namespace {

namespace fs = std::filesystem;

std::string named(const NamedPath& p) { return p.option + " " + p.path; }

/// The folder a path's file goes into ("." for a bare name).
fs::path folder_of(const std::string& path) {
  const fs::path folder = fs::path(path).parent_path();
  return folder.empty() ? fs::path(".") : folder;
}

/// Whether this process can create a file in `folder`: tried, not guessed from
/// the permission bits (root, read-only file systems, /proc).
bool can_create_in(const fs::path& folder, std::string& why) {
  std::string probe = (folder / ".quadmesh-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) {
    why = std::strerror(errno);
    return false;
  }
  ::close(fd);
  ::unlink(probe.c_str());
  return true;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec;
  if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec);
  const fs::path ca = fs::weakly_canonical(fs::absolute(a), ec);
  if (ec) return false;
  const fs::path cb = fs::weakly_canonical(fs::absolute(b), ec);
  return !ec && ca == cb;
}

namespace {

/// An output file's path must not be a folder or another kind of file.
void require_file_path(const NamedPath& output) {
  std::error_code ec;
  if (fs::is_directory(output.path, ec))
    throw UsageError(fmt::format("{}: is a folder, not a file", named(output)));
  if (fs::exists(output.path, ec) && !fs::is_regular_file(output.path, ec))
    throw UsageError(fmt::format("{}: exists and is not a regular file", named(output)));
}

}  // namespace

void check_output_file(const NamedPath& output, io::Format only) {
  if (output.path.empty()) return;
  require_file_path(output);
  try {
    if (output.option != "--report") io::check_output_path(output.path);  // format and folder
  } catch (const Error& e) {
    throw UsageError(e.what());
  }
  if (only != io::Format::unknown && io::format_of(output.path) != only)
    throw UsageError(fmt::format("{}: this output must be a .msh file", output.path));
  check_output_location(output);
}

void check_output_location(const NamedPath& output) {
  if (output.path.empty()) return;
  require_file_path(output);
  std::error_code ec;
  const fs::path folder = folder_of(output.path);
  if (!fs::is_directory(folder, ec))
    throw UsageError(fmt::format("{}: the folder {} does not exist", output.path, folder.string()));
  std::string why;
  if (!can_create_in(folder, why))
    throw UsageError(fmt::format("{}: cannot write in the folder {}: {}", named(output), folder.string(), why));
}

void check_output_folder(const NamedPath& folder) {
  if (folder.path.empty()) return;
  std::error_code ec;
  if (fs::exists(folder.path, ec) && !fs::is_directory(folder.path, ec))
    throw UsageError(fmt::format("{}: exists and is not a folder", named(folder)));
  const fs::path where = fs::is_directory(folder.path, ec) ? fs::path(folder.path) : folder_of(folder.path);
  if (!fs::is_directory(where, ec))
    throw UsageError(fmt::format("{}: the folder {} does not exist", named(folder), where.string()));
  std::string why;
  if (!can_create_in(where, why))
    throw UsageError(fmt::format("{}: cannot write in the folder {}: {}", named(folder), where.string(), why));
}

void check_distinct(const std::vector<NamedPath>& paths) {
  for (std::size_t i = 0; i < paths.size(); ++i)
    for (std::size_t j = i + 1; j < paths.size(); ++j) {
      if (paths[i].path.empty() || paths[j].path.empty() || !same_file(paths[i].path, paths[j].path)) continue;
      throw UsageError(fmt::format("{}: the same file as {}; give {} another path", named(paths[j]),
                                   named(paths[i]), paths[j].option));
    }
}

}  // namespace qm::tools
