// Harmonic representatives of closed edge 1-forms (method.md section 4, seed paper
// Alg. 4.4, eq. 4.3).
//
// omega = eta + d0 f with f minimizing the cotangent-weighted norm of omega:
// L f = -d0^T W eta. L is singular on the constants, so vertex 0 is pinned
// (f_0 = 0): the reduced matrix is positive definite and factored once by CHOLMOD;
// every right-hand side is a back-solve.
#pragma once

#include "libquadmesh/forms/cotan_laplacian.h"

#include <memory>

namespace qm {

/// A factored cotangent Laplacian (vertex 0 pinned), reused for many solves.
class HarmonicSolver {
 public:
  /// Throws qm::Error(solver) when the factorization fails (the weighted graph
  /// must be connected and the reduced Laplacian positive definite).
  HarmonicSolver(const Mesh& mesh, const Eigen::VectorXd& weights);
  ~HarmonicSolver();

  /// The harmonic forms cohomologous to the columns of eta (|E| x k).
  Eigen::MatrixXd harmonic(const Eigen::MatrixXd& eta) const;

  /// max over vertices and columns of |d0^T W omega| relative to the largest
  /// |W omega| (co-closedness of harmonic forms).
  double coclosedness(const Eigen::MatrixXd& omega) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace qm
