// Assembling a weighted graph Laplacian straight from its edges (the energy
// sum_e w_e (s_a f_a - s_b f_b)^2), without forming d0^T W d0 as a sparse product
// (which converts storage orders three times and cost as much as the
// back-solves on a 278k-triangle surface).
#pragma once

#include <Eigen/SparseCore>

#include <vector>

namespace qm::internal {

/// One edge's term w (s_a f_a - s_b f_b)^2 of the energy. An endpoint index < 0
/// is a Dirichlet vertex with value 0: its row and column are dropped.
struct EdgeTerm {
  int a = -1, b = -1;
  double w = 0;
  double sign = 1;  ///< s_a s_b
};

/// The n x n matrix of the quadratic form sum over `terms` (symmetric, both
/// triangles stored, compressed). Entries are summed in the order of `terms`, so
/// the result is the same on every run.
inline Eigen::SparseMatrix<double> edge_laplacian(Eigen::Index n, const std::vector<EdgeTerm>& terms) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * terms.size());
  for (const EdgeTerm& t : terms) {
    if (t.a >= 0) entries.emplace_back(t.a, t.a, t.w);
    if (t.b >= 0) entries.emplace_back(t.b, t.b, t.w);
    if (t.a >= 0 && t.b >= 0) {
      entries.emplace_back(t.a, t.b, -t.sign * t.w);
      entries.emplace_back(t.b, t.a, -t.sign * t.w);
    }
  }
  Eigen::SparseMatrix<double> L(n, n);
  L.setFromTriplets(entries.begin(), entries.end());
  L.makeCompressed();
  return L;
}

}  // namespace qm::internal
