// The counts of an ASCII Gmsh MSH file (format 2.x and 4.1) against its data.
//
// Gmsh's reader takes a count at its word: with an $Elements count 10 too small
// it reads the first elements and drops the rest without a warning, and a count
// too large for the file makes it allocate for data that is not there. These
// checks count what really follows each count, without storing anything.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace qm::io {

/// "FILE: line N: $Elements declares 174 elements but 184 follow" and the like for
/// the first count in $Nodes or $Elements that the lines after it contradict, a
/// malformed count or block line, or a node coordinate that is not finite.
/// Expects a text file whose sections are closed (diagnose_msh checked them);
/// formats other than 2.x and 4.1 are left to Gmsh.
std::optional<std::string> check_msh_counts(const std::string& path);

/// The same for a binary MSH file (format 2.x and 4.1, 8-byte sizes, little
/// endian): every count against the bytes left, before Gmsh allocates for it
/// ("FILE: $Nodes block 1 declares 8589934592 nodes; the 3000 bytes left hold at
/// most 93"). Binary data has no lines: the message names the section and block.
std::optional<std::string> check_binary_msh_counts(const std::string& path);

/// Nodes of an element of Gmsh type `type` (1 line, 2 triangle, 3 quadrangle, ...
/// up to 19), 0 for a type not listed here.
std::size_t msh_element_nodes(long long type);

}  // namespace qm::io
