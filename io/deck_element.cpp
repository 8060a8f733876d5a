#include "io/deck_element.h"

#include "libquadmesh/core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace qm::io {

namespace {

struct Entry {
  Format format;
  const char* name;
  ElementKind kind;
  int nodes;
};

/// Every element type a deck takes; the first of each (format, kind, nodes) is the
/// one the generic names give.
constexpr std::array<Entry, 29> entries{{
    {Format::inp, "CPS4", ElementKind::plane_stress, 4},  {Format::inp, "CPS4R", ElementKind::plane_stress, 4},
    {Format::inp, "CPE4", ElementKind::plane_strain, 4},  {Format::inp, "CPE4R", ElementKind::plane_strain, 4},
    {Format::inp, "S4", ElementKind::shell, 4},           {Format::inp, "S4R", ElementKind::shell, 4},
    {Format::inp, "CPS8", ElementKind::plane_stress, 8},  {Format::inp, "CPS8R", ElementKind::plane_stress, 8},
    {Format::inp, "CPE8", ElementKind::plane_strain, 8},  {Format::inp, "CPE8R", ElementKind::plane_strain, 8},
    {Format::inp, "S8R", ElementKind::shell, 8},          {Format::inp, "S8", ElementKind::shell, 8},
    {Format::bdf, "CQUAD4", ElementKind::shell, 4},       {Format::bdf, "CQUAD8", ElementKind::shell, 8},
    {Format::unv, "44", ElementKind::plane_stress, 4},    {Format::unv, "54", ElementKind::plane_strain, 4},
    {Format::unv, "94", ElementKind::shell, 4},           {Format::unv, "45", ElementKind::plane_stress, 8},
    {Format::unv, "55", ElementKind::plane_strain, 8},    {Format::unv, "95", ElementKind::shell, 8},
    // Nastran's CQUAD4/CQUAD8 are plane or shell by their property (PSHELL): the same card
    {Format::bdf, "CQUAD4", ElementKind::plane_stress, 4}, {Format::bdf, "CQUAD8", ElementKind::plane_stress, 8},
    // triangles (a triangle mesh written as a deck): the kind the quads would get
    {Format::inp, "CPS3", ElementKind::plane_stress, 3},  {Format::inp, "CPE3", ElementKind::plane_strain, 3},
    {Format::inp, "S3", ElementKind::shell, 3},           {Format::bdf, "CTRIA3", ElementKind::shell, 3},
    {Format::unv, "41", ElementKind::plane_stress, 3},    {Format::unv, "51", ElementKind::plane_strain, 3},
    {Format::unv, "91", ElementKind::shell, 3},
}};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string extension(Format f) { return f == Format::inp ? ".inp" : f == Format::bdf ? ".bdf" : ".unv"; }

/// "CPS4 CPS4R ..." : the names of `format` for `nodes` nodes.
std::string names_for(Format format, int nodes) {
  std::vector<std::string> names;
  for (const Entry& e : entries)
    if (e.format == format && e.nodes == nodes && std::find(names.begin(), names.end(), e.name) == names.end())
      names.emplace_back(e.name);
  std::string out;
  for (const std::string& n : names) out += n + " ";
  return out + "plane-stress plane-strain shell";
}

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::bad_input, message); }

/// The entry `name` asks for, or nullptr for an unknown name (generic names: the
/// first entry of their kind).
const Entry* find_entry(Format format, int nodes, const std::string& name) {
  const std::string n = upper(name);
  const bool generic = n == "PLANE-STRESS" || n == "PLANE-STRAIN" || n == "SHELL";
  const ElementKind kind = n == "PLANE-STRESS"   ? ElementKind::plane_stress
                           : n == "PLANE-STRAIN" ? ElementKind::plane_strain
                                                 : ElementKind::shell;
  for (const Entry& e : entries)
    if (e.format == format && e.nodes == nodes && (generic ? e.kind == kind : n == e.name)) return &e;
  return nullptr;
}

void check_nodes(const std::string& path, Format format, int nodes) {
  if (nodes <= 4) return;
  if (max_quad_nodes(format) < nodes)
    fail(fmt::format("{}: {} cannot hold {}-node quads ({}); write .msh or .vtk{}", path,
                     std::filesystem::path(path).extension().string(), nodes,
                     nodes == 9 ? "--complete" : "--order 2",
                     nodes == 9 ? ", or drop --complete for 8-node quads" : ", .inp, .bdf or .unv"));
}

}  // namespace

void check_element_request(const std::string& path, int nodes, const std::string& name) {
  const Format format = format_of(path);
  check_nodes(path, format, nodes);
  if (name.empty()) return;
  if (!is_deck(format))
    fail(fmt::format("--element-type {}: {} is not a solver deck; element types apply to .inp, .bdf and .unv", name,
                     path));
  if (!find_entry(format, nodes, name))
    fail(fmt::format("--element-type {} does not fit {}-node quads in {} (it takes: {})", name, nodes,
                     extension(format), names_for(format, nodes)));
}

DeckElement deck_element(Format format, int nodes, const std::string& name, bool in_xy_plane) {
  const std::string asked = name.empty() ? (in_xy_plane ? "plane-stress" : "shell") : name;
  const Entry* e = find_entry(format, nodes, asked);
  if (!e)
    fail(fmt::format("--element-type {} does not fit {}-node quads in {} (it takes: {})", asked, nodes,
                     extension(format), names_for(format, nodes)));
  if (e->kind != ElementKind::shell && !in_xy_plane && format != Format::bdf)
    fail(fmt::format("--element-type {}: a plane element, but the part does not lie in the z = 0 plane (where "
                     "solvers read plane elements); use a shell type",
                     asked));
  return {e->name, e->kind, e->nodes};
}

DeckElement triangle_element(Format format, ElementKind kind) {
  for (const Entry& e : entries)
    if (e.format == format && e.nodes == 3 && (e.kind == kind || format == Format::bdf)) return {e.name, kind, 3};
  throw AssertionError("every deck format has a triangle of each kind");
}

bool lies_in_xy_plane(const std::vector<Vec3>& points) {
  double extent = 0;
  for (const Vec3& p : points) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  const double tolerance = 1e-9 * extent;
  return std::all_of(points.begin(), points.end(), [&](const Vec3& p) { return std::abs(p.z()) <= tolerance; });
}

}  // namespace qm::io
