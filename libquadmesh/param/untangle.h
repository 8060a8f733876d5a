// Local untangling of a seamless parameterization (method.md section 9:
// "flipped triangles ... must not produce broken output: detect, repair").
//
// Every free vertex of a triangle whose image is not positively oriented is moved
// to the centroid of the kernel of its star (the points from which all the link
// edges are seen counter-clockwise: every triangle around it is then positive),
// sweep after sweep while folds remain. A move shifts all of a
// vertex's chart copies by the same vector, so the transitions across cuts stay
// integer translations; boundary vertices move only along the boundary (U), and
// cones (lattice points) do not move; their stars move last.
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

namespace qm {

struct UntangleReport {
  std::size_t flipped_before = 0;
  std::size_t flipped_after = 0;
  std::size_t moved_vertices = 0;  ///< size of the last region
  int rounds = 0;
};

/// `pinned[v]`: 1 v never moves (the cones), 2 v moves only when the others could
/// not untangle (the cones' model stars), 0 free. Modifies `param` in place.
UntangleReport untangle(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                        const std::vector<char>& pinned);

/// Triangles whose image area is <= 0.
std::size_t count_flipped(const FaceMap& param);

/// The report of an untangling that has not moved anything yet: the flipped
/// triangles of `param`, before and (so far) after.
UntangleReport unmoved_report(const FaceMap& param);

}  // namespace qm
