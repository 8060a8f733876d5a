#include "io/file_format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace qm::io {

Format format_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".obj") return Format::obj;
  if (ext == ".off") return Format::off;
  if (ext == ".ply") return Format::ply;
  if (ext == ".stl") return Format::stl;
  if (ext == ".msh") return Format::msh;
  if (ext == ".geo") return Format::geo;
  if (ext == ".step" || ext == ".stp") return Format::step;
  if (ext == ".brep") return Format::brep;
  if (ext == ".iges" || ext == ".igs") return Format::iges;
  if (ext == ".vtk") return Format::vtk;
  if (ext == ".inp") return Format::inp;
  if (ext == ".bdf" || ext == ".nas") return Format::bdf;
  if (ext == ".unv") return Format::unv;
  if (ext == ".mesh") return Format::medit;
  if (ext == ".su2") return Format::su2;
  return Format::unknown;
}

bool is_cad(Format f) {
  return f == Format::geo || f == Format::step || f == Format::brep || f == Format::iges;
}

bool is_deck(Format f) { return f == Format::inp || f == Format::bdf || f == Format::unv; }

int max_quad_nodes(Format f) {
  if (f == Format::msh || f == Format::vtk) return 9;
  return is_deck(f) ? 8 : 4;
}

bool is_readable(Format f) {
  switch (f) {
    case Format::obj: case Format::off: case Format::ply: case Format::stl: case Format::msh:
    case Format::geo: case Format::step: case Format::brep: case Format::iges:
    case Format::vtk: case Format::bdf: case Format::unv: case Format::medit:
      return true;
    default:
      return false;
  }
}

bool is_writable(Format f) {
  switch (f) {
    case Format::obj: case Format::off: case Format::ply: case Format::msh: case Format::vtk:
    case Format::inp: case Format::bdf: case Format::unv: case Format::medit: case Format::su2:
      return true;
    default:
      return false;
  }
}

std::string readable_extensions() {
  return ".obj .off .ply .stl .msh .geo .step/.stp .brep .iges/.igs .vtk .bdf .unv .mesh";
}
std::string writable_extensions() { return ".msh .vtk .inp .bdf .unv .mesh .su2 .obj .off .ply"; }

}  // namespace qm::io
