// The body of a PLY file checked against its header, without storing it.
//
// A PLY count is a promise about the bytes that follow; CGAL's reader believes
// it and allocates (a face announcing 2^31 - 1 indices costs 8 GB before the read
// fails). This walk checks every count against what the file really holds, every
// face index against the vertex count and every coordinate for NaN/Inf, so that
// CGAL only ever sees a file whose counts are true.
#pragma once

#include "io/ply_header.h"

#include <cstdint>
#include <istream>
#include <optional>
#include <string>

namespace qm::io {

/// Checks the element counts against `data_bytes` (the bytes after the header:
/// binary, each value's size and a face at least three indices; ASCII, a digit
/// and a separator per value), then walks the data in `in` and returns "FILE: [line N: ]face F: what is wrong" for the first problem: a list
/// length that runs past the end, a face with fewer than 3 vertices or an index
/// out of range, a coordinate that is not finite, a file that ends early, or data
/// left over after the last element (a count that is too small).
std::optional<std::string> check_ply_data(std::istream& in, const std::string& path,
                                          const PlyHeader& header, std::uint64_t data_bytes);

}  // namespace qm::io
