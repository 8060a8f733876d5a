#include "libquadmesh/param/barrier_untangle.h"

#include <Eigen/Dense>
#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm {

/// safely_positive's margin: twice the image area must exceed the longest image
/// edge times this many units of the extraction's fixed-point lattice (2^-30 cells).
constexpr double safe_area_units = 64;

bool safely_positive(const CornerValues& c) {
  const double longest = std::max({std::abs(c[1] - c[0]), std::abs(c[2] - c[1]), std::abs(c[0] - c[2])});
  return image_area2(c) > safe_area_units * std::ldexp(1.0, -30) * longest;
}

namespace {

/// Inverse of the 2x2 matrix of a triangle's edge vectors p1 - p0, p2 - p0 in a
/// frame of its plane, and its area. Degenerate triangles get an equilateral
/// reference of the mean edge length (so they are asked to open up, not to vanish).
struct Reference {
  Eigen::Matrix2d inverse;
  double area = 0;
};

/// A triangle with twice its area below this times its first edge squared is
/// degenerate (dimensionless).
constexpr double degenerate_area_ratio = 1e-12;

Reference reference_of(const TriangleSoup& soup, int f) {
  const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
  const Vec3 e1 = soup.points[static_cast<std::size_t>(t[1])] - soup.points[static_cast<std::size_t>(t[0])];
  const Vec3 e2 = soup.points[static_cast<std::size_t>(t[2])] - soup.points[static_cast<std::size_t>(t[0])];
  const double l = e1.norm(), twice_area = e1.cross(e2).norm();
  Eigen::Matrix2d R;
  if (l > 0 && twice_area > degenerate_area_ratio * l * l) {
    R << l, e1.dot(e2) / l, 0, twice_area / l;
  } else {
    const double m = std::max((e1.norm() + e2.norm() + (e2 - e1).norm()) / 3, 1e-300);
    R << m, 0.5 * m, 0, 0.5 * std::sqrt(3.0) * m;
  }
  return {R.inverse(), 0.5 * R.determinant()};
}

double chi(double d, double eps) { return 0.5 * (d + std::sqrt(eps * eps + d * d)); }
double chi_derivative(double d, double eps) { return 0.5 * (1 + d / std::sqrt(eps * eps + d * d)); }

/// The free vertices of a set of faces, their degrees of freedom and the energy.
class RegionEnergy {
 public:
  RegionEnergy(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& param,
               const std::vector<int>& faces, const std::vector<char>& pinned)
      : soup_(soup), param_(param), faces_(faces) {
    std::vector<char> in_region(soup.triangles.size(), 0);
    for (int f : faces) in_region[static_cast<std::size_t>(f)] = 1;
    dof_.assign(soup.points.size(), -1);
    along_u_.assign(soup.points.size(), 0);
    for (int f : faces)
      for (int v : soup.triangles[static_cast<std::size_t>(f)]) {
        const auto vi = static_cast<std::size_t>(v);
        if (dof_[vi] != -1 || pinned[vi] == 1) continue;
        bool inner = true;  // every face around v is in the region
        for (int g : adjacency.vertex_faces[vi]) inner = inner && in_region[static_cast<std::size_t>(g)];
        if (!inner) continue;
        dof_[vi] = dofs_;
        along_u_[vi] = adjacency.boundary_vertex[vi];
        free_.push_back(v);
        dofs_ += adjacency.boundary_vertex[vi] ? 1 : 2;
      }
    double image = 0, reference = 0;
    for (int f : faces) {
      references_.push_back(reference_of(soup, f));
      image += std::abs(image_area2(param.corners[static_cast<std::size_t>(f)])) / 2;
      reference += references_.back().area;
    }
    // det J of order 1 on average, so that eps has one meaning for every region
    scale_ = image > 0 ? std::sqrt(reference / image) : 1.0;
    total_area_ = reference;
  }

  int dofs() const { return dofs_; }
  const std::vector<int>& free_vertices() const { return free_; }

  /// Displacement of vertex v (image units) for the variables x.
  Complex moved(const Eigen::VectorXd& x, int v) const {
    const int k = dof_[static_cast<std::size_t>(v)];
    if (k < 0) return 0;
    return along_u_[static_cast<std::size_t>(v)] ? Complex(x[k], 0) : Complex(x[k], x[k + 1]);
  }

  /// Smallest det J over the region for x.
  double min_det(const Eigen::VectorXd& x) const {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < faces_.size(); ++i) d = std::min(d, jacobian(x, i).determinant());
    return d;
  }

