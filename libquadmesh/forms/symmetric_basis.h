// Symmetric holomorphic forms (method.md section 6, seed paper section 4.5).
//
// h = omega + i *omega is symmetric (h(phi e) = conj h(e)) exactly when omega is
// phi-invariant. phi* acts on the harmonic space as an isometry M (in the L2
// inner product B); the symmetric forms are its +1 eigenspace, found as the range
// of P = (I + M) / 2 in B-orthonormal coordinates. For an open surface its real
// dimension is the doubled genus G. For a closed surface (phi = identity) every
// harmonic form qualifies; a basis of G forms whose stars complete it to the whole
// harmonic space is returned (the holomorphic forms have complex dimension G).
#pragma once

#include "libquadmesh/forms/doubled_surface.h"
#include "libquadmesh/forms/hodge_star.h"

namespace qm {

/// (phi* omega)(e) = sign(e) omega(phi(e)) for every column.
Eigen::MatrixXd pull_back(const DoubledSurface& d, const Eigen::MatrixXd& forms);

struct SymmetricBasis {
  Eigen::MatrixXd coefficients;  ///< 2G x m: omega_sym = harmonic * coefficients (B-orthonormal)
  Eigen::MatrixXd real_part;     ///< |E| x m: omega_sym
  Eigen::MatrixXd imaginary_part;  ///< |E| x m: *omega_sym = harmonic * Lambda * coefficients
  Eigen::VectorXd invariance_spectrum;  ///< eigenvalues of P (1: invariant, 0: anti-invariant)
  int dimension() const { return static_cast<int>(coefficients.cols()); }
};

/// Precondition: harmonic (|E| x 2G) is a basis of the harmonic forms of d.mesh
/// and star its Galerkin Hodge star.
SymmetricBasis symmetric_basis(const DoubledSurface& d, const Eigen::MatrixXd& harmonic,
                               const HodgeStar& star, bool closed_surface);

/// max over edges of |h(phi e) - conj h(e)| / max |h|, over all columns.
double symmetry_residual(const DoubledSurface& d, const SymmetricBasis& basis);

/// max over boundary edges of S of |Im h(e)| / max |h|, over all columns.
double boundary_imaginary_residual(const DoubledSurface& d, const SymmetricBasis& basis);

}  // namespace qm
