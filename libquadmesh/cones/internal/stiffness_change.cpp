#include "libquadmesh/cones/internal/stiffness_change.h"

#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/core/error.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace qm {

namespace {

/// A pivot at most this fraction of the block's largest diagonal entry is taken
/// as vanishing (the constants' direction leaves round-off there), and C C^T must
/// match the block to this fraction of it.
constexpr double pivot_tolerance = 1e-12;
constexpr double match_tolerance = 1e-10;

}  // namespace

StiffnessChange stiffness_change(const TriangleSoup& soup, const CutGraph& cut, const std::vector<double>& before,
                                 const std::vector<double>& after) {
  QM_ASSERT(before.size() == soup.triangles.size() && after.size() == before.size());
  StiffnessChange change;
  std::vector<std::size_t> changed;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (after[f] != before[f]) {
      QM_ASSERT(after[f] > before[f]);
      changed.push_back(f);
      for (int w : cut.wedge[f]) change.wedges.push_back(w);
    }
  std::sort(change.wedges.begin(), change.wedges.end());
  change.wedges.erase(std::unique(change.wedges.begin(), change.wedges.end()), change.wedges.end());
  const auto index = [&](int w) {
    return static_cast<Eigen::Index>(std::lower_bound(change.wedges.begin(), change.wedges.end(), w) -
                                     change.wedges.begin());
  };
  const auto n = static_cast<Eigen::Index>(change.wedges.size());
  change.block = Eigen::MatrixXd::Zero(n, n);
  for (std::size_t f : changed) {
    // the cotan form as add_fitting_energy weighs it, times the stiffness added
    const double d = after[f] - before[f];
    const auto cot = corner_cotangents(soup, f);
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t i = (k + 1) % 3, j = (k + 2) % 3;
      const double w = 0.5 * d * cot[k];
      const int wi = cut.wedge[f][i], wj = cut.wedge[f][j];
      for (int axis = 0; axis < 2; ++axis) {
        const int vi = 2 * wi + axis, vj = 2 * wj + axis;
        change.matrix.emplace_back(vi, vi, w);
        change.matrix.emplace_back(vj, vj, w);
        change.matrix.emplace_back(vi, vj, -w);
        change.matrix.emplace_back(vj, vi, -w);
      }
      const Eigen::Index a = index(wi), b = index(wj);
      change.block(a, a) += w;
      change.block(b, b) += w;
      change.block(a, b) -= w;
      change.block(b, a) -= w;
    }
  }
  return change;
}

namespace {

/// R (m x rank, lower trapezoidal) with R R^T = A, by Cholesky's factorization in
/// A's order, a pivot that vanishes (at most pivot_tolerance of A's largest
/// diagonal entry) left out; nothing where A is not positive semidefinite to
/// round-off (a negative pivot, or R R^T off A by more than match_tolerance).
std::optional<Eigen::MatrixXd> semidefinite_root(const Eigen::MatrixXd& A) {
  const Eigen::Index m = A.rows();
  if (m == 0) return Eigen::MatrixXd(0, 0);
  const double scale = A.diagonal().cwiseAbs().maxCoeff();
  Eigen::MatrixXd rest = A;  // the Schur complement, column by column
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(m, m);
  Eigen::Index rank = 0;
  for (Eigen::Index j = 0; j < m; ++j) {
    const double pivot = rest(j, j);
    if (pivot < -pivot_tolerance * scale) return std::nullopt;
    if (pivot <= pivot_tolerance * scale) continue;  // (its column is checked below)
    const Eigen::VectorXd l = rest.col(j).tail(m - j) / std::sqrt(pivot);
    rest.bottomRightCorner(m - j, m - j).noalias() -= l * l.transpose();
    R.col(rank++).tail(m - j) = l;
  }
  R.conservativeResize(m, rank);
  if ((R * R.transpose() - A).cwiseAbs().maxCoeff() > match_tolerance * scale) return std::nullopt;
  return R;
}

}  // namespace

std::optional<Eigen::SparseMatrix<double>> change_columns(const StiffnessChange& change,
                                                          const std::vector<int>& position, int variables,
                                                          std::size_t max_wedges) {
  const std::size_t n = change.wedges.size();
  if (n > max_wedges) return std::nullopt;
  std::vector<Eigen::Triplet<double>> entries;
  int column = 0;
  for (int axis = 0; axis < 2; ++axis) {
    // the wedges in elimination order: C's columns then start where L's paths do
    const auto variable = [&](Eigen::Index i) { return 2 * change.wedges[static_cast<std::size_t>(i)] + axis; };
    std::vector<Eigen::Index> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) {
      return position[static_cast<std::size_t>(variable(a))] < position[static_cast<std::size_t>(variable(b))];
    });
    const auto m = static_cast<Eigen::Index>(n);
    Eigen::MatrixXd ordered(m, m);
    for (Eigen::Index i = 0; i < m; ++i)
      for (Eigen::Index j = 0; j < m; ++j) ordered(i, j) = change.block(order[i], order[j]);
    const std::optional<Eigen::MatrixXd> R = semidefinite_root(ordered);
    if (!R) return std::nullopt;
    for (Eigen::Index c = 0; c < R->cols(); ++c, ++column)
      for (Eigen::Index i = 0; i < m; ++i)
        if ((*R)(i, c) != 0) entries.emplace_back(variable(order[i]), column, (*R)(i, c));
  }
  Eigen::SparseMatrix<double> C(variables, column);
  C.setFromTriplets(entries.begin(), entries.end());
  C.makeCompressed();
  return C;
}

}  // namespace qm
