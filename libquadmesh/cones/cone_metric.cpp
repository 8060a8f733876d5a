#include "libquadmesh/cones/cone_metric.h"

#include "libquadmesh/cones/internal/face_geometry.h"
#include "libquadmesh/cones/tip_scale.h"
#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <deque>
#include <optional>

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

/// Per triangle, its area.
std::vector<double> triangle_areas(const TriangleSoup& soup) {
  std::vector<double> out;
  out.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) {
    const Vec3& p = soup.points[static_cast<std::size_t>(t[0])];
    out.push_back(0.5 * (soup.points[static_cast<std::size_t>(t[1])] - p)
                            .cross(soup.points[static_cast<std::size_t>(t[2])] - p)
                            .norm());
  }
  return out;
}

/// The constant that makes sum_f area_f e^(2 u_f) equal the surface's area
/// (`areas`: triangle_areas).
double area_preserving_shift(const TriangleSoup& soup, const std::vector<double>& areas, const Eigen::VectorXd& u) {
  double area = 0, scaled = 0;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const double uf = (u[t[0]] + u[t[1]] + u[t[2]]) / 3.0;
    area += areas[f];
    scaled += areas[f] * std::exp(2 * uf);
  }
  return scaled > 0 ? -0.5 * std::log(scaled / area) : 0.0;
}

}  // namespace

namespace {

/// The most doubles of u a solver remembers (128 MB): about 460 metrics of a
/// 36,000-vertex scan.
constexpr std::size_t remembered_values = std::size_t{16} << 20;

/// A target with nonzero values at more than 1 / max_key_share of the vertices
/// (spread over the surface) is not kept.
constexpr std::size_t max_key_share = 4;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

}  // namespace

/// The metrics solved for, oldest first, each under its target's nonzero values,
/// compared bit for bit (the boundary's turns and the cones: a few per cent of the
/// vertices), for one surface curvature (the first given; the placement gives no
/// other): a metric asked for again is the one the solve gave. Targets spread
/// over the surface are not kept.
struct ConeMetricSolver::Remembered {
  using Key = std::vector<std::pair<std::size_t, double>>;
  struct Entry {
    Key key;
    Eigen::VectorXd u;
  };
  std::vector<double> surface;
  std::deque<Entry> entries;

  /// The key of a target on `surface_curvature`; nothing when it is not kept.
  std::optional<Key> key_of(const std::vector<double>& target, const std::vector<double>& surface_curvature) {
    if (surface.empty()) surface = surface_curvature;
    if (surface.size() != surface_curvature.size() ||
        std::memcmp(surface.data(), surface_curvature.data(), sizeof(double) * surface.size()) != 0)
      return std::nullopt;
    Key key;
    for (std::size_t v = 0; v < target.size(); ++v)
      if (target[v] != 0.0 || std::signbit(target[v])) {
        if (key.size() >= target.size() / max_key_share) return std::nullopt;
        key.push_back({v, target[v]});
      }
    return key;
  }

  const Eigen::VectorXd* find(const Key& key) const {
    const auto same = [](const std::pair<std::size_t, double>& a, const std::pair<std::size_t, double>& b) {
      return a.first == b.first && same_bits(a.second, b.second);
    };
    for (const Entry& e : entries)
      if (std::equal(e.key.begin(), e.key.end(), key.begin(), key.end(), same)) return &e.u;
    return nullptr;
  }

  void add(Key key, const Eigen::VectorXd& u) {
    const auto per_entry = static_cast<std::size_t>(u.size()) + 2 * key.size();
    if (per_entry > remembered_values) return;
    while (!entries.empty() && (entries.size() + 1) * per_entry > remembered_values) entries.pop_front();
    entries.push_back({std::move(key), u});
  }
};

struct ConeMetricSolver::Factor {
  std::vector<double> areas;  ///< per triangle (the area-preserving shift's)
  SparseMatrix L;
  Eigen::VectorXd weight;
  double epsilon = 0;
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> cholesky;
};

ConeMetricSolver::ConeMetricSolver(const TriangleSoup& soup, const SurfaceAdjacency& adjacency)
    : soup_(soup), adjacency_(adjacency), remembered_(std::make_unique<Remembered>()) {}

