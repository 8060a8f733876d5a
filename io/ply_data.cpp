#include "io/ply_data.h"

#include "io/text_diagnostics.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <vector>

namespace qm::io {

namespace {

constexpr std::uint64_t saturated = std::numeric_limits<std::uint64_t>::max();

std::uint64_t saturating_add(std::uint64_t a, std::uint64_t b) {
  return a > saturated - b ? saturated : a + b;
}

std::uint64_t saturating_mul(std::uint64_t a, std::uint64_t b) {
  return b != 0 && a > saturated / b ? saturated : a * b;
}

bool is_coordinate(const PlyHeader& header, std::size_t element, const PlyProperty& p) {
  return element == header.vertex_element && (p.name == "x" || p.name == "y" || p.name == "z");
}

bool is_face_indices(const PlyHeader& header, std::size_t element, std::size_t property) {
  return element == header.face_element && property == header.face_indices;
}

/// "vertex 12", "face 3", or "element 'edge' item 5" (PLY counts from 0).
std::string item_name(const PlyElement& element, std::uint64_t item) {
  if (element.name == "vertex" || element.name == "vertices") return fmt::format("vertex {}", item);
  if (element.name == "face" || element.name == "faces") return fmt::format("face {}", item);
  return fmt::format("element '{}' item {}", printable(element.name, 20), item);
}

std::uint64_t item_minimum_bytes(const PlyHeader& header, std::size_t e, bool binary) {
  std::uint64_t bytes = 0;
  const auto& properties = header.elements[e].properties;
  for (std::size_t k = 0; k < properties.size(); ++k) {
    const PlyProperty& p = properties[k];
    const std::uint64_t value = binary ? static_cast<std::uint64_t>(p.value.size) : 2;
    const std::uint64_t length = binary ? static_cast<std::uint64_t>(p.length.size) : 2;
    if (!p.is_list) bytes += value;
    else bytes += length + (is_face_indices(header, e, k) ? 3 * value : 0);
  }
  return bytes;
}

/// The binary data after the header: values in the file's byte order.
class BinaryData {
 public:
  BinaryData(std::istream& in, std::uint64_t bytes, bool big_endian)
      : in_(in), left_(bytes), big_endian_(big_endian) {}

  std::uint64_t left() const { return left_; }

  /// The bits of one value of `size` bytes, as an unsigned number; false at the end.
  bool read(int size, std::uint64_t& bits) {
    unsigned char b[8];
    if (left_ < static_cast<std::uint64_t>(size) ||
        !in_.read(reinterpret_cast<char*>(b), size))
      return false;
    left_ -= static_cast<std::uint64_t>(size);
    bits = 0;
    for (int i = 0; i < size; ++i) {
      const int byte = big_endian_ ? i : size - 1 - i;
      bits = (bits << 8) | b[byte];
    }
    return true;
  }

  bool skip(std::uint64_t bytes) {
    if (left_ < bytes) return false;
    in_.seekg(static_cast<std::streamoff>(bytes), std::ios::cur);
    left_ -= bytes;
    return static_cast<bool>(in_);
  }

 private:
  std::istream& in_;
  std::uint64_t left_;
  bool big_endian_;
};

std::int64_t as_integer(std::uint64_t bits, const PlyType& type) {
  if (!type.is_signed || type.size == 8) return static_cast<std::int64_t>(bits);
  const std::uint64_t sign = std::uint64_t{1} << (8 * type.size - 1);
  return static_cast<std::int64_t>((bits ^ sign)) - static_cast<std::int64_t>(sign);
}

double as_real(std::uint64_t bits, const PlyType& type) {
  if (type.size == 4) {
    const auto narrow = static_cast<std::uint32_t>(bits);
    float f;
    std::memcpy(&f, &narrow, sizeof f);
    return f;
  }
  double d;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

std::optional<std::string> check_binary(std::istream& in, const std::string& path,
                                        const PlyHeader& header, std::uint64_t data_bytes) {
  BinaryData data(in, data_bytes, header.encoding == PlyEncoding::binary_big_endian);
  const std::uint64_t vertices = header.elements[header.vertex_element].count;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::uint64_t i = 0; i < element.count; ++i) {
      auto truncated = [&] {
        return fmt::format("{}: the file ends in {} of {} (truncated?)", path, item_name(element, i),
                           element.count);
      };
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        std::uint64_t bits = 0;
        if (!p.is_list) {
          if (!data.read(p.value.size, bits)) return truncated();
          if (is_coordinate(header, e, p) && !std::isfinite(as_real(bits, p.value)))
            return fmt::format("{}: {}: coordinate {} is not a finite number ({})", path,
                               item_name(element, i), p.name, as_real(bits, p.value));
          continue;
        }
        if (!data.read(p.length.size, bits)) return truncated();
        const std::int64_t length = as_integer(bits, p.length);
        if (length < 0)
          return fmt::format("{}: {}: negative list length {}", path, item_name(element, i), length);
        const auto n = static_cast<std::uint64_t>(length);
        if (saturating_mul(n, static_cast<std::uint64_t>(p.value.size)) > data.left())
          return fmt::format("{}: {}: a list of {} values runs past the end of the file", path,
                             item_name(element, i), n);
        if (!is_face_indices(header, e, k)) {
          if (!data.skip(n * static_cast<std::uint64_t>(p.value.size))) return truncated();
          continue;
        }
        if (n < 3)
          return fmt::format("{}: {}: {} vertices (a face needs at least 3)", path,
                             item_name(element, i), n);
        for (std::uint64_t c = 0; c < n; ++c) {
          if (!data.read(p.value.size, bits)) return truncated();
          const std::int64_t index = as_integer(bits, p.value);
          if (index < 0 || static_cast<std::uint64_t>(index) >= vertices)
            return fmt::format("{}: {}: vertex index {} is not in 0..{}", path,
                               item_name(element, i), index,
                               static_cast<std::int64_t>(vertices) - 1);
        }
      }
    }
  }
  if (data.left() == 0) return std::nullopt;
  // A trailing line end or two is harmless; more is data the counts leave out.
  if (data.left() <= 4) {
    bool blank = true;
    for (int c; (c = in.get()) != std::char_traits<char>::eof();)
      blank = blank && (c == '\n' || c == '\r' || c == ' ');
    if (blank) return std::nullopt;
  }
  return fmt::format("{}: {} bytes follow the last {} (is a count in the header too small?)", path,
                     data.left(), printable(header.elements.back().name, 20));
}

