#include "tools/compare/gmsh_version.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <tuple>

namespace qm::tools {

namespace {

/// The digits at `at` as a number (at most 6 of them), advancing `at`; -1 if none.
int number_at(const std::string& text, std::size_t& at) {
  int value = 0, digits = 0;
  while (at < text.size() && std::isdigit(static_cast<unsigned char>(text[at])) && digits < 6) {
    value = 10 * value + (text[at] - '0');
    ++at;
    ++digits;
  }
  return digits > 0 ? value : -1;
}

}  // namespace

std::optional<GmshVersion> parse_gmsh_version(const std::string& text) {
  std::size_t at = 0;
  GmshVersion v;
  v.major = number_at(text, at);
  if (v.major < 0 || at >= text.size() || text[at] != '.') return std::nullopt;
  ++at;
  v.minor = number_at(text, at);
  if (v.minor < 0) return std::nullopt;
  if (at < text.size() && text[at] == '.') {
    ++at;
    v.patch = std::max(0, number_at(text, at));
  }
  return v;
}

bool at_least(const GmshVersion& a, const GmshVersion& b) {
  return std::tie(a.major, a.minor, a.patch) >= std::tie(b.major, b.minor, b.patch);
}

std::string quasi_structured_missing(const std::string& version_text) {
  const auto version = parse_gmsh_version(version_text);
  const std::string since = fmt::format("{}.{}", kQuasiStructuredSince.major, kQuasiStructuredSince.minor);
  if (!version)
    return fmt::format(
        "the Gmsh program did not tell its version (gmsh --version: \"{}\"), and the quasi-structured quad "
        "mesher (Mesh.Algorithm = 11) needs Gmsh {} or later; give such a Gmsh with --gmsh",
        version_text.substr(0, 40), since);
  if (at_least(*version, kQuasiStructuredSince)) return "";
  return fmt::format(
      "Gmsh {} lacks the quasi-structured quad mesher (Mesh.Algorithm = 11 came with Gmsh {}); give a newer "
      "Gmsh with --gmsh",
      version_text, since);
}

}  // namespace qm::tools