  /// Energy for x with barrier parameter eps; gradient into `grad`.
  double energy(const Eigen::VectorXd& x, Eigen::VectorXd& grad, double eps) const {
    grad.setZero(x.size());
    double e = 0;
    for (std::size_t i = 0; i < faces_.size(); ++i) {
      const Eigen::Matrix2d J = jacobian(x, i);
      const double w = references_[i].area / total_area_;
      const double D = J.determinant(), N = J.squaredNorm(), c = chi(D, eps);
      e += w * N / c;
      // dE/dJ, then dJ/dA = (.) M^T with A the image edge matrix, M = R^-1
      Eigen::Matrix2d cofactor;
      cofactor << J(1, 1), -J(1, 0), -J(0, 1), J(0, 0);
      const Eigen::Matrix2d dJ = w * (2 * J / c - N * chi_derivative(D, eps) / (c * c) * cofactor);
      const Eigen::Matrix2d dA = scale_ * dJ * references_[i].inverse.transpose();
      const Triangle& t = soup_.triangles[static_cast<std::size_t>(faces_[i])];
      const Eigen::Vector2d g1 = dA.col(0), g2 = dA.col(1), g0 = -(g1 + g2);
      const Eigen::Vector2d g[3] = {g0, g1, g2};
      for (int k = 0; k < 3; ++k) {
        const int d = dof_[static_cast<std::size_t>(t[k])];
        if (d < 0) continue;
        grad[d] += g[k][0];
        if (!along_u_[static_cast<std::size_t>(t[k])]) grad[d + 1] += g[k][1];
      }
    }
    return e;
  }

 private:
  Eigen::Matrix2d jacobian(const Eigen::VectorXd& x, std::size_t i) const {
    const int f = faces_[i];
    const Triangle& t = soup_.triangles[static_cast<std::size_t>(f)];
    Complex u[3];
    for (int k = 0; k < 3; ++k) u[k] = param_.corners[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)] + moved(x, t[k]);
    Eigen::Matrix2d A;
    A << (u[1] - u[0]).real(), (u[2] - u[0]).real(), (u[1] - u[0]).imag(), (u[2] - u[0]).imag();
    return scale_ * A * references_[i].inverse;
  }

  const TriangleSoup& soup_;
  const FaceMap& param_;
  std::vector<int> faces_;
  std::vector<int> dof_;
  std::vector<char> along_u_;
  std::vector<int> free_;
  std::vector<Reference> references_;
  int dofs_ = 0;
  double scale_ = 1, total_area_ = 1;
};

/// The faces within `rings` vertex rings of `seeds`, split into the connected
/// pieces (faces sharing a vertex) that can be untangled separately.
std::vector<std::vector<int>> regions_around(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                             const std::vector<int>& seeds, int rings) {
  std::vector<char> in(soup.triangles.size(), 0);
  std::vector<int> front = seeds;
  for (int f : seeds) in[static_cast<std::size_t>(f)] = 1;
  for (int r = 0; r < rings; ++r) {
    std::vector<int> next;
    for (int f : front)
      for (int v : soup.triangles[static_cast<std::size_t>(f)])
        for (int g : adjacency.vertex_faces[static_cast<std::size_t>(v)])
          if (!in[static_cast<std::size_t>(g)]) {
            in[static_cast<std::size_t>(g)] = 1;
            next.push_back(g);
          }
    front.swap(next);
  }
  std::vector<std::vector<int>> pieces;
  std::vector<char> seen(soup.triangles.size(), 0);
  for (std::size_t start = 0; start < in.size(); ++start) {
    if (!in[start] || seen[start]) continue;
    std::vector<int> piece{static_cast<int>(start)};
    seen[start] = 1;
    for (std::size_t i = 0; i < piece.size(); ++i)
      for (int v : soup.triangles[static_cast<std::size_t>(piece[i])])
        for (int g : adjacency.vertex_faces[static_cast<std::size_t>(v)])
          if (in[static_cast<std::size_t>(g)] && !seen[static_cast<std::size_t>(g)]) {
            seen[static_cast<std::size_t>(g)] = 1;
            piece.push_back(g);
          }
    pieces.push_back(std::move(piece));
  }
  return pieces;
}

