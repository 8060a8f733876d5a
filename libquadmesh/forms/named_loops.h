// The named loops of method.md section 2 on the input surface S: boundary loops
// alpha_k, bridge paths beta_k (shortest paths from boundary 0 to boundary k) and
// 2g handle generators. For display (the seed paper's figures) and for the
// quantization constraints of section 7 (quantization.h rounds their periods).
#pragma once

#include "libquadmesh/core/mesh.h"

#include <vector>

namespace qm {

/// Loops as vertex sequences on S.
struct NamedLoops {
  std::vector<std::vector<int>> boundaries;  ///< closed, in border order; boundary 0 is the reference
  std::vector<std::vector<int>> bridges;     ///< open: bridges[k - 1] from boundary 0 to boundary k (k >= 1)
  std::vector<std::vector<int>> handles;     ///< closed: 2g generators of the capped surface
};

/// Boundary loops follow the border halfedges (boundary 0 is the one holding the
/// lowest-index border halfedge). Bridges are Dijkstra shortest paths by edge length
/// from all of boundary 0. Handles come from a tree-cotree decomposition of S with
/// every hole capped by a virtual face, so exactly 2g edges close a loop each.
/// Precondition: S connected and manifold.
NamedLoops named_loops(const Mesh& surface);

/// Per vertex (vertex_count of them), the index in loops.boundaries of the
/// boundary loop it lies on, or -1: the named loops' numbering, which the
/// quantization's boundary levels and the output's boundary groups follow
/// (SurfaceAdjacency::loop_of_vertex numbers the same loops in its own order).
/// Precondition: every loop vertex is < vertex_count.
std::vector<int> boundary_loop_of_vertex(const NamedLoops& loops, std::size_t vertex_count);

}  // namespace qm
