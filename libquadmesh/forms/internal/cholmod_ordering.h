// One fill-reducing ordering policy for every CHOLMOD factorization of a surface
// Laplacian in forms/ and param/.
//
// CHOLMOD's default (nmethods = 0) orders with AMD and, when AMD's fill is high,
// also tries METIS and nested dissection and keeps the best. On surface Laplacians
// the extra orderings cost more than they save: measured on bunny-open-large
// doubled (278k vertices) and on its 1.1M-triangle subdivision doubled (1.1M):
//   default: analyse 15.2 s + factor 8.1 s (it tried METIS: 54M nonzeros in L)
//   AMD only: analyse 2.2 s + factor 9.8 s (84M nonzeros in L)
// and at 278k vertices the default already stops at AMD (0.35 s + 1.6 s).
#pragma once

#include <Eigen/CholmodSupport>

namespace qm::internal {

/// Restricts a CHOLMOD decomposition's analysis to AMD (see above).
template <class Decomposition>
void use_amd_ordering(Decomposition& cholesky) {
  cholesky.cholmod().nmethods = 1;
  cholesky.cholmod().method[0].ordering = CHOLMOD_AMD;
  cholesky.cholmod().postorder = 1;
}

}  // namespace qm::internal
