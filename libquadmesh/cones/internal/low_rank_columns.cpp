#include "libquadmesh/cones/internal/low_rank_columns.h"

#include "libquadmesh/core/error.h"

#include <algorithm>
#include <utility>

namespace qm {

LowRankColumns::LowRankColumns(Eigen::Index rows, std::size_t capacity, std::size_t batch)
    : rows_(rows), capacity_(capacity), batch_(std::max<std::size_t>(1, batch)) {
  QM_ASSERT(rows > 0 && capacity > 0);
}

void LowRankColumns::clear() { std::fill(value_of_.begin(), value_of_.end(), -1); }

void LowRankColumns::swap_slots(std::size_t a, std::size_t b) {
  if (a == b) return;
  columns_.col(static_cast<Eigen::Index>(a)).swap(columns_.col(static_cast<Eigen::Index>(b)));
  std::swap(value_of_[a], value_of_[b]);
}

const Eigen::MatrixXd& LowRankColumns::align(const std::vector<int>& values, const Solve& solve) {
  const std::size_t k = values.size();
  QM_ASSERT(k <= capacity_);
  if (columns_.rows() != rows_) {
    columns_.resize(rows_, static_cast<Eigen::Index>(capacity_));
    value_of_.assign(capacity_, -1);
  }
  const auto slot_of = [&](int v, std::size_t from) {
    return static_cast<std::size_t>(
        std::find(value_of_.begin() + static_cast<std::ptrdiff_t>(from), value_of_.end(), v) - value_of_.begin());
  };
  // slot i gets values[i]'s column where one is kept, else is marked missing (the
  // column there before, another value's, moves to a free slot past k if any)
  std::vector<std::size_t> slots;
  for (std::size_t i = 0; i < k; ++i) {
    const int v = values[i];
    QM_ASSERT(v >= 0 && v < rows_);
    if (value_of_[i] == v) continue;
    if (const std::size_t j = slot_of(v, i); j < capacity_) {
      swap_slots(i, j);
      continue;
    }
    if (value_of_[i] >= 0)
      if (const std::size_t j = slot_of(-1, k); j < capacity_) swap_slots(i, j);
    value_of_[i] = v;
    slots.push_back(i);
  }
  if (slots.empty()) return columns_;
  // the batch filled with expected values' columns: in free slots past k, then in
  // those of values not expected
  const std::size_t batch = std::min(capacity_, (slots.size() + batch_ - 1) / batch_ * batch_);
  const auto expected = [&](int v) { return std::find(expected_.begin(), expected_.end(), v) != expected_.end(); };
  std::vector<std::size_t> spare;
  for (std::size_t j = k; j < capacity_; ++j)
    if (value_of_[j] < 0) spare.push_back(j);
  for (std::size_t j = k; j < capacity_; ++j)
    if (value_of_[j] >= 0 && !expected(value_of_[j])) spare.push_back(j);
  std::size_t next = 0;
  for (int v : expected_) {
    if (slots.size() >= batch || next == spare.size()) break;
    if (v < 0 || v >= rows_ || slot_of(v, 0) < capacity_) continue;
    value_of_[spare[next]] = v;
    slots.push_back(spare[next++]);
  }
  const auto width = static_cast<Eigen::Index>(slots.size());
  Eigen::MatrixXd units = Eigen::MatrixXd::Zero(rows_, width);
  for (Eigen::Index c = 0; c < width; ++c) units(value_of_[slots[static_cast<std::size_t>(c)]], c) = 1;
  Eigen::MatrixXd solved;
  try {
    solved = solve(units);
  } catch (...) {
    clear();  // the slots named above hold no columns
    throw;
  }
  QM_ASSERT(solved.rows() == rows_ && solved.cols() == width);
  for (Eigen::Index c = 0; c < width; ++c) columns_.col(static_cast<Eigen::Index>(slots[static_cast<std::size_t>(c)])) = solved.col(c);
  computed_ += slots.size();
  ++solves_;
  return columns_;
}

}  // namespace qm
