#include "libquadmesh/forms/harmonic_basis.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/internal/cholmod_ordering.h"
#include "libquadmesh/forms/internal/edge_laplacian.h"

#include <Eigen/CholmodSupport>

namespace qm {

namespace {

using Cholesky = Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower>;

/// One factored block of L: the vertices of D it solves for, as unknown `index`
/// with coefficient `sign` (f(v) = sign * x[index]); index < 0: f(v) = 0 there.
struct Block {
  std::vector<int> index;
  std::vector<double> sign;
  Eigen::Index unknowns = 0;
  Cholesky cholesky;
};

/// The terms w_e (s_a x_a - s_b x_b)^2 of the energy of D restricted to a block.
std::vector<internal::EdgeTerm> block_terms(const Mesh& mesh, const Eigen::VectorXd& weights, const Block& b) {
  std::vector<internal::EdgeTerm> terms;
  terms.reserve(mesh.number_of_edges());
  for (Mesh::Edge_index e : mesh.edges()) {
    const Mesh::Halfedge_index h = mesh.halfedge(e, 0);
    const auto s = static_cast<std::size_t>(mesh.source(h)), t = static_cast<std::size_t>(mesh.target(h));
    terms.push_back({b.index[s], b.index[t], weights[static_cast<Eigen::Index>(e)], b.sign[s] * b.sign[t]});
  }
  return terms;
}

void factor(const Mesh& mesh, const Eigen::VectorXd& weights, Block& b) {
  const SparseMatrix A = internal::edge_laplacian_lower(b.unknowns, block_terms(mesh, weights, b));
  internal::use_amd_ordering(b.cholesky);
  b.cholesky.compute(A);
  if (b.cholesky.info() != Eigen::Success)
    throw Error(ErrorCode::solver,
                "the cotangent Laplacian could not be factored (not positive definite once a "
                "vertex is pinned: degenerate triangles?)");
}

/// All vertices, vertex 0 pinned.
void pinned_block(std::size_t n, Block& b) {
  b.index.resize(n);
  b.sign.assign(n, 1.0);
  b.index[0] = -1;
  for (std::size_t v = 1; v < n; ++v) b.index[v] = static_cast<int>(v - 1);
  b.unknowns = static_cast<Eigen::Index>(n) - 1;
}

/// The even functions: v+ and v- share unknown v (S's vertex), S's vertex 0 pinned.
void even_block(const DoubledSurface& d, Block& b) {
  const std::size_t n = d.vertex_mirror.size();
  b.index.resize(n);
  b.sign.assign(n, 1.0);
  for (std::size_t v = 0; v < n; ++v) {
    const std::size_t s = v < d.input_vertices ? v : static_cast<std::size_t>(d.vertex_mirror[v]);
    b.index[v] = static_cast<int>(s) - 1;  // S's vertex 0 -> -1
  }
  b.unknowns = static_cast<Eigen::Index>(d.input_vertices) - 1;
}

/// The odd functions: f(v+) = -f(v-) = k(v) on S's interior vertices, 0 on its boundary.
void odd_block(const DoubledSurface& d, Block& b) {
  const std::size_t n = d.vertex_mirror.size();
  b.index.assign(n, -1);
  b.sign.assign(n, 1.0);
  int next = 0;
  for (std::size_t v = 0; v < d.input_vertices; ++v) {
    const auto m = static_cast<std::size_t>(d.vertex_mirror[v]);
    if (m == v) continue;
    b.index[v] = b.index[m] = next++;
    b.sign[m] = -1.0;
  }
  b.unknowns = next;
}

/// f += the block's part of the solution of L f = rhs: x = A^-1 R^T rhs, f += R x
/// (R the block's restriction: f(v) = sign(v) x[index(v)]).
void solve_block(const Block& b, const Eigen::MatrixXd& rhs, Eigen::MatrixXd& f) {
  if (b.unknowns == 0) return;
  Eigen::MatrixXd r = Eigen::MatrixXd::Zero(b.unknowns, rhs.cols());
  for (Eigen::Index j = 0; j < rhs.cols(); ++j)
    for (std::size_t v = 0; v < b.index.size(); ++v)
      if (b.index[v] >= 0) r(b.index[v], j) += b.sign[v] * rhs(static_cast<Eigen::Index>(v), j);
  const Eigen::MatrixXd x = b.cholesky.solve(r);
  if (b.cholesky.info() != Eigen::Success)
    throw Error(ErrorCode::solver, "back-substitution with the cotangent Laplacian failed");
  for (Eigen::Index j = 0; j < rhs.cols(); ++j)
    for (std::size_t v = 0; v < b.index.size(); ++v)
      if (b.index[v] >= 0) f(static_cast<Eigen::Index>(v), j) += b.sign[v] * x(b.index[v], j);
}

bool is_identity(const std::vector<int>& mirror) {
  for (std::size_t v = 0; v < mirror.size(); ++v)
    if (mirror[v] != static_cast<int>(v)) return false;
  return true;
}

}  // namespace

struct HarmonicSolver::Impl {
  SparseMatrix d0;
  Eigen::VectorXd weights;
  std::vector<std::unique_ptr<Block>> blocks;  ///< their solutions add up to f (Cholesky can not move)
};

HarmonicSolver::HarmonicSolver(const Mesh& mesh, const Eigen::VectorXd& weights)
    : impl_(std::make_unique<Impl>()) {
  impl_->d0 = exterior_derivative_0(mesh);
  impl_->weights = weights;
  impl_->blocks.push_back(std::make_unique<Block>());
  pinned_block(mesh.number_of_vertices(), *impl_->blocks[0]);
  factor(mesh, weights, *impl_->blocks[0]);
}

HarmonicSolver::HarmonicSolver(const DoubledSurface& d, const Eigen::VectorXd& weights)
    : impl_(std::make_unique<Impl>()) {
  impl_->d0 = exterior_derivative_0(d.mesh);
  impl_->weights = weights;
  if (is_identity(d.vertex_mirror)) {
    impl_->blocks.push_back(std::make_unique<Block>());
    pinned_block(d.mesh.number_of_vertices(), *impl_->blocks[0]);
  } else {
    impl_->blocks.push_back(std::make_unique<Block>());
    impl_->blocks.push_back(std::make_unique<Block>());
    even_block(d, *impl_->blocks[0]);
    odd_block(d, *impl_->blocks[1]);
  }
  for (const auto& b : impl_->blocks) factor(d.mesh, weights, *b);
}

HarmonicSolver::~HarmonicSolver() = default;

Eigen::MatrixXd HarmonicSolver::harmonic(const Eigen::MatrixXd& eta) const {
  const Eigen::MatrixXd rhs = -(impl_->d0.transpose() * (impl_->weights.asDiagonal() * eta));
  Eigen::MatrixXd f = Eigen::MatrixXd::Zero(rhs.rows(), eta.cols());
  for (const auto& b : impl_->blocks) solve_block(*b, rhs, f);
  return eta + impl_->d0 * f;
}

double HarmonicSolver::coclosedness(const Eigen::MatrixXd& omega) const {
  const Eigen::MatrixXd flux = impl_->weights.asDiagonal() * omega;
  const double scale = flux.cwiseAbs().maxCoeff();
  if (scale == 0) return 0;
  return (impl_->d0.transpose() * flux).cwiseAbs().maxCoeff() / scale;
}

}  // namespace qm
