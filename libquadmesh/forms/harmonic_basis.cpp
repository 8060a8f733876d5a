#include "libquadmesh/forms/harmonic_basis.h"

#include "libquadmesh/core/error.h"

#include <Eigen/CholmodSupport>

namespace qm {

struct HarmonicSolver::Impl {
  SparseMatrix d0;
  Eigen::VectorXd weights;
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> cholesky;
};

HarmonicSolver::HarmonicSolver(const Mesh& mesh, const Eigen::VectorXd& weights)
    : impl_(std::make_unique<Impl>()) {
  impl_->d0 = exterior_derivative_0(mesh);
  impl_->weights = weights;
  const SparseMatrix L = cotan_laplacian(mesh, weights);
  const Eigen::Index n = L.rows();
  const SparseMatrix reduced = L.bottomRightCorner(n - 1, n - 1);  // vertex 0 pinned
  impl_->cholesky.compute(reduced);
  if (impl_->cholesky.info() != Eigen::Success)
    throw Error(ErrorCode::solver,
                "the cotangent Laplacian could not be factored (not positive definite once a "
                "vertex is pinned: degenerate triangles?)");
}

HarmonicSolver::~HarmonicSolver() = default;

Eigen::MatrixXd HarmonicSolver::harmonic(const Eigen::MatrixXd& eta) const {
  const Eigen::MatrixXd rhs = -(impl_->d0.transpose() * (impl_->weights.asDiagonal() * eta));
  const Eigen::Index n = rhs.rows();
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(n, eta.cols());
  f.bottomRows(n - 1) = impl_->cholesky.solve(rhs.bottomRows(n - 1));
  if (impl_->cholesky.info() != Eigen::Success)
    throw Error(ErrorCode::solver, "back-substitution with the cotangent Laplacian failed");
  return eta + impl_->d0 * f;
}

double HarmonicSolver::coclosedness(const Eigen::MatrixXd& omega) const {
  const Eigen::MatrixXd flux = impl_->weights.asDiagonal() * omega;
  const double scale = flux.cwiseAbs().maxCoeff();
  if (scale == 0) return 0;
  return (impl_->d0.transpose() * flux).cwiseAbs().maxCoeff() / scale;
}

}  // namespace qm
