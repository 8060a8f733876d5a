#include "io/write_deck.h"

#include "libquadmesh/core/error.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <fstream>

namespace qm::io {

namespace {

const char* kind_words(ElementKind k) {
  return k == ElementKind::plane_stress ? "plane stress" : k == ElementKind::plane_strain ? "plane strain" : "shell";
}

/// ids, `per_line` to a line, comma separated
void write_id_lines(std::ostream& out, const std::vector<int>& ids, std::size_t per_line) {
  for (std::size_t i = 0; i < ids.size(); ++i)
    out << ids[i] << (i + 1 == ids.size() || (i + 1) % per_line == 0 ? "\n" : ", ");
}

/// A real in 16 characters (Nastran large field).
std::string large_field(double x) { return fmt::format("{:16.9E}", x); }

/// A Nastran small-field entry: the name, then the fields, 8 to a line, each
/// continuation line starting with a blank field.
void write_small_entry(std::ostream& out, const std::string& name, const std::vector<int>& fields) {
  out << fmt::format("{:<8}", name);
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0 && i % 8 == 0) out << "\n        ";
    out << fmt::format("{:>8}", fields[i]);
  }
  out << '\n';
}

}  // namespace

void write_inp(std::ostream& out, const DeckMesh& deck) {
  const bool shell = deck.element.kind == ElementKind::shell;
  std::size_t triangles = 0;
  for (const auto& e : deck.elements) triangles += e.size() == 3;
  out << fmt::format("** quadmesh: {} nodes, {} {} elements{} ({})\n", deck.nodes.size(),
                     deck.elements.size() - triangles, deck.element.name,
                     triangles ? fmt::format(" and {} {}", triangles, deck.triangle.name) : std::string(),
                     kind_words(deck.element.kind));
  out << fmt::format("** element set {}; per boundary group a node set and an element-edge surface of the same name:",
                     deck.element_set);
  for (const DeckSet& s : deck.sets) out << ' ' << s.name;
  out << "\n** add a material, a section (*" << (shell ? "SHELL" : "SOLID") << " SECTION, ELSET=" << deck.element_set
      << ", MATERIAL=...) and a step\n";
  out << "*NODE, NSET=NALL\n";
  for (std::size_t k = 0; k < deck.nodes.size(); ++k) {
    const Vec3& p = deck.nodes[k];
    out << fmt::format("{}, {:.17g}, {:.17g}, {:.17g}\n", k + 1, p.x(), p.y(), p.z());
  }
  for (const DeckElement* type : {&deck.element, &deck.triangle}) {
    bool header = false;
    for (std::size_t e = 0; e < deck.elements.size(); ++e) {
      if (static_cast<int>(deck.elements[e].size()) != type->nodes) continue;
      if (!header) out << fmt::format("*ELEMENT, TYPE={}, ELSET={}\n", type->name, deck.element_set);
      header = true;
      out << e + 1;
      for (int v : deck.elements[e]) out << ", " << v;
      out << '\n';
    }
  }
  for (const DeckSet& s : deck.sets) {
    out << fmt::format("*NSET, NSET={}\n", s.name);
    write_id_lines(out, s.nodes, 16);
    if (s.sides.empty()) continue;
    out << fmt::format("*SURFACE, NAME={}, TYPE=ELEMENT\n", s.name);
    for (const auto& [element, side] : s.sides) out << fmt::format("{}, S{}\n", element, side + (shell ? 3 : 1));
  }
}

void write_bdf(std::ostream& out, const DeckMesh& deck) {
  out << fmt::format("$ quadmesh: {} nodes, {} {} elements (PID 1: add a PSHELL 1 and its MAT1), bulk data to "
                     "INCLUDE after BEGIN BULK\n",
                     deck.nodes.size(), deck.elements.size(), deck.element.name);
  for (std::size_t k = 0; k < deck.nodes.size(); ++k) {
    const Vec3& p = deck.nodes[k];
    out << fmt::format("GRID*   {:>16}{:>16}{}{}\n*       {}\n", k + 1, "", large_field(p.x()), large_field(p.y()),
                       large_field(p.z()));
  }
  for (std::size_t e = 0; e < deck.elements.size(); ++e) {
    std::vector<int> fields{static_cast<int>(e + 1), 1};
    fields.insert(fields.end(), deck.elements[e].begin(), deck.elements[e].end());
    write_small_entry(out, deck.elements[e].size() == 3 ? deck.triangle.name : deck.element.name, fields);
  }
  for (std::size_t i = 0; i < deck.sets.size(); ++i) {
    out << fmt::format("$ node set {}: SET1 {}\n", deck.sets[i].name, i + 1);
    std::vector<int> fields{static_cast<int>(i + 1)};
    fields.insert(fields.end(), deck.sets[i].nodes.begin(), deck.sets[i].nodes.end());
    write_small_entry(out, "SET1", fields);
  }
}

void write_unv(std::ostream& out, const DeckMesh& deck) {
  const auto separator = [&] { out << "    -1\n"; };
  separator();
  out << "  2411\n";
  for (std::size_t k = 0; k < deck.nodes.size(); ++k) {
    const Vec3& p = deck.nodes[k];
    out << fmt::format("{:10}{:10}{:10}{:10}\n{:25.16E}{:25.16E}{:25.16E}\n", k + 1, 1, 1, 11, p.x(), p.y(), p.z());
  }
  separator();
  separator();
  out << "  2412\n";
  for (std::size_t e = 0; e < deck.elements.size(); ++e) {
    const std::vector<int>& v = deck.elements[e];
    std::vector<int> nodes = v;
    if (v.size() == 8) nodes = {v[0], v[4], v[1], v[5], v[2], v[6], v[3], v[7]};
    const std::string& type = v.size() == 3 ? deck.triangle.name : deck.element.name;
    out << fmt::format("{:10}{:>10}{:10}{:10}{:10}{:10}\n", e + 1, type, 1, 1, 7, nodes.size());
    for (std::size_t i = 0; i < nodes.size(); ++i)
      out << fmt::format("{:10}", nodes[i]) << (i + 1 == nodes.size() || (i + 1) % 8 == 0 ? "\n" : "");
  }
  separator();
  separator();
  out << "  2467\n";
  const auto group = [&](std::size_t number, const std::string& name, int code, const std::vector<int>& ids) {
    out << fmt::format("{:10}{:10}{:10}{:10}{:10}{:10}{:10}{:10}\n{}\n", number, 0, 0, 0, 0, 0, 0, ids.size(), name);
    for (std::size_t i = 0; i < ids.size(); ++i)
      out << fmt::format("{:10}{:10}{:10}{:10}", code, ids[i], 0, 0) << (i % 2 == 1 || i + 1 == ids.size() ? "\n" : "");
  };
  for (std::size_t i = 0; i < deck.sets.size(); ++i) group(i + 1, deck.sets[i].name, 7, deck.sets[i].nodes);
  std::vector<int> all(deck.elements.size());
  for (std::size_t e = 0; e < all.size(); ++e) all[e] = static_cast<int>(e + 1);
  group(deck.sets.size() + 1, deck.element_set, 8, all);
  separator();
}

void write_deck(const std::string& path, Format format, const OutputMesh& mesh, const std::string& element_type) {
  const DeckMesh deck = deck_mesh(mesh, format, element_type);
  std::ofstream out(path);
  if (format == Format::inp)
    write_inp(out, deck);
  else if (format == Format::bdf)
    write_bdf(out, deck);
  else
    write_unv(out, deck);
  out.close();
  if (!out) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the deck", path));
}

}  // namespace qm::io
