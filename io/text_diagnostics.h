// Finding the place at fault in a mesh file before a library reads it.
//
// CGAL's and Gmsh's readers answer only yes or no, trust the counts they read
// (and allocate for them) and may drop what they cannot use without a word. So
// these scanners run first, in bounded memory, and name the first offending line
// (or element, for binary data). They are not readers: they check the structure
// (counts, numbers, index ranges) and nothing else.
#pragma once

#include "io/file_format.h"

#include <optional>
#include <string>

namespace qm::io {

/// `text` made safe for a one-line message: control and non-ASCII bytes become
/// '?', and anything past `max_length` characters becomes "...".
std::string printable(const std::string& text, std::size_t max_length = 60);

/// "file.obj: line 12: ..." for the first malformed line of an OBJ file, if any.
std::optional<std::string> diagnose_obj(const std::string& path);
/// The same for OFF (header, counts, truncation, index ranges).
std::optional<std::string> diagnose_off(const std::string& path);
/// PLY: the header line by line (ply_header.h), then every count, list, index
/// and coordinate of the data against it (ply_data.h).
std::optional<std::string> diagnose_ply(const std::string& path);
/// Binary: the size against the announced triangle count and every corner
/// finite; ASCII: text, and the structure.
std::optional<std::string> diagnose_stl(const std::string& path);
/// Gmsh MSH sections: a missing $End... marker means a truncated file.
std::optional<std::string> diagnose_msh(const std::string& path);

/// The checks every reader makes before parsing: the file exists, is a regular
/// file (not a directory, FIFO or device), non-empty and readable, with a readable
/// extension, and (OBJ OFF PLY STL MSH) its first problem if any: binary bytes in
/// a text format, a malformed line, or a count the data contradicts. Returns its format; throws qm::Error(bad_input) with a
/// one-line message that starts with the path.
Format check_input_file(const std::string& path);

}  // namespace qm::io
