// What a solver deck holds, prepared once for the three deck writers: nodes
// numbered compactly, the 2D elements only (oriented for the element type), each
// group as a node set and as the element sides along it.
#pragma once

#include "io/deck_element.h"
#include "io/write_mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace qm::io {

struct DeckSet {
  std::string name;                      ///< the group's name made a solver name (deck_name)
  std::vector<int> nodes;                ///< deck node ids (from 1), increasing
  std::vector<std::pair<int, int>> sides;  ///< (deck element id from 1, side s: the edge from corner s to the next)
};

struct DeckMesh {
  DeckElement element;           ///< of the quads
  DeckElement triangle;          ///< of the triangles (a triangle mesh), of the same kind
  std::vector<Vec3> nodes;                   ///< node id k + 1 is nodes[k]
  /// deck node ids, 3, 4 or 8 per element, in the Gmsh / Abaqus order; element id k + 1
  std::vector<std::vector<int>> elements;
  std::vector<DeckSet> sets;                 ///< one per line group, then per point group
  std::string element_set;                   ///< the surface group's name (deck_name)
};

/// A name every deck takes: letters, digits and '_' (others become '_'), starting
/// with a letter (else "G" is put first), at most 80 characters.
std::string deck_name(const std::string& name);

/// The deck of `mesh` (triangles and quads of 4 nodes, or quads of 8; lines and
/// points are not elements of a deck). Nodes that no face uses are left out and the
/// others numbered from 1 in their order; plane elements are turned
/// counter-clockwise seen from +z (solvers reject a negative area). Throws
/// qm::Error(bad_input) as deck_element does, or for faces of other node counts.
DeckMesh deck_mesh(const OutputMesh& mesh, Format format, const std::string& element_type);

}  // namespace qm::io
