// A sparse symmetric positive definite system with fill in its factor, for the
// tests of the seamless map's factorization and its ordering.
#pragma once

#include <Eigen/Sparse>

namespace qm::test {

/// A grid graph's Laplacian (side x side, edge weights 1-1.3) plus a small
/// diagonal (1e-3-5e-3).
Eigen::SparseMatrix<double> grid_system(int side);

}  // namespace qm::test
