#include "tools/quadmesh/library_wording.h"

#include <fmt/format.h>

#include <regex>
#include <utility>

namespace qm::tools {

namespace {

/// Library names (qm::Error::option()) and the flags that set them.
const std::pair<const char*, const char*> kFlags[] = {
    {"QuadMeshOptions::coefficients", "--coeffs"},
    {"QuadMeshOptions::form", "--form"},
    {"QuadMeshOptions::size_relative", "--size"},
    {"QuadMeshOptions::size", "--size"},
    {"QuadMeshOptions::quads", "--quads"},
    {"QuadMeshOptions::max_quads", "--max-quads"},
    {"QuadMeshOptions::tip_angle_deg", "--tip-angle"},
    {"QuadMeshOptions::max_deviation_relative", "--max-deviation"},
    {"QuadMeshOptions::max_deviation", "--max-deviation"},
    {"QuadMeshOptions::remesh_size", "--remesh-size"},
    {"QuadMeshOptions::rotate", "--rotate"},
    {"largest_component()", "--largest-component"},
    {"CadSandbox::timeout_seconds", "--cad-timeout"},
    {"CadSandbox::memory_gib", "--cad-memory"},
    {"CadSandbox::allow_geo_commands", "--allow-geo-commands"},
};

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
}

}  // namespace

std::string command_line_wording(const std::string& message) {
  std::string text = message;
  // the forms as the command line counts them, from 1
  static const std::regex form_range(R"(QuadMeshOptions::form = (\d+)(.*)\(0 to (\d+)\))");
  static const std::regex form_index(R"(QuadMeshOptions::form = (\d+))");
  try {
    std::smatch m;
    if (std::regex_search(text, m, form_range))
      text = m.prefix().str() +
             fmt::format("--form {}{}(1 to {})", std::stoll(m[1]) + 1, m[2].str(), std::stoll(m[3]) + 1) +
             m.suffix().str();
    else if (std::regex_search(text, m, form_index))
      text = m.prefix().str() + fmt::format("--form {}", std::stoll(m[1]) + 1) + m.suffix().str();
  } catch (const std::exception&) {  // a number out of range: the field's name is still replaced below
  }
  for (const auto& [name, flag] : kFlags) replace_all(text, name, flag);
  return text;
}

}  // namespace qm::tools