// The optimisation of one region (Garanzha et al.'s eps schedule):
/// eps starts at least here (determinant units: image area over reference area)...
constexpr double min_initial_eps = 1e-3;
/// ...then follows the smallest determinant D: with sigma = max(1 - E / E_previous,
/// min_sigma) and mu = (1 - sigma) chi(D, eps), eps becomes min(2 sqrt(mu (mu - D)),
/// eps_shrink eps) when D < mu, else eps_drop eps.
constexpr double min_sigma = 0.1;
constexpr double eps_shrink = 0.7;
constexpr double eps_drop = 0.1;
/// L-BFGS per round: stop at this gradient norm (absolute and relative), or after so many iterations.
constexpr double lbfgs_gradient_tolerance = 1e-9;
constexpr int lbfgs_iterations = 100;
/// Rounds at most; a round raises D "enough" when by min_progress |D_best|, and
/// stall_rounds rounds without that give the region up.
constexpr int max_rounds = 60;
constexpr int stall_rounds = 8;
constexpr double min_progress = 0.01;

/// Minimizes the barrier energy over one region with shrinking eps; commits the
/// moves to `param` when every triangle of the region ends up positive.
bool untangle_region(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                     const std::vector<int>& faces, const std::vector<char>& pinned, std::size_t& moved) {
  const RegionEnergy region(soup, adjacency, param, faces, pinned);
  if (region.dofs() == 0) return false;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(region.dofs());
  Eigen::VectorXd grad;
  double D = region.min_det(x);
  double eps = std::max(min_initial_eps, 2 * std::abs(D));
  double previous = region.energy(x, grad, eps);
  LBFGSpp::LBFGSParam<double> settings;
  settings.epsilon = lbfgs_gradient_tolerance;
  settings.epsilon_rel = lbfgs_gradient_tolerance;
  settings.max_iterations = lbfgs_iterations;
  LBFGSpp::LBFGSSolver<double> solver(settings);
  // the region's corners moved by y, face by face
  auto displaced = [&](const Eigen::VectorXd& y) {
    std::vector<CornerValues> corners;
    for (int f : faces) {
      CornerValues c = param.corners[static_cast<std::size_t>(f)];
      for (int k = 0; k < 3; ++k)
        c[static_cast<std::size_t>(k)] += region.moved(y, soup.triangles[static_cast<std::size_t>(f)][k]);
      corners.push_back(c);
    }
    return corners;
  };
  auto untangled = [&](const std::vector<CornerValues>& corners) {
    return std::all_of(corners.begin(), corners.end(), safely_positive);
  };
  // a region whose smallest determinant stops rising in stall_rounds rounds cannot be
  // untangled with its outer ring where it is: a larger region is tried instead
  double best_D = D;
  int stalled = 0;
  for (int round = 0; round < max_rounds && stalled < stall_rounds && !(D > 0 && untangled(displaced(x))); ++round) {
    // the line search may stop on a trial point: keep the best point evaluated
    Eigen::VectorXd best = x;
    double best_energy = region.energy(x, grad, eps);
    auto f = [&](const Eigen::VectorXd& y, Eigen::VectorXd& g) {
      const double e = region.energy(y, g, eps);
      if (e < best_energy) {
        best_energy = e;
        best = y;
      }
      return e;
    };
    double fx = 0;
    try {
      solver.minimize(f, x, fx);
    } catch (const std::exception&) {
      // no further descent from here: the best point so far stands
    }
    x = best;
    D = region.min_det(x);
    // eps follows the smallest determinant (Garanzha et al.'s update)
    const double sigma = std::max(1 - best_energy / previous, min_sigma);
    const double mu = (1 - sigma) * chi(D, eps);
    previous = best_energy;
    eps = D < mu ? std::min(2 * std::sqrt(mu * (mu - D)), eps_shrink * eps) : eps_drop * eps;
    if (D > best_D + min_progress * std::abs(best_D)) {
      best_D = D;
      stalled = 0;
    } else {
      ++stalled;
    }
  }
  const std::vector<CornerValues> corners = displaced(x);
  if (!untangled(corners)) return false;
  for (std::size_t i = 0; i < faces.size(); ++i) param.corners[static_cast<std::size_t>(faces[i])] = corners[i];
  moved += region.free_vertices().size();
  return true;
}

}  // namespace

UntangleReport untangle_by_barrier(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                                   const std::vector<char>& pinned) {
  UntangleReport report = unmoved_report(param);
  for (int rings : {2, 4, 8, 16}) {
    if (std::all_of(param.corners.begin(), param.corners.end(), safely_positive)) break;
    ++report.rounds;
    std::vector<int> seeds;
    for (std::size_t f = 0; f < param.corners.size(); ++f)
      if (!safely_positive(param.corners[f])) seeds.push_back(static_cast<int>(f));
    for (const std::vector<int>& faces : regions_around(soup, adjacency, seeds, rings))
      untangle_region(soup, adjacency, param, faces, pinned, report.moved_vertices);
    report.flipped_after = count_flipped(param);
  }
  return report;
}

}  // namespace qm
