#include "libquadmesh/cones/cone_metric.h"

#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <cmath>

namespace qm {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// The faint diagonal added to L, relative to its mean off-diagonal weight.
constexpr double regularization = 1e-10;
/// Largest turning error (radians) of the field at a vertex: the field then
/// turns by its cone to well within the cross field's alignment tolerance...
constexpr double turning_tolerance = 1e-8;
/// ...or, where the faint diagonal is larger (a mesh of large mean weight: split
/// slivers), the error it leaves at a vertex whose u is this: (L + eps) u = rhs
/// leaves L u - rhs = -eps u, and a vertex whose inner edges cannot turn the
/// field is held by eps alone, at u = rhs / eps, far beyond.
constexpr double max_held_u = 100;

/// The cotan Laplacian over inner edges.
SparseMatrix inner_edge_laplacian(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  const auto nV = static_cast<Eigen::Index>(soup.points.size());
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const auto cot = corner_cotangents(soup, f);
    for (int k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      if (adjacency.find(j, i).face < 0) continue;  // a boundary edge: no transport across it
      const double w = 0.5 * cot[static_cast<std::size_t>(k)];
      entries.emplace_back(i, i, w);
      entries.emplace_back(j, j, w);
      entries.emplace_back(i, j, -w);
      entries.emplace_back(j, i, -w);
    }
  }
  SparseMatrix L(nV, nV);
  L.setFromTriplets(entries.begin(), entries.end());
  return L;
}

/// Per vertex, the sum of |w| over its inner edges (0: nothing turns the field there).
Eigen::VectorXd transport_weight(const SparseMatrix& L) {
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(L.rows());
  for (Eigen::Index c = 0; c < L.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(L, c); it; ++it)
      if (it.row() != it.col()) weight[it.row()] += std::abs(it.value());
  return weight;
}

/// The constant that makes sum_f area_f e^(2 u_f) equal the surface's area.
double area_preserving_shift(const TriangleSoup& soup, const Eigen::VectorXd& u) {
  double area = 0, scaled = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3& p = soup.points[static_cast<std::size_t>(t[0])];
    const double a = 0.5 * (soup.points[static_cast<std::size_t>(t[1])] - p)
                               .cross(soup.points[static_cast<std::size_t>(t[2])] - p)
                               .norm();
    const double uf = (u[t[0]] + u[t[1]] + u[t[2]]) / 3.0;
    area += a;
    scaled += a * std::exp(2 * uf);
  }
  return scaled > 0 ? -0.5 * std::log(scaled / area) : 0.0;
}

}  // namespace

struct ConeMetricSolver::Factor {
  SparseMatrix L;
  Eigen::VectorXd weight;
  double epsilon = 0;
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> cholesky;
};

ConeMetricSolver::ConeMetricSolver(const TriangleSoup& soup, const SurfaceAdjacency& adjacency)
    : soup_(soup), adjacency_(adjacency), factor_(std::make_unique<Factor>()) {
  factor_->L = inner_edge_laplacian(soup, adjacency);
  // L is singular (constants; and a corner whose inner edges all have weight 0):
  // a faint diagonal makes it definite without moving the solution measurably
  factor_->weight = transport_weight(factor_->L);
  factor_->epsilon = regularization * std::max(factor_->weight.mean(), 1e-300);
  SparseMatrix A = factor_->L;
  for (Eigen::Index v = 0; v < A.rows(); ++v) A.coeffRef(v, v) += factor_->epsilon;
  factor_->cholesky.setMode(Eigen::CholmodLDLt);
  factor_->cholesky.compute(A);
  if (factor_->cholesky.info() != Eigen::Success)
    throw Error(ErrorCode::solver, "the cone metric's Laplacian could not be factored (degenerate triangles?)");
}

ConeMetricSolver::~ConeMetricSolver() = default;

Eigen::VectorXd ConeMetricSolver::apply_inverse(const Eigen::VectorXd& x) const {
  Eigen::VectorXd y = factor_->cholesky.solve(x);
  if (factor_->cholesky.info() != Eigen::Success || !y.allFinite())
    throw Error(ErrorCode::solver, "the cone metric's solve failed");
  return y;
}

Eigen::VectorXd ConeMetricSolver::solve(const std::vector<double>& target_curvature,
                                        const std::vector<double>& surface_curvature) const {
  const std::size_t nV = soup_.points.size();
  QM_ASSERT(target_curvature.size() == nV && surface_curvature.size() == nV && nV > 0);
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(nV));
  for (std::size_t v = 0; v < nV; ++v) rhs[static_cast<Eigen::Index>(v)] = target_curvature[v] - surface_curvature[v];
  Eigen::VectorXd u = factor_->cholesky.solve(rhs);
  if (factor_->cholesky.info() != Eigen::Success || !u.allFinite())
    throw Error(ErrorCode::solver, "the cone metric's solve failed");
  // every vertex must turn the field as asked; one whose inner edges carry no
  // weight cannot turn it at all
  const Eigen::VectorXd residual = factor_->L * u - rhs;
  const double tolerance = std::max(turning_tolerance, max_held_u * factor_->epsilon);
  for (std::size_t v = 0; v < nV; ++v)
    if (std::abs(residual[static_cast<Eigen::Index>(v)]) > tolerance)
      throw Error(ErrorCode::unsupported, describe_vertex(soup_, static_cast<int>(v)) +
                                              ": its triangles cannot turn by " +
                                              std::to_string(target_curvature[v] * 180 / M_PI) +
                                              " degrees there (split them)");
  // such a vertex takes the mean of its neighbours' scale
  for (std::size_t v = 0; v < nV; ++v) {
    if (factor_->weight[static_cast<Eigen::Index>(v)] > factor_->epsilon || adjacency_.vertex_faces[v].empty()) continue;
    double sum = 0;
    int count = 0;
    for (int f : adjacency_.vertex_faces[v])
      for (int c : soup_.triangles[static_cast<std::size_t>(f)])
        if (static_cast<std::size_t>(c) != v) {
          sum += u[c];
          ++count;
        }
    u[static_cast<Eigen::Index>(v)] = sum / count;
  }
  u.array() += area_preserving_shift(soup_, u);
  return u;
}

Eigen::VectorXd cone_metric(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                            const std::vector<double>& target_curvature, const std::vector<double>& surface_curvature) {
  return ConeMetricSolver(soup, adjacency).solve(target_curvature, surface_curvature);
}

}  // namespace qm
