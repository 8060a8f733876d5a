// The named loops of method.md section 2 on the input surface S: boundary loops
// alpha_k, bridge paths beta_k (shortest paths from boundary 0 to boundary k) and
// 2g handle generators. For display (the seed paper's figures) and, later, for
// the quantization constraints of section 7.
#pragma once

#include "libquadmesh/core/mesh.h"

#include <vector>

namespace qm {

struct NamedLoops {
  std::vector<std::vector<int>> boundaries;  ///< closed, in border order
  std::vector<std::vector<int>> bridges;     ///< open: from boundary 0 to boundary k (k >= 1)
  std::vector<std::vector<int>> handles;     ///< closed: 2g generators of the capped surface
};

/// Boundary loops follow the border halfedges (boundary 0 is the one holding the
/// lowest-index border halfedge). Bridges are Dijkstra shortest paths by edge length
/// from all of boundary 0. Handles come from a tree-cotree decomposition of S with
/// every hole capped by a virtual face, so exactly 2g edges close a loop each.
/// Precondition: S connected and manifold.
NamedLoops named_loops(const Mesh& surface);

}  // namespace qm
