#include "io/msh_counts.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <vector>

namespace qm::io {

namespace {

/// Little-endian binary data of a section, with the position in the file.
struct Bytes {
  const std::string& data;
  std::size_t pos;

  std::uint64_t left() const { return data.size() - pos; }
  bool u64(std::uint64_t& v) { return fixed(v, 8); }
  bool i32(std::int64_t& v) {
    std::uint64_t raw = 0;
    if (!fixed(raw, 4)) return false;
    v = static_cast<std::int32_t>(static_cast<std::uint32_t>(raw));
    return true;
  }
  bool skip(std::uint64_t n) {
    if (n > left()) return false;
    pos += static_cast<std::size_t>(n);
    return true;
  }
  /// A decimal count on its own line (format 2 writes its counts as text).
  bool text_count(std::uint64_t& v) {
    const std::size_t end = data.find('\n', pos);
    if (end == std::string::npos || end - pos > 20) return false;
    const std::string line = data.substr(pos, end - pos);
    if (line.empty() || line.find_first_not_of("0123456789\r ") != std::string::npos) return false;
    v = std::stoull(line);
    pos = end + 1;
    return true;
  }
  /// `marker` follows (after the line end that ends the binary data).
  bool at(const std::string& marker) const {
    const std::size_t p = data.compare(pos, 1, "\n") == 0 ? pos + 1 : pos;
    return data.compare(p, marker.size(), marker) == 0;
  }

