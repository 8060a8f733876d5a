#include "io/msh_counts.h"

#include "io/text_diagnostics.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <vector>

namespace qm::io {

namespace {

/// The lines of the file as token lists, with their numbers and one line of
/// look-ahead.
class MshLines {
 public:
  explicit MshLines(const std::string& path) : in_(path) {}

  /// The next line (false at the end of the file); `peek` leaves it for next time.
  bool next(std::vector<std::string>& tokens) {
    if (!peek()) return false;
    tokens = std::move(ahead_);
    has_ahead_ = false;
    line_ = ahead_line_;
    return true;
  }
  bool peek() {
    if (has_ahead_) return true;
    std::string text;
    if (!std::getline(in_, text)) return false;
    ahead_.clear();
    std::istringstream split(text);
    for (std::string t; split >> t;) ahead_.push_back(t);
    ahead_line_ = ++read_;
    has_ahead_ = true;
    return true;
  }
  const std::vector<std::string>& ahead() const { return ahead_; }
  /// The number of the line `next` returned last.
  long line() const { return line_; }

 private:
  std::ifstream in_;
  std::vector<std::string> ahead_;
  bool has_ahead_ = false;
  long read_ = 0, ahead_line_ = 0, line_ = 0;
};

bool is_marker(const std::vector<std::string>& tokens) {
  return !tokens.empty() && !tokens[0].empty() && tokens[0][0] == '$';
}

bool parse_count(const std::string& token, long long& value) {
  const char* begin = token.c_str();
  char* end = nullptr;
  errno = 0;
  value = std::strtoll(begin, &end, 10);
  return end != begin && *end == '\0' && errno != ERANGE && value >= 0;
}

/// `tokens` are `n` counts (non-negative integers); false if not.
bool parse_counts(const std::vector<std::string>& tokens, std::size_t n, std::vector<long long>& out) {
  if (tokens.size() != n) return false;
  out.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
    if (!parse_count(tokens[i], out[i])) return false;
  return true;
}

std::optional<std::string> finite_coordinates(const std::string& where,
                                              const std::vector<std::string>& tokens,
                                              std::size_t first) {
  if (tokens.size() < first + 3)
    return fmt::format("{}: a node needs three coordinates, found {}", where,
                       tokens.size() < first ? 0 : tokens.size() - first);
  for (std::size_t i = first; i < first + 3; ++i) {
    const char* begin = tokens[i].c_str();
    char* end = nullptr;
    const double v = std::strtod(begin, &end);
    if (end == begin || *end != '\0')
      return fmt::format("{}: '{}' is not a number", where, printable(tokens[i]));
    if (!std::isfinite(v))
      return fmt::format("{}: coordinate '{}' is not a finite number", where, printable(tokens[i]));
  }
  return std::nullopt;
}

/// Format 2: "$Nodes", a count, then one line per node up to "$EndNodes" (the
/// same for $Elements).
std::optional<std::string> check_v2_section(MshLines& lines, const std::string& path,
                                            bool nodes) {
  const char* section = nodes ? "$Nodes" : "$Elements";
  const char* what = nodes ? "nodes" : "elements";
  std::vector<std::string> t;
  std::vector<long long> count;
  if (!lines.next(t) || !parse_counts(t, 1, count))
    return fmt::format("{}: line {}: expected the number of {} after {}", path, lines.line(), what,
                       section);
  const long header = lines.line();
  long long found = 0;
  while (lines.peek() && !is_marker(lines.ahead())) {
    lines.next(t);
    if (t.empty()) continue;
    ++found;
    const std::string where = fmt::format("{}: line {}", path, lines.line());
    if (nodes) {
      if (auto problem = finite_coordinates(where, t, 1)) return problem;
      continue;
    }
    std::vector<long long> head;
    if (t.size() < 3 || !parse_counts({t[0], t[1], t[2]}, 3, head))
      return fmt::format("{}: expected an element 'tag type tag-count tags... nodes...'", where);
    const std::size_t k = msh_element_nodes(head[1]);
    if (k > 0 && t.size() != 3 + static_cast<std::size_t>(head[2]) + k)
      return fmt::format("{}: an element of type {} with {} tags has {} values, not {}", where,
                         head[1], head[2], t.size(), 3 + head[2] + static_cast<long long>(k));
  }
  if (found != count[0])
    return fmt::format("{}: line {}: {} declares {} {} but {} follow", path, header, section,
                       count[0], what, found);
  return std::nullopt;
}

/// The lines after the current one that have `size` tokens, up to a marker or a
/// line of another size (how many entries a block really has).
long long count_lines_of_size(MshLines& lines, std::size_t size) {
  long long n = 0;
  std::vector<std::string> t;
  while (lines.peek() && !is_marker(lines.ahead()) && lines.ahead().size() == size) {
    lines.next(t);
    ++n;
  }
  return n;
}

/// Format 4.1 $Nodes: "blocks nodes min max", then per block "dim entity
/// parametric n", n tag lines and n coordinate lines.
std::optional<std::string> check_v4_nodes(MshLines& lines, const std::string& path,
                                          long long& max_tag) {
  std::vector<std::string> t;
  std::vector<long long> head, block;
  if (!lines.next(t) || !parse_counts(t, 4, head))
    return fmt::format("{}: line {}: expected '$Nodes' counts 'blocks nodes min-tag max-tag'", path,
                       lines.line());
  const long header = lines.line();
  max_tag = head[3];
  long long total = 0;
  for (long long b = 0; b < head[0]; ++b) {
    if (!lines.next(t) || is_marker(t))
      return fmt::format("{}: line {}: $Nodes declares {} blocks but {} follow", path, header,
                         head[0], b);
    if (!parse_counts(t, 4, block) || block[0] > 3 || block[2] > 1)
      return fmt::format("{}: line {}: expected a node block 'dim entity parametric count'", path,
                         lines.line());
    const long at = lines.line();
    const long long n = block[3];
    // n tags, one per line: fewer means the count is too large
    for (long long i = 0; i < n; ++i) {
      if (!lines.peek() || is_marker(lines.ahead()) || lines.ahead().size() != 1)
        return fmt::format("{}: line {}: the node block declares {} nodes but {} follow", path, at,
                           n, i);
      lines.next(t);
    }
    // then n coordinate lines; more tags here mean the count is too small
    if (lines.peek() && lines.ahead().size() == 1 && !is_marker(lines.ahead()))
      return fmt::format("{}: line {}: the node block declares {} nodes but {} follow", path, at,
                         n, n + count_lines_of_size(lines, 1));
    const std::size_t values = 3 + (block[2] == 1 ? static_cast<std::size_t>(block[0]) : 0);
    for (long long i = 0; i < n; ++i) {
      if (!lines.next(t) || is_marker(t))
        return fmt::format("{}: the file ends in the node block at line {} (truncated?)", path, at);
      const std::string where = fmt::format("{}: line {}", path, lines.line());
      if (auto problem = finite_coordinates(where, t, 0)) return problem;
      if (t.size() != values)
        return fmt::format("{}: a node here has {} values, not {}", where, t.size(), values);
    }
    total += n;
  }
  if (lines.peek() && !is_marker(lines.ahead()))
    return fmt::format("{}: line {}: more data after the {} node blocks that line {} declares",
                       path, lines.line() + 1, head[0], header);
  if (total != head[1])
    return fmt::format("{}: line {}: $Nodes declares {} nodes but its blocks hold {}", path, header,
                       head[1], total);
  return std::nullopt;
}

/// Format 4.1 $Elements: "blocks elements min max", then per block "dim entity
/// type n" and n lines "tag node...".
std::optional<std::string> check_v4_elements(MshLines& lines, const std::string& path,
                                             long long max_node_tag) {
  std::vector<std::string> t;
  std::vector<long long> head, block;
  if (!lines.next(t) || !parse_counts(t, 4, head))
    return fmt::format("{}: line {}: expected '$Elements' counts 'blocks elements min-tag max-tag'",
                       path, lines.line());
  const long header = lines.line();
  long long total = 0;
  long previous_block = 0;
  long long previous_count = 0;
  std::size_t previous_size = 0;
  // An element line where a block line or the end was expected: the count of
  // the block before is too small.
  auto too_many = [&]() {
    const long long more = count_lines_of_size(lines, previous_size);
    return fmt::format("{}: line {}: the element block declares {} elements but {} follow", path,
                       previous_block, previous_count, previous_count + more);
  };
  for (long long b = 0; b < head[0]; ++b) {
    if (!lines.peek() || is_marker(lines.ahead()))
      return fmt::format("{}: line {}: $Elements declares {} blocks but {} follow", path, header,
                         head[0], b);
    if (!parse_counts(lines.ahead(), 4, block) || block[0] > 3 || block[2] == 0) {
      if (b > 0 && lines.ahead().size() == previous_size) return too_many();
      lines.next(t);
      return fmt::format("{}: line {}: expected an element block 'dim entity type count'", path,
                         lines.line());
    }
    lines.next(t);
    const long at = lines.line();
    const long long n = block[3];
    const std::size_t k = msh_element_nodes(block[2]);
    for (long long i = 0; i < n; ++i) {
      if (!lines.peek() || is_marker(lines.ahead()) || (k > 0 && lines.ahead().size() != 1 + k))
        return fmt::format("{}: line {}: the element block declares {} elements but {} follow",
                           path, at, n, i);
      lines.next(t);
      // Gmsh crashes on a node tag far beyond the others (SIGSEGV at 3e9)
      for (std::size_t c = 1; c < t.size(); ++c) {
        long long tag = 0;
        if (!parse_count(t[c], tag) || tag < 1 || tag > max_node_tag)
          return fmt::format("{}: line {}: element {} refers to node '{}', but the node tags go "
                             "from 1 to {}", path, lines.line(), printable(t[0], 20),
                             printable(t[c], 20), max_node_tag);
      }
    }
    total += n;
    previous_block = at;
    previous_count = n;
    previous_size = k > 0 ? 1 + k : t.size();
  }
  if (lines.peek() && !is_marker(lines.ahead())) {
    if (head[0] > 0 && lines.ahead().size() == previous_size) return too_many();
    return fmt::format("{}: line {}: more data after the {} element blocks that line {} declares",
                       path, lines.line() + 1, head[0], header);
  }
  if (total != head[1])
    return fmt::format("{}: line {}: $Elements declares {} elements but its blocks hold {}", path,
                       header, head[1], total);
  return std::nullopt;
}

}  // namespace

std::size_t msh_element_nodes(long long type) {
  static const std::size_t nodes[] = {0, 2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, 20, 15, 13};
  return type >= 0 && type < static_cast<long long>(std::size(nodes)) ? nodes[type] : 0;
}

std::optional<std::string> check_msh_counts(const std::string& path) {
  MshLines lines(path);
  std::vector<std::string> t;
  int major = 0;
  bool v41 = false;
  long long max_node_tag = std::numeric_limits<int>::max();  // until $Nodes says
  while (lines.next(t)) {
    if (!is_marker(t)) continue;
    if (t[0] == "$MeshFormat") {
      if (!lines.next(t) || t.size() != 3)
        return fmt::format("{}: line {}: expected 'version file-type data-size'", path, lines.line());
      major = std::atoi(t[0].c_str());
      v41 = t[0] == "4.1";
    } else if ((t[0] == "$Nodes" || t[0] == "$Elements") && (major == 2 || v41)) {
      const bool nodes = t[0] == "$Nodes";
      auto problem = major == 2 ? check_v2_section(lines, path, nodes)
                     : nodes    ? check_v4_nodes(lines, path, max_node_tag)
                                : check_v4_elements(lines, path, max_node_tag);
      if (problem) return problem;
    }
  }
  return std::nullopt;
}

}  // namespace qm::io
