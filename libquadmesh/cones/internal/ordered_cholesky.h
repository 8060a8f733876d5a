// The seamless map's factorization (seamless_map.cpp, PenaltySolver): CHOLMOD's
// simplicial Cholesky factorization of a sparse symmetric positive definite
// matrix, its fill-reducing ordering chosen by the caller, and updated in place
// when the matrix gains a positive semidefinite low-rank term C C^T (the values
// the rounding fixes, the triangles the stiffening weighs more: on bunny-open's
// 75,358 unknowns a factorization takes 0.18 s, an update a few milliseconds).
#pragma once

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <vector>

namespace qm {

/// Analysed by CHOLMOD's default ordering (minimum degree: analyzePattern), by
/// METIS's nested dissection, or by a permutation given (CHOLMOD's own from an
/// analysis before: the same factorization).
class OrderedCholesky : public Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>, Eigen::Lower> {
 public:
  using SparseMatrix = Eigen::SparseMatrix<double>;

  /// H's pattern ordered by METIS; returns CHOLMOD's permutation (postordered).
  /// Throws qm::Error (solver) where it cannot be ordered.
  std::vector<int> analyse_by_nested_dissection(const SparseMatrix& H);

  /// H's pattern ordered by `permutation` (a permutation of this pattern's
  /// analysis before). Throws qm::Error (solver) where it cannot be analysed.
  void analyse_by(const SparseMatrix& H, const std::vector<int>& permutation);

  /// The analysis's permutation (row k of L is row permutation[k] of H).
  std::vector<int> permutation() const;

  /// Its inverse: the row of L each row of H is (the elimination order's positions).
  std::vector<int> positions() const;

  /// The factorization of H + C C^T from that of H (CHOLMOD's multiple-rank
  /// update, in place; the factor becomes an LDL' one, which solve() takes as it
  /// is, and which is factored anew only after analyse_by). C has H's rows. False
  /// where CHOLMOD could not: the factor is then left symbolic, to be factored
  /// again.
  bool update(const SparseMatrix& C);
};

}  // namespace qm
