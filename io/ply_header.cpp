#include "io/ply_header.h"

#include "io/text_check.h"
#include "io/text_diagnostics.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace qm::io {

namespace {

/// A real header is a few hundred bytes; past this it is not a PLY header.
constexpr std::size_t max_header_bytes = std::size_t{1} << 20;

std::optional<PlyType> ply_type(const std::string& name) {
  if (name == "char" || name == "int8") return PlyType{1, false, true};
  if (name == "uchar" || name == "uint8") return PlyType{1, false, false};
  if (name == "short" || name == "int16") return PlyType{2, false, true};
  if (name == "ushort" || name == "uint16") return PlyType{2, false, false};
  if (name == "int" || name == "int32") return PlyType{4, false, true};
  if (name == "uint" || name == "uint32") return PlyType{4, false, false};
  if (name == "float" || name == "float32") return PlyType{4, true, true};
  if (name == "double" || name == "float64") return PlyType{8, true, true};
  return std::nullopt;
}

std::vector<std::string> tokens_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> tokens;
  for (std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

/// A count: decimal digits only (no sign, no exponent), below 2^63.
bool parse_count(const std::string& token, std::uint64_t& count) {
  if (token.empty() || token.find_first_not_of("0123456789") != std::string::npos) return false;
  errno = 0;
  const unsigned long long value = std::strtoull(token.c_str(), nullptr, 10);
  if (errno == ERANGE || value > static_cast<unsigned long long>(std::numeric_limits<std::int64_t>::max()))
    return false;
  count = value;
  return true;
}

/// One header line into `line` (CR and trailing blanks dropped); a message if the
/// bytes read so far are not a text header.
std::optional<std::string> next_header_line(std::istream& in, const std::string& path,
                                            long line_no, std::size_t& bytes, std::string& line,
                                            bool& at_end) {
  line.clear();
  at_end = false;
  for (int c; (c = in.get()) != std::char_traits<char>::eof();) {
    if (++bytes > max_header_bytes)
      return fmt::format("{}: no 'end_header' in the first 1 MiB: not a PLY file", path);
    if (c == '\n') {
      while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
        line.pop_back();
      return std::nullopt;
    }
    if (is_binary_byte(static_cast<unsigned char>(c)))
      return fmt::format("{}: line {}: not text (byte 0x{:02x})", path, line_no, c);
    line.push_back(static_cast<char>(c));
  }
  at_end = true;
  return std::nullopt;
}

std::optional<std::string> parse_property(const std::vector<std::string>& t,
                                          const std::string& where, PlyProperty& property) {
  const bool list = t.size() >= 2 && t[1] == "list";
  if (t.size() != (list ? 5u : 3u))
    return fmt::format("{}: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'",
                       where);
  const std::string& type = list ? t[3] : t[1];
  const auto value = ply_type(type);
  if (!value) return fmt::format("{}: unknown property type '{}'", where, printable(type, 20));
  property.value = *value;
  property.name = t.back();
  property.is_list = list;
  if (list) {
    const auto length = ply_type(t[2]);
    if (!length || length->is_float)
      return fmt::format("{}: a list's length type must be an integer type, found '{}'", where,
                         printable(t[2], 20));
    property.length = *length;
  }
  return std::nullopt;
}

const PlyProperty* find_property(const PlyElement& element, const std::string& name) {
  for (const PlyProperty& p : element.properties)
    if (p.name == name) return &p;
  return nullptr;
}

/// The vertex and face elements are there, with what the readers take from them.
std::optional<std::string> check_required(const std::string& path, PlyHeader& header) {
  const long end_line = header.lines;
  bool has_vertex = false, has_face = false;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    if ((element.name == "vertex" || element.name == "vertices") && !has_vertex) {
      has_vertex = true;
      header.vertex_element = e;
    } else if ((element.name == "face" || element.name == "faces") && !has_face) {
      has_face = true;
      header.face_element = e;
    }
  }
  if (!has_vertex) {
    // most likely a misspelt vertex element: name the first element line
    for (const PlyElement& element : header.elements)
      if (element.name != "face" && element.name != "faces")
        return fmt::format("{}: line {}: expected 'element vertex N', found 'element {}'", path,
                           element.line, printable(element.name, 20));
    return fmt::format("{}: line {}: the header declares no 'element vertex'", path, end_line);
  }
  const PlyElement& vertex = header.elements[header.vertex_element];
  for (const char* axis : {"x", "y", "z"}) {
    const PlyProperty* p = find_property(vertex, axis);
    if (!p)
      return fmt::format("{}: line {}: element vertex has no property '{}'", path, vertex.line, axis);
    if (p->is_list || !p->value.is_float)
      return fmt::format("{}: line {}: vertex property '{}' must be float or double", path, p->line,
                         axis);
  }
  if (vertex.count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
    return fmt::format("{}: line {}: {} vertices: more than 2^31 - 1, the most this program takes",
                       path, vertex.line, vertex.count);
  if (!has_face)
    return fmt::format("{}: line {}: the header declares no 'element face'", path, end_line);
  const PlyElement& face = header.elements[header.face_element];
  for (std::size_t k = 0; k < face.properties.size(); ++k) {
    const PlyProperty& p = face.properties[k];
    if (p.name != "vertex_indices" && p.name != "vertex_index") continue;
    if (!p.is_list || p.value.is_float || p.value.size != 4)
      return fmt::format("{}: line {}: face property '{}' must be a list of int or uint", path,
                         p.line, p.name);
    header.face_indices = k;
    if (face.count > static_cast<std::uint64_t>(std::numeric_limits<int>::max()))
      return fmt::format("{}: line {}: {} faces: more than 2^31 - 1, the most this program takes",
                         path, face.line, face.count);
    return std::nullopt;
  }
  return fmt::format("{}: line {}: element face has no list property 'vertex_indices'", path,
                     face.line);
}

}  // namespace

std::optional<std::string> read_ply_header(std::istream& in, const std::string& path,
                                           PlyHeader& header) {
  header = PlyHeader{};
  std::size_t bytes = 0;
  std::string line;
  bool at_end = false;
  for (long line_no = 1;; ++line_no) {
    if (auto problem = next_header_line(in, path, line_no, bytes, line, at_end)) return problem;
    if (at_end && line.empty())
      return fmt::format("{}: the PLY header has no 'end_header' (truncated?)", path);
    header.lines = line_no;
    const std::string where = fmt::format("{}: line {}", path, line_no);
    const auto t = tokens_of(line);
    if (line_no == 1) {
      if (t.size() != 1 || t[0] != "ply")
        return fmt::format("{}: a PLY file starts with 'ply', found '{}'", where,
                           printable(line, 20));
      continue;
    }
    if (line_no == 2) {
      if (t.size() != 3 || t[0] != "format" || t[2] != "1.0")
        return fmt::format("{}: expected 'format ascii 1.0' (or binary_little_endian, "
                           "binary_big_endian), found '{}'", where, printable(line));
      if (t[1] == "ascii") header.encoding = PlyEncoding::ascii;
      else if (t[1] == "binary_little_endian") header.encoding = PlyEncoding::binary_little_endian;
      else if (t[1] == "binary_big_endian") header.encoding = PlyEncoding::binary_big_endian;
      else return fmt::format("{}: unknown PLY format '{}'", where, printable(t[1], 30));
      continue;
    }
    if (t.empty()) return fmt::format("{}: empty line in the PLY header", where);
    if (t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") {
      if (t.size() != 1) return fmt::format("{}: expected 'end_header', found '{}'", where, printable(line));
      return check_required(path, header);
    }
    if (t[0] == "element") {
      PlyElement element;
      if (t.size() != 3 || !parse_count(t[2], element.count))
        return fmt::format("{}: expected 'element NAME COUNT' with a count from 0 to 2^63 - 1, "
                           "found '{}'", where, printable(line));
      element.name = t[1];
      element.line = line_no;
      header.elements.push_back(std::move(element));
      continue;
    }
    if (t[0] == "property") {
      if (header.elements.empty())
        return fmt::format("{}: 'property' before any 'element' line", where);
      PlyProperty property;
      property.line = line_no;
      if (auto problem = parse_property(t, where, property)) return problem;
      header.elements.back().properties.push_back(std::move(property));
      continue;
    }
    return fmt::format("{}: unknown PLY header line '{}'", where, printable(line));
  }
}

}  // namespace qm::io
