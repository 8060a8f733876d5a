// A breadth-first spanning tree of a mesh's vertices (the primal tree of a
// tree-cotree decomposition, method.md section 2).
#pragma once

#include "libquadmesh/core/mesh.h"

#include <vector>

namespace qm {

struct VertexTree {
  std::vector<int> parent;      ///< parent vertex, -1 at the root (vertex 0)
  std::vector<int> depth;       ///< edges to the root
  std::vector<char> edge_used;  ///< per edge: in the tree
};

/// Breadth-first from vertex 0. Precondition: the mesh is connected.
VertexTree vertex_spanning_tree(const Mesh& mesh);

}  // namespace qm
