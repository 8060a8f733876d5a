// Cotangent weights and the cotangent Laplacian (method.md section 4).
//
// w_e = (cot a + cot b) / 2 with a, b the angles opposite edge e (one angle on a
// border edge). L = d0^T W d0 is symmetric positive semi-definite, its kernel the
// constants, every row summing to zero: (L f)_i = sum_j w_ij (f_i - f_j).
#pragma once

#include "libquadmesh/core/mesh.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace qm {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Per-edge cotangent weights, indexed by edge index.
Eigen::VectorXd cotan_weights(const Mesh& mesh);

/// The coboundary d0 (|E| x |V|): (d0 f)(e) = f(target) - f(source) of halfedge(e, 0).
SparseMatrix exterior_derivative_0(const Mesh& mesh);

/// L = d0^T diag(w) d0 (|V| x |V|).
SparseMatrix cotan_laplacian(const Mesh& mesh, const Eigen::VectorXd& weights);

}  // namespace qm
