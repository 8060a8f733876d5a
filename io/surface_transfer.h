// How a Gmsh child process hands its result back to the reader (io/read_surface.cpp):
// a SurfaceFile, or the qm::Error it ended with, as bytes in a temporary file.
//
// The format is private to one build of quadmesh (both ends are the same program):
//   "QMSF1" kind
//   kind 'S': f64 cad_mesh_size, u64 polygons_split,
//             u64 n, n x (f64 x, f64 y, f64 z), u64 n, n x i64 point label,
//             u64 n, n x (i32 a, i32 b, i32 c), u64 n, n x i64 triangle label,
//             u64 n, n x (i32 a, i32 b, i32 curve),
//             u64 n, n x (i32 tag, u64 len, name bytes, u64 m, m x i32 curve),
//             u64 n, n x (i32 tag, u64 len, name bytes, u64 m, m x i64 element)
//   kind 'E': i32 error code, u64 len, message bytes
//   "END"
// in the machine's byte order. Anything else (a child killed while writing) does
// not decode.
#pragma once

#include "io/read_surface.h"
#include "libquadmesh/core/error.h"

#include <optional>
#include <string>
#include <variant>

namespace qm::io {

std::string encode_surface(const SurfaceFile& file);
std::string encode_error(const Error& error);

/// The SurfaceFile or the Error that `bytes` holds (format given by the caller:
/// it is not stored); nullopt if they are not a complete message.
std::optional<std::variant<SurfaceFile, Error>> decode_result(const std::string& bytes,
                                                                Format format);

}  // namespace qm::io
