// Is a file text at all? Checked before any line-based scanner or reader runs,
// because binary garbage has no line ends: a reader that reads "a line" of it
// reads the whole file into memory, and a parser fed NUL bytes finds nothing to
// stop at.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace qm::io {

/// Longer lines than this are not what a mesh file holds (a polygon with 10 000
/// corners written "f 1234567/1234567/1234567 ..." is about 250 KB).
constexpr std::size_t max_text_line = std::size_t{1} << 20;

/// True for a byte no text file holds: NUL and the C0 controls other than tab,
/// line feed, vertical tab, form feed, carriage return and ^Z (DOS end of file).
/// Bytes >= 0x80 are allowed: UTF-8 names and comments.
bool is_binary_byte(unsigned char byte);

/// "FILE: line N: not text (byte 0x00)" for the first line of `path` that holds a
/// binary byte, or "FILE: line N: not text (a line over 1 MiB)", if any. Reads the
/// file once in small blocks: bounded memory whatever the file holds.
std::optional<std::string> check_text(const std::string& path);

}  // namespace qm::io
