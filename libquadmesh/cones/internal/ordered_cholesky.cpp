#include "libquadmesh/cones/internal/ordered_cholesky.h"

#include "libquadmesh/core/error.h"

#include <mutex>

namespace qm {

namespace {

/// Held while METIS orders a system (a MapOrdering's first map).
std::mutex metis_mutex;

}  // namespace

std::vector<int> OrderedCholesky::analyse_by_nested_dissection(const SparseMatrix& H) {
  cholmod().nmethods = 1;
  cholmod().method[0].ordering = CHOLMOD_METIS;
  {
    // METIS draws from one random state for the whole process, seeded at each
    // call: two calls at once (placements side by side) would order differently
    // from one at a time
    std::lock_guard<std::mutex> lock(metis_mutex);
    analyzePattern(H);
  }
  if (!m_cholmodFactor || !m_cholmodFactor->Perm)
    throw Error(ErrorCode::solver, "the seamless map's system could not be ordered");
  return permutation();
}

void OrderedCholesky::analyse_by(const SparseMatrix& H, const std::vector<int>& permutation) {
  QM_ASSERT(static_cast<Eigen::Index>(permutation.size()) == H.rows());
  if (m_cholmodFactor) cholmod_free_factor(&m_cholmodFactor, &cholmod());
  cholmod().nmethods = 1;
  cholmod().method[0].ordering = CHOLMOD_GIVEN;
  cholmod_sparse A = Eigen::viewAsCholmod(H.selfadjointView<Eigen::Lower>());
  std::vector<int> given = permutation;  // (CHOLMOD's signature is not const)
  m_cholmodFactor = cholmod_analyze_p(&A, given.data(), nullptr, 0, &cholmod());
  if (!m_cholmodFactor) throw Error(ErrorCode::solver, "the seamless map's system could not be ordered");
  m_isInitialized = true;
  m_info = Eigen::Success;
  m_analysisIsOk = true;
  m_factorizationIsOk = false;
}

std::vector<int> OrderedCholesky::permutation() const {
  QM_ASSERT(m_cholmodFactor && m_cholmodFactor->Perm);
  const int* p = static_cast<const int*>(m_cholmodFactor->Perm);
  return {p, p + m_cholmodFactor->n};
}

std::vector<int> OrderedCholesky::positions() const {
  const std::vector<int> order = permutation();
  std::vector<int> position(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) position[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  return position;
}

bool OrderedCholesky::update(const SparseMatrix& C) {
  QM_ASSERT(m_cholmodFactor && m_factorizationIsOk && C.rows() == static_cast<Eigen::Index>(m_cholmodFactor->n));
  if (C.cols() == 0) return true;
  const std::vector<int> position = positions();
  // CHOLMOD takes C's rows in L's order (cholmod_updown does not apply the
  // permutation), each column's rows sorted
  std::vector<Eigen::Triplet<double>> permuted;
  permuted.reserve(static_cast<std::size_t>(C.nonZeros()));
  for (Eigen::Index c = 0; c < C.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(C, c); it; ++it)
      permuted.emplace_back(position[static_cast<std::size_t>(it.row())], static_cast<int>(c), it.value());
  SparseMatrix P(C.rows(), C.cols());
  P.setFromTriplets(permuted.begin(), permuted.end());
  P.makeCompressed();
  cholmod_sparse view = Eigen::viewAsCholmod(P);
  view.sorted = 1;
  const bool done = cholmod_updown(1, &view, m_cholmodFactor, &cholmod()) != 0 &&
                    cholmod().status == CHOLMOD_OK && m_cholmodFactor->xtype != CHOLMOD_PATTERN;
  if (!done) m_factorizationIsOk = false;
  return done;
}

}  // namespace qm
