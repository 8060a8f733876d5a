#include "libquadmesh/param/form_choice.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>
#include <Eigen/Dense>

#include <cmath>
#include <limits>

namespace qm {

namespace {

/// Per triangle: area and the gradients of Re and Im of every basis form, in one
/// flat array (triangle f, form k: grad Re at 6 (f K + k), grad Im 3 after), so
/// that evaluating the objective allocates nothing per triangle.
struct Gradients {
  Eigen::Index K = 0;
  std::vector<double> area;
  std::vector<double> grad;
  std::size_t at(std::size_t f, Eigen::Index k) const {
    return 6 * (f * static_cast<std::size_t>(K) + static_cast<std::size_t>(k));
  }
  const double* re(std::size_t f, Eigen::Index k) const { return &grad[at(f, k)]; }
  const double* im(std::size_t f, Eigen::Index k) const { return &grad[at(f, k) + 3]; }
};

Gradients gradients(const TriangleSoup& soup, const std::vector<FaceMap>& basis) {
  const std::size_t nF = soup.triangles.size();
  Gradients g;
  g.K = static_cast<Eigen::Index>(basis.size());
  g.area.assign(nF, 0.0);
  g.grad.assign(6 * nF * basis.size(), 0.0);
  for (std::size_t f = 0; f < nF; ++f) {
    const Triangle& t = soup.triangles[f];
    const Vec3 e1 = soup.points[static_cast<std::size_t>(t[1])] - soup.points[static_cast<std::size_t>(t[0])];
    const Vec3 e2 = soup.points[static_cast<std::size_t>(t[2])] - soup.points[static_cast<std::size_t>(t[0])];
    const Vec3 n = e1.cross(e2);
    const double n2 = n.squaredNorm();
    g.area[f] = 0.5 * std::sqrt(n2);
    if (n2 <= 0) continue;
    // grad u = (du1 (e2 x n) + du2 (n x e1)) / |n|^2 for u linear with u(0) = 0
    const Vec3 b1 = e2.cross(n) / n2, b2 = n.cross(e1) / n2;
    for (Eigen::Index k = 0; k < g.K; ++k) {
      const CornerValues& c = basis[static_cast<std::size_t>(k)].corners[f];
      const Complex d1 = c[1] - c[0], d2 = c[2] - c[0];
      Eigen::Map<Vec3>(&g.grad[g.at(f, k)]) = d1.real() * b1 + d2.real() * b2;
      Eigen::Map<Vec3>(&g.grad[g.at(f, k) + 3]) = d1.imag() * b1 + d2.imag() * b2;
    }
  }
  return g;
}

/// The objective and its gradient with respect to c: the area-weighted variance
/// of log |h|^2 over the triangles.
double ratio(const Gradients& g, const Eigen::VectorXd& c, Eigen::VectorXd* gradient) {
  const Eigen::Index K = g.K;
  double total_area = 0, sum = 0, sum2 = 0;
  Eigen::VectorXd d1 = Eigen::VectorXd::Zero(K), d2 = d1, dl(K);
  for (std::size_t f = 0; f < g.area.size(); ++f) {
    const double a = g.area[f];
    if (a <= 0) continue;
    Vec3 gu = Vec3::Zero(), gv = Vec3::Zero();
    for (Eigen::Index k = 0; k < K; ++k) {
      gu += c[k] * Eigen::Map<const Vec3>(g.re(f, k));
      gv += c[k] * Eigen::Map<const Vec3>(g.im(f, k));
    }
    const double q = std::max(1e-300, 0.5 * (gu.squaredNorm() + gv.squaredNorm()));
    const double l = std::log(q);
    total_area += a;
    sum += a * l;
    sum2 += a * l * l;
    if (gradient) {
      for (Eigen::Index k = 0; k < K; ++k)
        dl[k] = (Eigen::Map<const Vec3>(g.re(f, k)).dot(gu) + Eigen::Map<const Vec3>(g.im(f, k)).dot(gv)) / q;
      d1 += a * dl;
      d2 += 2 * a * l * dl;
    }
  }
  if (total_area <= 0) return std::numeric_limits<double>::infinity();
  const double mean = sum / total_area;
  if (gradient) *gradient = d2 / total_area - 2 * mean * d1 / total_area;
  return sum2 / total_area - mean * mean;
}

// The descent on the unit sphere of coefficients (most_uniform_combination):
/// the first step (along the unit tangent), grown by step_growth after a success
/// and halved after a failure, down to min_step;
constexpr double initial_step = 0.1;
constexpr double step_growth = 1.5;
constexpr double min_step = 1e-8;
/// at most this many steps from each start; it stops at a tangent gradient below
/// min_tangent or a relative decrease of the ratio below min_relative_decrease.
constexpr int max_descent_steps = 60;
constexpr double min_tangent = 1e-10;
constexpr double min_relative_decrease = 1e-6;
/// Constraint rows (unit vectors) closer than this to dependent count once.
constexpr double constraint_rank_threshold = 1e-6;

}  // namespace

double uniformity_ratio(const TriangleSoup& soup, const std::vector<FaceMap>& basis,
                        const Eigen::VectorXd& coefficients) {
  return ratio(gradients(soup, basis), coefficients, nullptr);
}

Eigen::VectorXd most_uniform_combination(const TriangleSoup& soup, const std::vector<FaceMap>& basis) {
  QM_ASSERT(!basis.empty());
  const Gradients g = gradients(soup, basis);
  const Eigen::Index K = static_cast<Eigen::Index>(basis.size());
  Eigen::VectorXd best = Eigen::VectorXd::Unit(K, 0);
  double best_value = std::numeric_limits<double>::infinity();
  for (Eigen::Index start = 0; start < K; ++start) {
    Eigen::VectorXd c = Eigen::VectorXd::Unit(K, start), grad;
    double value = ratio(g, c, &grad);
    double step = initial_step;
    for (int it = 0; it < max_descent_steps && K > 1; ++it) {
      const double before = value;
      const Eigen::VectorXd tangent = grad - grad.dot(c) * c;  // on the sphere
      if (tangent.norm() < min_tangent) break;
      bool moved = false;
      while (step > min_step) {
        Eigen::VectorXd trial = (c - step * tangent / tangent.norm()).normalized();
        Eigen::VectorXd trial_grad;
        const double v = ratio(g, trial, &trial_grad);
        if (v < value) {
          c = trial;
          value = v;
          grad = trial_grad;
          step *= step_growth;
          moved = true;
          break;
        }
        step *= 0.5;
      }
      if (!moved || before - value < min_relative_decrease * std::abs(before)) break;
    }
    if (value < best_value) {
      best_value = value;
      best = c;
    }
  }
  return best;
}

Eigen::VectorXd most_uniform_combination(const TriangleSoup& soup, const std::vector<FaceMap>& basis,
                                         const Eigen::MatrixXd& constraints) {
  if (constraints.rows() == 0) return most_uniform_combination(soup, basis);
  QM_ASSERT(constraints.cols() == static_cast<Eigen::Index>(basis.size()));
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(constraints, Eigen::ComputeFullV);
  svd.setThreshold(constraint_rank_threshold);
  const Eigen::Index rank = svd.rank();
  const Eigen::Index free = constraints.cols() - rank;
  QM_ASSERT_MSG(free > 0, "most_uniform_combination: the constraints leave no form");
  const Eigen::MatrixXd null_space = svd.matrixV().rightCols(free);
  std::vector<FaceMap> reduced;
  for (Eigen::Index i = 0; i < free; ++i) reduced.push_back(linear_combination(basis, null_space.col(i)));
  return (null_space * most_uniform_combination(soup, reduced)).normalized();
}

}  // namespace qm
