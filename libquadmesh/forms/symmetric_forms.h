// The forms stage as one call: doubling, cotangent weights, cohomology, harmonic
// basis, Hodge star, symmetric basis, zeros, with residuals and stage timings
// (method.md sections 1-6).
#pragma once

#include "libquadmesh/forms/cohomology_basis.h"
#include "libquadmesh/forms/symmetric_basis.h"
#include "libquadmesh/forms/zeros.h"

#include <string>
#include <utility>
#include <vector>

namespace qm {

struct FormsResiduals {
  double closedness = 0;          ///< max |d omega| over faces (harmonic basis)
  double coclosedness = 0;        ///< max |d0^T W omega| / max |W omega|
  double hodge_star_squared = 0;  ///< ||Lambda^2 + I||_F / ||I||_F
  double boundary_imaginary = 0;  ///< max |Im h| on boundary edges of S / max |h|
  double symmetry = 0;            ///< max |h(phi e) - conj h(e)| / max |h|
};

struct SymmetricForms {
  DoubledSurface doubled;
  int doubled_genus = 0;
  Eigen::VectorXd weights;  ///< cotangent weights on D
  CohomologyBasis cohomology;
  Eigen::MatrixXd harmonic;  ///< |E(D)| x 2G
  HodgeStar star;
  SymmetricBasis symmetric;
  FormZeros zeros;  ///< of the first symmetric basis form
  FormsResiduals residuals;
  std::vector<std::pair<std::string, double>> timings;  ///< seconds per stage
};

/// Computes everything above for a supported surface (boundary: doubled; closed:
/// the surface itself). Precondition: `surface` is connected, orientable, with
/// chi <= 0. Throws qm::Error(solver) when a linear solve fails.
SymmetricForms compute_symmetric_forms(const Mesh& surface);

}  // namespace qm