/// The ASCII data after the header, one token at a time, with line numbers.
class Tokens {
 public:
  Tokens(std::istream& in, long line_no) : in_(in), line_no_(line_no) {}
  long line() const { return line_no_; }
  bool next(std::string& token) {
    while (next_ == tokens_.size()) {
      std::string text;
      if (!std::getline(in_, text)) return false;
      ++line_no_;
      tokens_.clear();
      next_ = 0;
      std::istringstream split(text);
      for (std::string t; split >> t;) tokens_.push_back(t);
    }
    token = tokens_[next_++];
    return true;
  }

 private:
  std::istream& in_;
  long line_no_;
  std::vector<std::string> tokens_;
  std::size_t next_ = 0;
};

bool parse_int(const std::string& token, std::int64_t& value) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(begin, &end, 10);
  return end != begin && *end == '\0' && errno != ERANGE;
}

std::optional<std::string> check_ascii(std::istream& in, const std::string& path,
                                       const PlyHeader& header) {
  Tokens tokens(in, header.lines);
  const std::uint64_t vertices = header.elements[header.vertex_element].count;
  std::string token;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    for (std::uint64_t i = 0; i < element.count; ++i) {
      auto where = [&] { return fmt::format("{}: line {}", path, tokens.line()); };
      auto truncated = [&] {
        return fmt::format("{}: the file ends in {} of {} (truncated?)", path, item_name(element, i),
                           element.count);
      };
      for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        if (!p.is_list) {
          if (!tokens.next(token)) return truncated();
          const char* begin = token.c_str();
          char* end = nullptr;
          const double value = std::strtod(begin, &end);
          if (end == begin || *end != '\0')
            return fmt::format("{}: '{}' is not a number", where(), printable(token));
          if (is_coordinate(header, e, p) && !std::isfinite(value))
            return fmt::format("{}: coordinate '{}' is not a finite number", where(),
                               printable(token));
          continue;
        }
        if (!tokens.next(token)) return truncated();
        std::int64_t length = 0;
        if (!parse_int(token, length) || length < 0)
          return fmt::format("{}: {}: '{}' is not a list length", where(), item_name(element, i),
                             printable(token));
        const bool indices = is_face_indices(header, e, k);
        if (indices && length < 3)
          return fmt::format("{}: {}: {} vertices (a face needs at least 3)", where(),
                             item_name(element, i), length);
        for (std::int64_t c = 0; c < length; ++c) {
          if (!tokens.next(token)) return truncated();
          std::int64_t index = 0;
          if (!indices) continue;
          if (!parse_int(token, index) || index < 0 || static_cast<std::uint64_t>(index) >= vertices)
            return fmt::format("{}: vertex index '{}' is not in 0..{}", where(), printable(token),
                               static_cast<std::int64_t>(vertices) - 1);
        }
      }
    }
  }
  if (tokens.next(token))
    return fmt::format("{}: line {}: data after the last {} (is a count in the header too small?)",
                       path, tokens.line(), printable(header.elements.back().name, 20));
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_ply_data(std::istream& in, const std::string& path,
                                          const PlyHeader& header, std::uint64_t data_bytes) {
  // First the counts against the size, element by element, so that the message
  // names the count that cannot be true.
  const bool binary = header.encoding != PlyEncoding::ascii;
  // (the last ASCII value needs no separator after it)
  const std::uint64_t available = binary ? data_bytes : saturating_add(data_bytes, 1);
  std::uint64_t needed = 0;
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    needed = saturating_add(needed,
                            saturating_mul(element.count, item_minimum_bytes(header, e, binary)));
    if (needed > available)
      return fmt::format("{}: line {}: 'element {} {}' cannot be true: the file has {} bytes after "
                         "its header",
                         path, element.line, printable(element.name, 20), element.count,
                         data_bytes);
  }
  return binary ? check_binary(in, path, header, data_bytes) : check_ascii(in, path, header);
}

}  // namespace qm::io
