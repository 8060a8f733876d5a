// The files a command reads and writes, checked before any work: a run that
// cannot write its outputs, or would write one over its input or over another
// output, fails at once with a usage error (exit 2), never after the computation.
#pragma once

#include "io/file_format.h"

#include <string>
#include <vector>

namespace qm::tools {

/// A file named on the command line, with what named it ("-o", "--report", "the input").
struct NamedPath {
  std::string option;
  std::string path;  ///< empty: not given (skipped)
};

/// Throws UsageError unless `output.path` can be written: a writable format (and
/// `only`, unless unknown), not an existing folder or other non-regular file, in
/// an existing folder where this process can create files.
void check_output_file(const NamedPath& output, io::Format only = io::Format::unknown);

/// Throws UsageError unless a file of any format can be written at `output.path`:
/// not an existing folder or other non-regular file, in an existing folder where
/// this process can create files (check_output_file without the format).
void check_output_location(const NamedPath& output);

/// Throws UsageError unless `folder` is an existing folder where this process
/// can create files, or does not exist and its parent is one (it is created later).
void check_output_folder(const NamedPath& folder);

/// Whether `a` and `b` name the same file: the same canonical path (through
/// symlinks, ".." and "./"; what does not exist yet compared as written), or
/// the same file through a hard link.
bool same_file(const std::string& a, const std::string& b);

/// Throws UsageError when two of `paths` name the same file: the same canonical
/// path (through symlinks, ".." and "./"), or the same file through a hard link.
void check_distinct(const std::vector<NamedPath>& paths);

}  // namespace qm::tools
