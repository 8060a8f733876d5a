#include "tests/support/grid_system.h"

#include <utility>
#include <vector>

namespace qm::test {

Eigen::SparseMatrix<double> grid_system(int side) {
  std::vector<Eigen::Triplet<double>> t;
  const auto id = [side](int i, int j) { return i * side + j; };
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      t.emplace_back(id(i, j), id(i, j), 1e-3 * (1 + (i + 2 * j) % 5));
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}})
        if (i + di < side && j + dj < side) {
          const int a = id(i, j), b = id(i + di, j + dj);
          const double w = 1 + 0.1 * ((i * 7 + j * 3) % 4);
          t.emplace_back(a, a, w);
          t.emplace_back(b, b, w);
          t.emplace_back(a, b, -w);
          t.emplace_back(b, a, -w);
        }
    }
  Eigen::SparseMatrix<double> H(side * side, side * side);
  H.setFromTriplets(t.begin(), t.end());
  return H;
}

}  // namespace qm::test