 private:
  bool fixed(std::uint64_t& v, int size) {
    if (left() < static_cast<std::uint64_t>(size)) return false;
    v = 0;
    for (int i = size - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(data[pos + i]);
    pos += static_cast<std::size_t>(size);
    return true;
  }
};

std::string ends(const std::string& path, const char* section) {
  return fmt::format("{}: the file ends inside {} (truncated?)", path, section);
}

/// Format 4.1 $Nodes: 4 counts, then per block dim, entity, parametric (int),
/// n (size_t), n tags (size_t) and n coordinate triples (double).
std::optional<std::string> v41_nodes(Bytes b, const std::string& path) {
  std::uint64_t blocks = 0, nodes = 0, min = 0, max = 0;
  if (!b.u64(blocks) || !b.u64(nodes) || !b.u64(min) || !b.u64(max)) return ends(path, "$Nodes");
  std::uint64_t total = 0;
  for (std::uint64_t k = 0; k < blocks; ++k) {
    std::int64_t dim = 0, entity = 0, parametric = 0;
    std::uint64_t n = 0;
    if (!b.i32(dim) || !b.i32(entity) || !b.i32(parametric) || !b.u64(n))
      return fmt::format("{}: $Nodes declares {} blocks; the file ends in block {}", path, blocks,
                         k + 1);
    if (dim < 0 || dim > 3 || parametric < 0 || parametric > 1)
      return fmt::format("{}: $Nodes block {} is not a node block (dimension {})", path, k + 1, dim);
    const std::uint64_t per = 8 + 8 * (3 + (parametric ? static_cast<std::uint64_t>(dim) : 0));
    if (n > b.left() / per)
      return fmt::format("{}: $Nodes block {} declares {} nodes; the {} bytes left hold at most {}",
                         path, k + 1, n, b.left(), b.left() / per);
    b.skip(n * per);
    total += n;
  }
  if (total != nodes)
    return fmt::format("{}: $Nodes declares {} nodes but its blocks hold {}", path, nodes, total);
  if (!b.at("$EndNodes"))
    return fmt::format("{}: $Nodes: more data after its {} blocks (is a count too small?)", path,
                       blocks);
  return std::nullopt;
}

/// Format 4.1 $Elements: 4 counts, then per block dim, entity, type (int), n
/// (size_t) and n times a tag and the nodes (size_t).
std::optional<std::string> v41_elements(Bytes b, const std::string& path,
                                        std::uint64_t max_node_tag) {
  std::uint64_t blocks = 0, elements = 0, min = 0, max = 0;
  if (!b.u64(blocks) || !b.u64(elements) || !b.u64(min) || !b.u64(max))
    return ends(path, "$Elements");
  std::uint64_t total = 0;
  for (std::uint64_t k = 0; k < blocks; ++k) {
    std::int64_t dim = 0, entity = 0, type = 0;
    std::uint64_t n = 0;
    if (!b.i32(dim) || !b.i32(entity) || !b.i32(type) || !b.u64(n))
      return fmt::format("{}: $Elements declares {} blocks; the file ends in block {}", path,
                         blocks, k + 1);
    const std::size_t corners = msh_element_nodes(type);
    if (corners == 0) return std::nullopt;  // a type not listed: Gmsh checks the rest
    const std::uint64_t per = 8 * (1 + corners);
    if (n > b.left() / per)
      return fmt::format("{}: $Elements block {} declares {} elements; the {} bytes left hold at "
                         "most {}", path, k + 1, n, b.left(), b.left() / per);
    for (std::uint64_t e = 0; e < n; ++e) {
      std::uint64_t tag = 0, node = 0;
      b.u64(tag);
      // Gmsh crashes on a node tag far beyond the others (SIGSEGV at 3e9)
      for (std::size_t c = 0; c < corners; ++c)
        if (b.u64(node) && (node < 1 || node > max_node_tag))
          return fmt::format("{}: $Elements block {}: element {} refers to node {}, but the node "
                             "tags go from 1 to {}", path, k + 1, tag, node, max_node_tag);
    }
    total += n;
  }
  if (total != elements)
    return fmt::format("{}: $Elements declares {} elements but its blocks hold {}", path, elements,
                       total);
  if (!b.at("$EndElements"))
    return fmt::format("{}: $Elements: more data after its {} blocks (is a count too small?)",
                       path, blocks);
  return std::nullopt;
}

/// Format 2 $Nodes: a text count, then per node an int tag and three doubles.
std::optional<std::string> v2_nodes(Bytes b, const std::string& path) {
  std::uint64_t nodes = 0;
  if (!b.text_count(nodes)) return fmt::format("{}: $Nodes has no node count", path);
  if (nodes > b.left() / 28)
    return fmt::format("{}: $Nodes declares {} nodes; the {} bytes left hold at most {}", path,
                       nodes, b.left(), b.left() / 28);
  b.skip(nodes * 28);
  if (!b.at("$EndNodes"))
    return fmt::format("{}: $Nodes declares {} nodes but more data follows", path, nodes);
  return std::nullopt;
}

/// Format 2 $Elements: a text count, then groups: type, count, tag count (int)
/// and per element its number, tags and nodes (int).
std::optional<std::string> v2_elements(Bytes b, const std::string& path) {
  std::uint64_t elements = 0;
  if (!b.text_count(elements)) return fmt::format("{}: $Elements has no element count", path);
  if (elements > b.left() / 8)  // the smallest: a point, no tags
    return fmt::format("{}: $Elements declares {} elements; the {} bytes left cannot hold them",
                       path, elements, b.left());
  std::uint64_t read = 0;
  while (read < elements) {
    std::int64_t type = 0, follow = 0, tags = 0;
    if (!b.i32(type) || !b.i32(follow) || !b.i32(tags)) return ends(path, "$Elements");
    const std::size_t corners = msh_element_nodes(type);
    if (corners == 0) return std::nullopt;  // a type not listed: Gmsh checks the rest
    if (follow < 0 || tags < 0)
      return fmt::format("{}: $Elements: a group of {} elements with {} tags", path, follow, tags);
    const std::uint64_t per = 4 * (1 + static_cast<std::uint64_t>(tags) + corners);
    if (static_cast<std::uint64_t>(follow) > b.left() / per)
      return fmt::format("{}: $Elements: a group declares {} elements; the {} bytes left hold at "
                         "most {}", path, follow, b.left(), b.left() / per);
    b.skip(static_cast<std::uint64_t>(follow) * per);
    read += static_cast<std::uint64_t>(follow);
  }
  if (read != elements || !b.at("$EndElements"))
    return fmt::format("{}: $Elements declares {} elements but more follow", path, elements);
  return std::nullopt;
}

}  // namespace

std::optional<std::string> check_binary_msh_counts(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  const std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t line_end = data.find('\n', 12);
  if (data.compare(0, 12, "$MeshFormat\n") != 0 || line_end == std::string::npos) return std::nullopt;
  std::istringstream format(data.substr(12, line_end - 12));
  std::string version, file_type, size;
  format >> version >> file_type >> size;
  // Only the layouts written by Gmsh 2.x and 4.1 with 8-byte sizes, little-endian
  // (the int 1 that follows the format line says which); others are left to Gmsh.
  if (size != "8" || data.compare(line_end + 1, 4, std::string("\1\0\0\0", 4)) != 0)
    return std::nullopt;
  const bool v41 = version == "4.1", v2 = version.rfind("2.", 0) == 0;
  if (!v41 && !v2) return std::nullopt;
  std::uint64_t max_node_tag = std::numeric_limits<std::int32_t>::max();  // until $Nodes says
  for (const char* section : {"\n$Nodes\n", "\n$Elements\n"}) {
    const std::size_t at = data.find(section, line_end);
    if (at == std::string::npos) continue;
    Bytes bytes{data, at + std::strlen(section)};
    const bool nodes = section[2] == 'N';
    if (nodes && v41) {
      Bytes counts = bytes;
      std::uint64_t skip = 0;
      if (counts.u64(skip) && counts.u64(skip) && counts.u64(skip)) counts.u64(max_node_tag);
    }
    auto problem = v41 ? (nodes ? v41_nodes(bytes, path) : v41_elements(bytes, path, max_node_tag))
                       : (nodes ? v2_nodes(bytes, path) : v2_elements(bytes, path));
    if (problem) return problem;
  }
  return std::nullopt;
}

}  // namespace qm::io
