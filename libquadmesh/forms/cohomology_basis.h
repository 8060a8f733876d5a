// A basis of closed, non-exact edge 1-forms by tree-cotree decomposition
// (method.md sections 2-3, seed paper Alg. 4.3; [Eppstein 2003]).
//
// A spanning tree T of the vertices (breadth-first) and a spanning tree C of the
// faces crossing no edge of T leave exactly 2G edges, the generators. For each
// generator g, eta_g is 1 on g, 0 on T and on the other generators, and on the
// edges crossed by C it is fixed by closedness, peeling C from its leaves. Then
// d(eta_g) = 0 on every face and the 2G classes are independent.
#pragma once

#include "libquadmesh/core/mesh.h"

#include <Eigen/Core>

#include <vector>

namespace qm {

struct CohomologyBasis {
  std::vector<int> generator_edges;  ///< the 2G edges in neither tree
  Eigen::MatrixXd forms;             ///< |E| x 2G, values along halfedge(e, 0)
};

/// Precondition: `mesh` is closed and connected.
CohomologyBasis cohomology_basis(const Mesh& mesh);

/// max over faces of |sum of the oriented edge values| for each column (closedness).
double max_face_curl(const Mesh& mesh, const Eigen::MatrixXd& forms);

}  // namespace qm
