// The seamless map's factorization updated in place (ordered_cholesky.h): after
// updates by C C^T (stiffened triangles' forms, penalties on fixed values), its
// solves are those of H + C C^T factored anew, whichever ordering analysed it,
// and it can be analysed and factored again afterwards.
#include "libquadmesh/cones/internal/ordered_cholesky.h"
#include "tests/support/grid_system.h"

#include <doctest/doctest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

using namespace qm;
using qm::test::grid_system;

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Columns touching a few neighbouring unknowns each (a triangle's form) and unit
/// columns times 1e4 (a fixed value's penalty).
SparseMatrix low_rank_term(int n) {
  std::vector<Eigen::Triplet<double>> t;
  int column = 0;
  for (int start : {5, 40, 41, 77}) {
    t.emplace_back(start, column, 0.7);
    t.emplace_back(start + 1, column, -0.4);
    t.emplace_back(start + 10, column, -0.3);
    ++column;
  }
  for (int v : {3, 58, 99}) t.emplace_back(v, column++, 1e4);
  SparseMatrix C(n, column);
  C.setFromTriplets(t.begin(), t.end());
  C.makeCompressed();
  return C;
}

/// The largest difference of the solutions of A x = b by `solver` and by a dense
/// factorization of A, relative to the solution's size.
double solve_error(OrderedCholesky& solver, const SparseMatrix& A, const Eigen::VectorXd& b) {
  const Eigen::VectorXd exact = Eigen::MatrixXd(A).ldlt().solve(b);
  const Eigen::VectorXd x = solver.solve(b);
  REQUIRE(solver.info() == Eigen::Success);
  return (x - exact).cwiseAbs().maxCoeff() / exact.cwiseAbs().maxCoeff();
}

}  // namespace

TEST_CASE("the map's factorization updated by C C^T solves H + C C^T, by either ordering, and factors again after") {
  const int side = 10, n = side * side;
  const SparseMatrix H = grid_system(side);
  const SparseMatrix C = low_rank_term(n);
  const SparseMatrix updated = H + SparseMatrix(C * C.transpose());
  Eigen::VectorXd b(n);
  for (int i = 0; i < n; ++i) b[i] = std::sin(0.3 * i) + 0.1 * i;

  for (const bool nested_dissection : {false, true}) {
    CAPTURE(nested_dissection);
    OrderedCholesky solver;
    if (nested_dissection) {
      std::vector<int> p = solver.analyse_by_nested_dissection(H);
      std::vector<int> sorted = p;
      std::sort(sorted.begin(), sorted.end());
      std::vector<int> identity(static_cast<std::size_t>(n));
      std::iota(identity.begin(), identity.end(), 0);
      CHECK(sorted == identity);  // a permutation
      CHECK(solver.permutation() == p);
      const std::vector<int> position = solver.positions();
      for (int k = 0; k < n; ++k) CHECK(position[static_cast<std::size_t>(p[static_cast<std::size_t>(k)])] == k);
    } else {
      solver.analyzePattern(H);
    }
    solver.factorize(H);
    REQUIRE(solver.info() == Eigen::Success);
    CHECK(solve_error(solver, H, b) < 1e-10);

    // the update's solves are H + C C^T's; before it they were H's, which differ
    REQUIRE(solver.update(C));
    CHECK(solve_error(solver, updated, b) < 1e-10);
    const Eigen::VectorXd before = Eigen::MatrixXd(H).ldlt().solve(b);
    CHECK((solver.solve(b) - before).cwiseAbs().maxCoeff() > 1e-3 * before.cwiseAbs().maxCoeff());

    // two updates, one after the other, add up; nothing to add changes nothing
    REQUIRE(solver.update(C));
    const SparseMatrix twice = updated + SparseMatrix(C * C.transpose());
    CHECK(solve_error(solver, twice, b) < 1e-10);
    CHECK(solver.update(SparseMatrix(n, 0)));
    CHECK(solve_error(solver, twice, b) < 1e-10);

    // analysed again by its own permutation, it factors another matrix
    solver.analyse_by(updated, solver.permutation());
    solver.factorize(updated);
    REQUIRE(solver.info() == Eigen::Success);
    CHECK(solve_error(solver, updated, b) < 1e-10);
  }
}
