// Assembling a weighted graph Laplacian straight from its edges (the energy
// sum_e w_e (s_a f_a - s_b f_b)^2), without forming d0^T W d0 as a sparse product
// (which converts storage orders three times and cost as much as the
// back-solves on a 278k-triangle surface).
#pragma once

#include <Eigen/SparseCore>

#include <algorithm>
#include <utility>
#include <vector>

namespace qm::internal {

/// One edge's term w (s_a f_a - s_b f_b)^2 of the energy. An endpoint index < 0
/// is a Dirichlet vertex with value 0: its row and column are dropped. a != b.
struct EdgeTerm {
  int a = -1, b = -1;
  double w = 0;
  double sign = 1;  ///< s_a s_b
};

/// The lower triangle of the n x n matrix of the quadratic form sum over `terms`
/// (symmetric: CHOLMOD with Eigen::Lower reads only this), compressed. Column c
/// holds the diagonal, then the rows > c in increasing order; entries are summed
/// in the order of `terms`, so the result is the same on every run.
inline Eigen::SparseMatrix<double> edge_laplacian_lower(Eigen::Index n, const std::vector<EdgeTerm>& terms) {
  std::vector<double> diagonal(static_cast<std::size_t>(n), 0.0);
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);  // off-diagonal entries per column
  for (const EdgeTerm& t : terms) {
    if (t.a >= 0) diagonal[static_cast<std::size_t>(t.a)] += t.w;
    if (t.b >= 0) diagonal[static_cast<std::size_t>(t.b)] += t.w;
    if (t.a >= 0 && t.b >= 0 && t.a != t.b) ++start[static_cast<std::size_t>(std::min(t.a, t.b)) + 1];
  }
  for (std::size_t c = 0; c < static_cast<std::size_t>(n); ++c) start[c + 1] += start[c];
  std::vector<std::pair<int, double>> off(static_cast<std::size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const EdgeTerm& t : terms)
    if (t.a >= 0 && t.b >= 0 && t.a != t.b)
      off[static_cast<std::size_t>(fill[static_cast<std::size_t>(std::min(t.a, t.b))]++)] = {std::max(t.a, t.b),
                                                                                              -t.sign * t.w};
  Eigen::SparseMatrix<double> L(n, n);
  std::vector<Eigen::Index> nonzeros(static_cast<std::size_t>(n));
  for (std::size_t c = 0; c < static_cast<std::size_t>(n); ++c) {
    const auto first = off.begin() + start[c], last = off.begin() + start[c + 1];
    std::stable_sort(first, last, [](const auto& x, const auto& y) { return x.first < y.first; });
    nonzeros[c] = 1;
    for (auto it = first; it != last; ++it)
      if (it == first || it->first != (it - 1)->first) ++nonzeros[c];
  }
  L.reserve(nonzeros);
  for (std::size_t c = 0; c < static_cast<std::size_t>(n); ++c) {
    const auto col = static_cast<Eigen::Index>(c);
    L.insert(col, col) = diagonal[c];
    // duplicates (the same pair from several terms) summed in term order
    auto it = off.begin() + start[c];
    const auto last = off.begin() + start[c + 1];
    while (it != last) {
      const int row = it->first;
      double sum = 0;
      for (; it != last && it->first == row; ++it) sum += it->second;
      L.insert(row, col) = sum;
    }
  }
  L.makeCompressed();
  return L;
}

}  // namespace qm::internal
