// Finding the line at fault in a text mesh file that a library refused.
//
// CGAL's readers answer only yes or no; when they say no, these scanners look for
// the first offending line so that the user's error names it. They are not
// readers: they check the structure (counts, numbers, index ranges) and nothing
// else.
#pragma once

#include "io/file_format.h"

#include <optional>
#include <string>

namespace qm::io {

/// `text` made safe for a one-line message: control and non-ASCII bytes become
/// '?', and anything past `max_length` characters becomes "...".
std::string printable(const std::string& text, std::size_t max_length = 60);

/// "file.obj:12: ..." for the first malformed line of an OBJ file, if any.
std::optional<std::string> diagnose_obj(const std::string& path);
/// The same for OFF (header, counts, truncation, index ranges).
std::optional<std::string> diagnose_off(const std::string& path);
/// PLY: the magic word and the end of the header.
std::optional<std::string> diagnose_ply(const std::string& path);
/// Binary size against the announced triangle count, or the ASCII structure.
std::optional<std::string> diagnose_stl(const std::string& path);
/// Gmsh MSH sections: a missing $End... marker means a truncated file.
std::optional<std::string> diagnose_msh(const std::string& path);

/// The checks every reader makes before parsing: the file exists, is a regular,
/// non-empty, readable file with a readable extension, and (text formats) its
/// first problem if any. Returns its format; throws qm::Error(bad_input) with a
/// one-line message that starts with the path.
Format check_input_file(const std::string& path);

}  // namespace qm::io
