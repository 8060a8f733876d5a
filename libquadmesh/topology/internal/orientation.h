// Orientability and a consistent orientation of a triangle soup.
//
// Two triangles on a manifold edge are consistently oriented when they run
// through that edge in opposite directions. A breadth-first search over
// manifold edges assigns each triangle a flip bit; meeting a contradiction means
// the component is non-orientable (a Möbius strip, say).
#pragma once

#include "libquadmesh/topology/internal/edge_incidence.h"

#include <vector>

namespace qm {

struct OrientationResult {
  bool orientable = true;
  bool consistent = true;            ///< the input orientation needs no flip
  int contradicting_edge = -1;       ///< where orientability failed (edge id), if it did
  std::vector<char> flip;            ///< per triangle: reverse it to orient consistently
  std::size_t flip_count = 0;        ///< triangles to reverse (the minority of each patch)
};

/// Finds a consistent orientation per edge-connected patch, flipping the
/// minority of each patch so that the input's orientation wins.
OrientationResult orient_consistently(const TriangleSoup& soup, const EdgeIncidence& inc);

/// Reverses the triangles marked in flip (swaps their second and third corner).
void apply_orientation(TriangleSoup& soup, const std::vector<char>& flip);

}  // namespace qm
