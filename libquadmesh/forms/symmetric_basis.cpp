#include "libquadmesh/forms/symmetric_basis.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Dense>

namespace qm {

Eigen::MatrixXd pull_back(const DoubledSurface& d, const Eigen::MatrixXd& forms) {
  Eigen::MatrixXd out(forms.rows(), forms.cols());
  for (Eigen::Index e = 0; e < forms.rows(); ++e)
    out.row(e) = d.edge_mirror_sign[e] * forms.row(d.edge_mirror[e]);
  return out;
}

namespace {

/// Greedy choice, for a closed surface, of B-orthonormal forms c_1..c_G with
/// {c_i, Lambda c_i} independent: Gram-Schmidt on the unit vectors against the
/// span of what was chosen and its stars.
/// In the Gram-Schmidt of closed_surface_coefficients, a candidate whose
/// B-norm is below this after orthogonalization is dependent on the span; its
/// image under Lambda is added only above dependent_image_norm.
constexpr double dependent_norm = 1e-6;
constexpr double dependent_image_norm = 1e-9;
/// P, (I + M_o) / 2 symmetrized, projects onto the forms M_o leaves invariant: its
/// eigenvalues are 0 or 1 up to rounding; those above this are kept.
constexpr double invariant_eigenvalue = 0.5;

Eigen::MatrixXd closed_surface_coefficients(const HodgeStar& star) {
  const Eigen::Index n = star.inner.rows();
  const Eigen::MatrixXd& B = star.inner;
  std::vector<Eigen::VectorXd> span;
  Eigen::MatrixXd chosen(n, 0);
  auto orthogonalize = [&](Eigen::VectorXd v) {
    for (const auto& s : span) v -= (s.dot(B * v)) * s;
    return v;
  };
  for (Eigen::Index i = 0; i < n && chosen.cols() < n / 2; ++i) {
    Eigen::VectorXd v = orthogonalize(Eigen::VectorXd::Unit(n, i));
    const double norm = std::sqrt(v.dot(B * v));
    if (norm < dependent_norm) continue;
    v /= norm;
    span.push_back(v);
    Eigen::VectorXd w = orthogonalize(star.lambda * v);
    const double wn = std::sqrt(w.dot(B * w));
    if (wn > dependent_image_norm) span.push_back(w / wn);
    chosen.conservativeResize(n, chosen.cols() + 1);
    chosen.col(chosen.cols() - 1) = v;
  }
  return chosen;
}

}  // namespace

SymmetricBasis symmetric_basis(const DoubledSurface& d, const Eigen::MatrixXd& harmonic,
                               const HodgeStar& star, bool closed_surface) {
  const Eigen::Index n = harmonic.cols();
  SymmetricBasis basis;
  if (closed_surface) {
    basis.coefficients = closed_surface_coefficients(star);
    basis.invariance_spectrum = Eigen::VectorXd::Ones(n);
  } else {
    // phi* in harmonic coordinates (least squares: phi* omega_k is harmonic)
    const Eigen::MatrixXd pulled = pull_back(d, harmonic);
    const Eigen::MatrixXd M = harmonic.colPivHouseholderQr().solve(pulled);
    // B-orthonormal coordinates: B = R^T R, M' = R M R^-1 is orthogonal
    const Eigen::LLT<Eigen::MatrixXd> llt(star.inner);
    if (llt.info() != Eigen::Success)
      throw Error(ErrorCode::solver, "the L2 Gram matrix of the harmonic basis is not positive definite");
    const Eigen::MatrixXd R = llt.matrixU();
    const Eigen::MatrixXd Rinv = R.inverse();
    const Eigen::MatrixXd Mo = R * M * Rinv;
    const Eigen::MatrixXd P = 0.25 * (2 * Eigen::MatrixXd::Identity(n, n) + Mo + Mo.transpose());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(P);
    basis.invariance_spectrum = eig.eigenvalues();
    std::vector<Eigen::Index> keep;
    for (Eigen::Index i = 0; i < n; ++i)
      if (eig.eigenvalues()[i] > invariant_eigenvalue) keep.push_back(i);
    basis.coefficients.resize(n, static_cast<Eigen::Index>(keep.size()));
    for (std::size_t j = 0; j < keep.size(); ++j)
      basis.coefficients.col(static_cast<Eigen::Index>(j)) = Rinv * eig.eigenvectors().col(keep[j]);
  }
  basis.real_part = harmonic * basis.coefficients;
  basis.imaginary_part = harmonic * (star.lambda * basis.coefficients);
  return basis;
}

double symmetry_residual(const DoubledSurface& d, const SymmetricBasis& b) {
  const Eigen::MatrixXd re = pull_back(d, b.real_part) - b.real_part;
  const Eigen::MatrixXd im = pull_back(d, b.imaginary_part) + b.imaginary_part;
  const double scale = (b.real_part.cwiseAbs2() + b.imaginary_part.cwiseAbs2()).cwiseSqrt().maxCoeff();
  return (re.cwiseAbs2() + im.cwiseAbs2()).cwiseSqrt().maxCoeff() / scale;
}

double boundary_imaginary_residual(const DoubledSurface& d, const SymmetricBasis& b) {
  const double scale = (b.real_part.cwiseAbs2() + b.imaginary_part.cwiseAbs2()).cwiseSqrt().maxCoeff();
  double worst = 0;
  for (Eigen::Index e = 0; e < b.imaginary_part.rows(); ++e)
    if (d.is_input_boundary_edge[e]) worst = std::max(worst, b.imaginary_part.row(e).cwiseAbs().maxCoeff());
  return worst / scale;
}

}  // namespace qm
