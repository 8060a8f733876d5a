// The columns of low_rank_columns.h: after any sequence of values fixed, taken
// back, expected and fixed again, the first columns are H0^-1 e_v of the values
// asked for, in order, the same numbers a solve of each alone gives; a solve for a
// missing column also computes those of the values expected next, and a column
// kept is not computed again.
#include "libquadmesh/cones/internal/low_rank_columns.h"

#include <doctest/doctest.h>

#include <Eigen/Cholesky>
#include <Eigen/Dense>

#include <vector>

using namespace qm;

namespace {

/// A path graph's Laplacian plus a diagonal: symmetric positive definite, with a
/// dense inverse (every column differs from every other in every entry).
Eigen::MatrixXd path_system(int n) {
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    A(i, i) = 2.1 + 0.01 * i;
    if (i + 1 < n) A(i, i + 1) = A(i + 1, i) = -1;
  }
  return A;
}

/// A solver of A that counts its calls and the right sides they took.
struct CountingSolve {
  Eigen::LLT<Eigen::MatrixXd> llt;
  std::size_t calls = 0, columns = 0;
  LowRankColumns::Solve function() {
    return [this](const Eigen::MatrixXd& units) {
      ++calls;
      columns += static_cast<std::size_t>(units.cols());
      return Eigen::MatrixXd(llt.solve(units));
    };
  }
};

/// Eigen's solve of one column and of several round differently; a wrong column
/// is off by the inverse's entries (0.01-0.9 here).
constexpr double tolerance = 1e-13;

/// The largest difference of align()'s first columns from A^-1 e_v of `values`,
/// each solved alone.
double column_error(const Eigen::MatrixXd& Y, const Eigen::LLT<Eigen::MatrixXd>& llt, const std::vector<int>& values) {
  double worst = 0;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const Eigen::VectorXd e = Eigen::VectorXd::Unit(Y.rows(), values[i]);
    const Eigen::VectorXd alone = llt.solve(e);
    worst = std::max(worst, (Y.col(static_cast<Eigen::Index>(i)) - alone).cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace

TEST_CASE("the low-rank columns: each value's own column in order, missing ones in batches with the expected, "
          "kept ones not computed again") {
  const int n = 30;
  CountingSolve counting{Eigen::LLT<Eigen::MatrixXd>(path_system(n))};
  const auto solve = counting.function();
  LowRankColumns columns(n, 8, 4);

  // one value fixed, three expected: one solve of four columns
  columns.expect({5, 9, 12});
  std::vector<int> fixed = {3};
  CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  CHECK(counting.calls == 1);
  CHECK(counting.columns == 4);

  // the expected ones fixed next (one after another, the last taken back first):
  // no solve
  for (int v : {9, 5, 12}) {
    fixed.push_back(v);
    CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  }
  fixed.pop_back();
  CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  CHECK(counting.calls == 1);

  // 12 fixed again after its place was taken by 20 (a rounding tried, refused)
  fixed.push_back(20);
  columns.expect({});
  CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  CHECK(counting.calls == 2);
  CHECK(counting.columns == 5);  // nothing expected: the missing column alone
  fixed.back() = 12;
  CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  CHECK(counting.calls == 2);

  // full: the capacity bounds the batch, and no column kept for a value fixed
  // is given to an expected one
  columns.expect({0, 1, 2, 4, 6, 7});
  fixed.insert(fixed.end(), {25, 26, 27, 28});  // 8 values: the capacity
  CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  CHECK(counting.calls == 3);
  CHECK(counting.columns == 5 + 4);  // 25-28 computed, 20's column dropped for 25's

  // a new factorization: every column computed again
  columns.clear();
  fixed = {3, 9};
  CHECK(column_error(columns.align(fixed, solve), counting.llt, fixed) < tolerance);
  CHECK(counting.calls == 4);
  CHECK(counting.columns == 9 + 4);  // two missing, two expected (0 and 1)
  CHECK(columns.computed() == counting.columns);
  CHECK(columns.solves() == counting.calls);
}
