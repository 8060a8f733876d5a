#include "io/text_diagnostics.h"

#include "io/msh_counts.h"
#include "io/ply_data.h"
#include "io/ply_header.h"
#include "io/text_check.h"
#include "libquadmesh/core/error.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace qm::io {

namespace {

std::vector<std::string> split_tokens(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

enum class NumberKind { ok, not_a_number, not_finite };

NumberKind parse_real(const std::string& token, double& value) {
  const char* begin = token.c_str();
  char* end = nullptr;
  value = std::strtod(begin, &end);
  if (end == begin || *end != '\0') return NumberKind::not_a_number;
  return std::isfinite(value) ? NumberKind::ok : NumberKind::not_finite;
}

bool parse_integer(const std::string& token, long& value) {
  const char* begin = token.c_str();
  char* end = nullptr;
  value = std::strtol(begin, &end, 10);
  return end != begin && *end == '\0';
}

/// Checks that tokens[first .. first+3) are three finite numbers.
std::optional<std::string> check_coordinates(const std::string& where,
                                             const std::vector<std::string>& tokens,
                                             std::size_t first) {
  if (tokens.size() < first + 3)
    return fmt::format("{}: a vertex needs three coordinates, found {}", where,
                       tokens.size() - first);
  for (std::size_t i = first; i < first + 3; ++i) {
    double v = 0;
    switch (parse_real(tokens[i], v)) {
      case NumberKind::not_a_number:
        return fmt::format("{}: '{}' is not a number", where, printable(tokens[i]));
      case NumberKind::not_finite:
        return fmt::format("{}: coordinate '{}' is not a finite number", where, tokens[i]);
      case NumberKind::ok:
        break;
    }
  }
  return std::nullopt;
}

/// The next line that is neither blank nor a '#' comment; false at the end.
/// Blank means what split_tokens skips (a stream's white space, form feeds and
/// vertical tabs too), so a content line always has a first token.
bool next_content_line(std::istream& in, std::string& line, long& line_no) {
  while (std::getline(in, line)) {
    ++line_no;
    const auto first = line.find_first_not_of(" \t\r\f\v");
    if (first == std::string::npos || line[first] == '#') continue;
    return true;
  }
  return false;
}

}  // namespace

std::string printable(const std::string& text, std::size_t max_length) {
  std::string out;
  for (char c : text) {
    if (out.size() >= max_length) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    out += (u >= 32 && u < 127) ? c : '?';
  }
  return out;
}

std::optional<std::string> diagnose_obj(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  long line_no = 0, vertices = 0;
  struct FaceRef {
    long line, index;
  };
  std::vector<FaceRef> forward;  // positive indices are checked against the final count
  while (std::getline(in, line)) {
    ++line_no;
    const auto tokens = split_tokens(line);
    if (tokens.empty() || tokens[0][0] == '#') continue;
    const std::string where = fmt::format("{}: line {}", path, line_no);
    if (tokens[0] == "v") {
      if (auto problem = check_coordinates(where, tokens, 1)) return problem;
      ++vertices;
    } else if (tokens[0] == "f") {
      if (tokens.size() < 4)
        return fmt::format("{}: a face needs at least three vertices, found {}", where,
                           tokens.size() - 1);
      for (std::size_t i = 1; i < tokens.size(); ++i) {
        long index = 0;
        if (!parse_integer(tokens[i].substr(0, tokens[i].find('/')), index) || index == 0)
          return fmt::format("{}: '{}' is not a vertex index", where, printable(tokens[i]));
        if (index < 0 && -index > vertices)
          return fmt::format("{}: relative index {} reaches before the first vertex", where, index);
        if (index > 0) forward.push_back({line_no, index});
      }
    }
  }
  if (vertices == 0)
    return fmt::format("{}: no vertex ('v' line) found: not an OBJ file", path);
  for (const FaceRef& ref : forward)
    if (ref.index > vertices)
      return fmt::format("{}: line {}: face refers to vertex {}, but the file defines only {}", path,
                         ref.line, ref.index, vertices);
  return std::nullopt;
}

std::optional<std::string> diagnose_off(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  long line_no = 0;
  if (!next_content_line(in, line, line_no)) return fmt::format("{}: empty file", path);
  auto tokens = split_tokens(line);
  const std::string& magic = tokens[0];
  if (magic.size() < 3 || magic.compare(magic.size() - 3, 3, "OFF") != 0)
    return fmt::format("{}: line {}: an OFF file starts with 'OFF', found '{}'", path, line_no,
                       printable(magic, 20));
  tokens.erase(tokens.begin());
  if (tokens.empty()) {
    if (!next_content_line(in, line, line_no))
      return fmt::format("{}: the file ends before the vertex and face counts", path);
    tokens = split_tokens(line);
  }
  long nv = 0, nf = 0;
  if (tokens.size() < 2 || !parse_integer(tokens[0], nv) || !parse_integer(tokens[1], nf) ||
      nv < 0 || nf < 0)
    return fmt::format("{}: line {}: expected the counts 'vertices faces edges'", path, line_no);
  for (long v = 0; v < nv; ++v) {
    if (!next_content_line(in, line, line_no))
      return fmt::format("{}: the file ends after {} of {} vertices (truncated?)", path, v, nv);
    if (auto problem = check_coordinates(fmt::format("{}: line {}", path, line_no), split_tokens(line), 0))
      return problem;
  }
  for (long f = 0; f < nf; ++f) {
    if (!next_content_line(in, line, line_no))
      return fmt::format("{}: the file ends after {} of {} faces (truncated?)", path, f, nf);
    tokens = split_tokens(line);
    long k = 0;
    if (!parse_integer(tokens[0], k) || k < 3 || k >= static_cast<long>(tokens.size()))  // no k + 1: k may be LONG_MAX
      return fmt::format("{}: line {}: expected a face 'n i1 ... in' with n >= 3", path, line_no);
    for (long i = 1; i <= k; ++i) {
      long index = 0;
      if (!parse_integer(tokens[i], index) || index < 0 || index >= nv)
        return fmt::format("{}: line {}: vertex index '{}' is not in 0..{}", path, line_no,
                           printable(tokens[i]), nv - 1);
    }
  }
  // CGAL stops after the declared faces: more would be dropped without a word
  if (next_content_line(in, line, line_no))
    return fmt::format("{}: line {}: data after the {} faces the header declares (is the face "
                       "count too small?)", path, line_no, nf);
  return std::nullopt;
}

std::optional<std::string> diagnose_ply(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PlyHeader header;
  if (auto problem = read_ply_header(in, path, header)) return problem;
  if (header.encoding == PlyEncoding::ascii)
    if (auto problem = check_text(path)) return problem;
  const auto offset = static_cast<std::uint64_t>(in.tellg());
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  return check_ply_data(in, path, header, size > offset ? size - offset : 0);
}

namespace {

std::uint32_t little_endian_u32(const char* bytes) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  return value;
}

/// The corners of every triangle of a binary STL (whose size matched its count)
/// are finite: Gmsh's reader drops a NaN corner and its triangles without a word.
std::optional<std::string> check_binary_stl(std::istream& in, const std::string& path,
                                            std::uint32_t count) {
  char record[50];
  for (std::uint32_t t = 0; t < count; ++t) {
    if (!in.read(record, sizeof record))
      return fmt::format("{}: the file ends in triangle {} of {} (truncated?)", path, t + 1, count);
    for (int c = 0; c < 9; ++c) {  // after the 12-byte normal, 3 corners of 3 floats
      const std::uint32_t bits = little_endian_u32(record + 12 + 4 * c);
      float value;
      std::memcpy(&value, &bits, sizeof value);
      if (!std::isfinite(value))
        return fmt::format("{}: triangle {} of {}: corner {} has a coordinate that is not a finite "
                           "number ({})",
                           path, t + 1, count, c / 3 + 1, value);
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> diagnose_stl(const std::string& path) {
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (size == 0) return fmt::format("{}: empty file", path);
  std::ifstream in(path, std::ios::binary);
  std::string head(84, '\0');
  in.read(&head[0], 84);
  head.resize(static_cast<std::size_t>(in.gcount()));
  // Binary STL: an 80-byte header, a triangle count, 50 bytes per triangle,
  // exactly; the first bytes of the header may say "solid" all the same.
  const std::uint64_t count = head.size() == 84 ? little_endian_u32(&head[80]) : 0;
  if (head.size() == 84 && 84 + 50 * count == size)
    return check_binary_stl(in, path, static_cast<std::uint32_t>(count));
  const auto start = head.find_first_not_of(" \t\r\n");
  if (start == std::string::npos || head.compare(start, 5, "solid") != 0) {
    if (head.size() < 84)
      return fmt::format("{}: {} bytes is too short for a binary STL and it is not ASCII STL",
                         path, size);
    return fmt::format(
        "{}: binary STL header announces {} triangles ({} bytes) but the file has {} bytes "
        "(truncated or not STL)",
        path, count, 84 + 50 * count, size);
  }
  if (auto problem = check_text(path)) return problem;
  std::ifstream text(path);
  std::string line;
  long line_no = 0, corners = 0;
  bool ended = false;
  while (std::getline(text, line)) {
    ++line_no;
    const auto tokens = split_tokens(line);
    if (tokens.empty()) continue;
    const std::string where = fmt::format("{}: line {}", path, line_no);
    if (tokens[0] == "vertex") {
      if (auto problem = check_coordinates(where, tokens, 1)) return problem;
      ++corners;
    } else if (tokens[0] == "endfacet") {
      if (corners != 3) return fmt::format("{}: a facet needs 3 vertices, found {}", where, corners);
      corners = 0;
    } else if (tokens[0] == "endsolid") {
      ended = true;
    }
  }
  if (!ended) return fmt::format("{}: ASCII STL without 'endsolid' (truncated?)", path);
  return std::nullopt;
}

std::optional<std::string> diagnose_msh(const std::string& path) {
  std::ifstream in(path);
  std::string line, open_section;
  long line_no = 0, open_line = 0;
  bool any_section = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] != '$') continue;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.rfind("$End", 0) == 0) {
      if (line.substr(4) != open_section)
        return fmt::format("{}: line {}: '{}' does not close '${}'", path, line_no, printable(line),
                           open_section);
      open_section.clear();
    } else {
      if (!open_section.empty())
        return fmt::format("{}: line {}: section '${}' opened at line {} is not closed", path, line_no,
                           open_section, open_line);
      open_section = line.substr(1);
      open_line = line_no;
      any_section = true;
    }
  }
  if (!any_section) return fmt::format("{}: not a Gmsh MSH file (no $MeshFormat section)", path);
  if (!open_section.empty())
    return fmt::format("{}: section '${}' opened at line {} is not closed (truncated?)", path,
                       open_section, open_line);
  return std::nullopt;
}

