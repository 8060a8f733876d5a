// File formats by extension, and which of them can be read and written.
#pragma once

#include <string>

namespace qm::io {

enum class Format {
  unknown,
  obj, off, ply,          // CGAL IO
  stl, msh,               // Gmsh SDK (discrete meshes)
  geo, step, brep, iges,  // Gmsh SDK (CAD, triangulated by Gmsh)
  vtk, inp, bdf, unv, medit, su2,  // written by Gmsh
};

/// The format named by a path's extension (case-insensitive): .stp is step,
/// .igs is iges, .mesh is Medit, .msh is Gmsh MSH.
Format format_of(const std::string& path);

bool is_readable(Format f);
bool is_writable(Format f);
bool is_cad(Format f);  ///< geo, step, brep, iges: Gmsh generates the triangulation
bool is_deck(Format f);  ///< inp, bdf, unv: solver decks (io/write_deck.h)
/// The most nodes a quad may have in the format: 9 in .msh and .vtk, 8 in the
/// solver decks (CalculiX, Nastran and I-DEAS have no 9-node quad in common use),
/// 4 elsewhere (no quadratic elements).
int max_quad_nodes(Format f);

/// "obj off ply stl msh geo step stp brep iges igs" and the like, for messages.
std::string readable_extensions();
std::string writable_extensions();

}  // namespace qm::io
