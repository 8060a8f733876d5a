// The element type a solver deck gives the quads: which names each deck format
// takes, and the default from the geometry (README "Solver decks").
#pragma once

#include "io/file_format.h"
#include "libquadmesh/core/triangle_soup.h"

#include <string>
#include <vector>

namespace qm::io {

enum class ElementKind { plane_stress, plane_strain, shell };

struct DeckElement {
  std::string name;  ///< as the deck writes it: "CPS8", "CQUAD4", "94" (an I-DEAS FE descriptor)
  ElementKind kind = ElementKind::shell;
  int nodes = 4;  ///< 3, 4 or 8
};

/// The element of `format` (.inp .bdf .unv) for quads of `nodes` nodes, by name
/// (case-insensitive): the format's own names (.inp: CPS4 CPS4R CPE4 CPE4R S4 S4R,
/// CPS8 CPS8R CPE8 CPE8R S8 S8R; .bdf: CQUAD4, CQUAD8; .unv: FE descriptors 44 54
/// 94, 45 55 95) or the generic plane-stress, plane-strain, shell. An empty name
/// gives plane stress when `in_xy_plane`, else shell. Throws qm::Error(bad_input),
/// one line, for a name the format or the node count does not take, or a plane
/// element for a part that is not in the z = 0 plane (CalculiX and Abaqus read
/// plane elements there only).
DeckElement deck_element(Format format, int nodes, const std::string& name, bool in_xy_plane);

/// The 3-node triangle of `format` of that kind (CPS3, S3, CTRIA3, 91, ...): the
/// elements of a triangle mesh written as a deck.
DeckElement triangle_element(Format format, ElementKind kind);

/// The checks of deck_element that need no mesh, for the command line before any
/// work: the format holds quads of `nodes` nodes, and `name` (when not empty) is
/// one of its element types for them. Throws qm::Error(bad_input), one line,
/// naming `path` and the problem.
void check_element_request(const std::string& path, int nodes, const std::string& name);

/// z = 0 within 1e-9 of the largest coordinate (or exactly, for a mesh at the origin).
bool lies_in_xy_plane(const std::vector<Vec3>& points);

}  // namespace qm::io