namespace {

/// A binary MSH file: "$MeshFormat" then "version 1 data-size". Reads at most
/// two short lines: a file of binary garbage has no line end to stop at.
bool binary_msh(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string head(128, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::istringstream lines(head);
  std::string magic, format;
  std::getline(lines, magic);
  std::getline(lines, format);
  if (!magic.empty() && magic.back() == '\r') magic.pop_back();
  const auto tokens = split_tokens(format);
  return magic == "$MeshFormat" && tokens.size() == 3 && tokens[1] == "1";
}

/// Text formats are checked for being text first: the line scanners and the
/// libraries' readers read "a line" of binary garbage as the whole file.
std::optional<std::string> diagnose(const std::string& path, Format format) {
  switch (format) {
    case Format::obj:
      if (auto problem = check_text(path)) return problem;
      return diagnose_obj(path);
    case Format::off:
      if (auto problem = check_text(path)) return problem;
      return diagnose_off(path);
    case Format::ply: return diagnose_ply(path);  // text header, then text or binary
    case Format::stl: return diagnose_stl(path);  // binary, or text
    case Format::msh:
      if (binary_msh(path)) return check_binary_msh_counts(path);
      if (auto problem = check_text(path)) return problem;
      if (auto problem = diagnose_msh(path)) return problem;
      return check_msh_counts(path);
    default: return std::nullopt;
  }
}

/// What a path that is not a regular file is, for the message.
std::string file_kind(std::filesystem::file_type type) {
  switch (type) {
    case std::filesystem::file_type::directory: return "a directory";
    case std::filesystem::file_type::fifo: return "a FIFO (named pipe)";
    case std::filesystem::file_type::character: return "a character device";
    case std::filesystem::file_type::block: return "a block device";
    case std::filesystem::file_type::socket: return "a socket";
    default: return "not a regular file";
  }
}

[[noreturn]] void refuse(const std::string& message) { throw Error(ErrorCode::bad_input, message); }

}  // namespace

Format check_input_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // Only regular files: a FIFO blocks the reader forever, and a device such as
  // /dev/zero or /dev/urandom never ends. Symbolic links to a regular file are fine.
  const fs::file_status status = fs::status(path, ec);
  if (status.type() == fs::file_type::not_found) refuse(fmt::format("{}: no such file", path));
  if (ec) refuse(fmt::format("{}: cannot open the file for reading ({})", path, ec.message()));
  if (!fs::is_regular_file(status))
    refuse(fmt::format("{}: is {}, not a mesh file", path, file_kind(status.type())));
  if (fs::file_size(path, ec) == 0) refuse(fmt::format("{}: empty file", path));
  if (!std::ifstream(path).good()) refuse(fmt::format("{}: cannot open the file for reading", path));
  const Format format = format_of(path);
  if (!is_readable(format))
    refuse(fmt::format("{}: unknown input format '{}' (readable: {})", path,
                       fs::path(path).extension().string(), readable_extensions()));
  if (auto problem = diagnose(path, format)) refuse(*problem);
  return format;
}

}  // namespace qm::io
