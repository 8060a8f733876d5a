// A small quad mesh of the rectangle [0, 2] x [0, 1] with its four sides as line
// groups, linear or quadratic, flat or bent onto a cylinder: what the deck tests
// write.
#pragma once

#include "io/write_mesh.h"

namespace qm::test {

struct RectangleDeckOptions {
  int nx = 4, ny = 2;        ///< quads along x and y
  bool quadratic = false;    ///< 8-node quads (straight edges: nodes at the midpoints)
  bool clockwise = false;    ///< faces listed clockwise seen from +z
  double bend_radius = 0;    ///< > 0: x wrapped onto a cylinder of this radius (a shell)
  double distortion = 0.15;  ///< interior points moved by up to this fraction of a cell
};

/// The mesh, with groups "left" (x = 0), "right" (x = 2), "bottom", "top".
io::OutputMesh rectangle_deck_mesh(const RectangleDeckOptions& options);

}  // namespace qm::test
