// The columns H0^-1 e_v of the seamless map's low-rank solves (seamless_map.cpp,
// PenaltySolver): each value the rounding fixes since the last factorization of
// H0 adds a penalty on its diagonal entry, and the Woodbury identity needs H0^-1
// e_v for each of them, one back-substitution per column. CHOLMOD's simplicial
// solve takes right sides four at a time: on bunny-open's 75,358 unknowns one
// column alone takes 6.5 ms and four together 11.4 ms (2.9 ms each, and no less
// per column past four). So the columns are kept by value, not by position (a
// rounding tried and taken back, or a value tested and let go, is fixed again
// later with its column still valid), and a solve for a missing column fills its
// batch with the columns of the values the rounding expects to fix next. CHOLMOD
// computes each column of a batch as it does one alone, so the maps are the same
// bit for bit (the 52 regression inputs' quads: the same bytes).
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <vector>

namespace qm {

class LowRankColumns {
 public:
  /// Solves H0 Y = E for a block of unit right sides.
  using Solve = std::function<Eigen::MatrixXd(const Eigen::MatrixXd&)>;

  /// Columns of `rows` entries, at most `capacity` kept, at least `batch` per solve
  /// where as many are expected.
  LowRankColumns(Eigen::Index rows, std::size_t capacity, std::size_t batch);

  /// Drops every column (H0 was factored again).
  void clear();

  /// The values likely fixed next, most likely first.
  void expect(std::vector<int> values) { expected_ = std::move(values); }

  /// The matrix whose first values.size() (<= capacity) columns are H0^-1 e_v of
  /// `values`, in order; the missing ones are computed in one call of `solve`.
  const Eigen::MatrixXd& align(const std::vector<int>& values, const Solve& solve);

  /// The columns computed and the solves that computed them, since construction.
  std::size_t computed() const { return computed_; }
  std::size_t solves() const { return solves_; }

 private:
  void swap_slots(std::size_t a, std::size_t b);

  Eigen::Index rows_;
  std::size_t capacity_;
  std::size_t batch_;
  Eigen::MatrixXd columns_;     ///< allocated at the first align()
  std::vector<int> value_of_;   ///< each slot's value (-1: none)
  std::vector<int> expected_;
  std::size_t computed_ = 0, solves_ = 0;
};

}  // namespace qm
