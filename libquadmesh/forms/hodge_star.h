// The Galerkin Hodge star on harmonic 1-forms (method.md section 5, seed paper
// Alg. 4.6, eqs. 4.6-4.8).
//
// A closed edge form is a constant covector u_f on each triangle f (in the plane
// of f, with u_f . (p_j - p_i) = omega(i -> j)). With n_f the unit normal,
//   A_ij = sum_f area_f (u_i x u_j) . n_f    (integral of omega_i ^ omega_j)
//   B_ij = sum_f area_f  u_i . u_j           (L2 inner product)
// and the star *omega_k = sum_j Lambda_jk omega_j solves A Lambda = B.
// Convention: *omega has covector n_f x u_f, so omega ^ *omega = |u|^2 dA > 0.
#pragma once

#include "libquadmesh/core/mesh.h"

#include <Eigen/Core>

namespace qm {

/// Per-face covectors of each form: result[k] is |F| x 3 for column k of forms.
std::vector<Eigen::MatrixX3d> face_covectors(const Mesh& mesh, const Eigen::MatrixXd& forms);

struct HodgeStar {
  Eigen::MatrixXd wedge;   ///< A (antisymmetric)
  Eigen::MatrixXd inner;   ///< B (symmetric positive definite)
  Eigen::MatrixXd lambda;  ///< Lambda = A^-1 B
  /// ||Lambda^2 + I||_F / ||I||_F: zero for the exact star; shrinks with refinement.
  double squared_residual = 0;
};

/// Precondition: forms (|E| x k) closed, k even, A invertible (a basis of harmonic forms).
HodgeStar galerkin_hodge_star(const Mesh& mesh, const Eigen::MatrixXd& forms);

}  // namespace qm