const ConeMetricSolver::Factor& ConeMetricSolver::factor() const {
  if (factor_) return *factor_;
  auto f = std::make_unique<Factor>();
  f->areas = triangle_areas(soup_);
  f->L = inner_edge_laplacian(soup_, adjacency_);
  // L is singular (constants; and a corner whose inner edges all have weight 0):
  // a faint diagonal makes it definite without moving the solution measurably
  f->weight = transport_weight(f->L);
  f->epsilon = regularization * std::max(f->weight.mean(), 1e-300);
  SparseMatrix A = f->L;
  for (Eigen::Index v = 0; v < A.rows(); ++v) A.coeffRef(v, v) += f->epsilon;
  f->cholesky.setMode(Eigen::CholmodLDLt);
  f->cholesky.compute(A);
  if (f->cholesky.info() != Eigen::Success)
    throw Error(ErrorCode::solver, "the cone metric's Laplacian could not be factored (degenerate triangles?)");
  factor_ = std::move(f);
  return *factor_;
}

ConeMetricSolver::~ConeMetricSolver() = default;

Eigen::VectorXd ConeMetricSolver::apply_inverse(const Eigen::VectorXd& x) const {
  const Factor& f = factor();
  Eigen::VectorXd y = f.cholesky.solve(x);
  if (f.cholesky.info() != Eigen::Success || !y.allFinite())
    throw Error(ErrorCode::solver, "the cone metric's solve failed");
  return y;
}

Eigen::VectorXd ConeMetricSolver::solve(const std::vector<double>& target_curvature,
                                        const std::vector<double>& surface_curvature, double tip_size) const {
  Eigen::VectorXd u = metric(target_curvature, surface_curvature);
  if (tip_size > 0)
    u += tip_scale_offset(soup_, adjacency_, acute_tips(soup_, adjacency_, target_curvature, surface_curvature, tip_size),
                          u);
  return u;
}

Eigen::VectorXd ConeMetricSolver::metric(const std::vector<double>& target_curvature,
                                         const std::vector<double>& surface_curvature) const {
  const std::size_t nV = soup_.points.size();
  QM_ASSERT(target_curvature.size() == nV && surface_curvature.size() == nV && nV > 0);
  std::optional<Remembered::Key> key = remembered_->key_of(target_curvature, surface_curvature);
  if (key)
    if (const Eigen::VectorXd* known = remembered_->find(*key)) return *known;
  Eigen::VectorXd rhs(static_cast<Eigen::Index>(nV));
  for (std::size_t v = 0; v < nV; ++v) rhs[static_cast<Eigen::Index>(v)] = target_curvature[v] - surface_curvature[v];
  const Factor& f = factor();
  Eigen::VectorXd u = f.cholesky.solve(rhs);
  if (f.cholesky.info() != Eigen::Success || !u.allFinite())
    throw Error(ErrorCode::solver, "the cone metric's solve failed");
  // every vertex must turn the field as asked; one whose inner edges carry no
  // weight cannot turn it at all
  const Eigen::VectorXd residual = f.L * u - rhs;
  const double tolerance = std::max(turning_tolerance, max_held_u * f.epsilon);
  for (std::size_t v = 0; v < nV; ++v)
    if (std::abs(residual[static_cast<Eigen::Index>(v)]) > tolerance)
      throw Error(ErrorCode::unsupported, describe_vertex(soup_, static_cast<int>(v)) +
                                              ": its triangles cannot turn by " +
                                              std::to_string(target_curvature[v] * 180 / M_PI) +
                                              " degrees there (split them)");
  // such a vertex takes the mean of its neighbours' scale
  for (std::size_t v = 0; v < nV; ++v) {
    if (f.weight[static_cast<Eigen::Index>(v)] > f.epsilon || adjacency_.vertex_faces[v].empty()) continue;
    double sum = 0;
    int count = 0;
    for (int face : adjacency_.vertex_faces[v])
      for (int c : soup_.triangles[static_cast<std::size_t>(face)])
        if (static_cast<std::size_t>(c) != v) {
          sum += u[c];
          ++count;
        }
    u[static_cast<Eigen::Index>(v)] = sum / count;
  }
  u.array() += area_preserving_shift(soup_, f.areas, u);
  if (key) remembered_->add(std::move(*key), u);
  return u;
}

Eigen::VectorXd cone_metric(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                            const std::vector<double>& target_curvature, const std::vector<double>& surface_curvature) {
  return ConeMetricSolver(soup, adjacency).solve(target_curvature, surface_curvature);
}

}  // namespace qm
