// Choosing h among the symmetric forms (method.md section 7, "--form auto").
//
// The objective of "auto" is the uniformity of |h|: the grid spacing in 3D is
// 1 / (s |h|), so a uniform |h| gives uniform quads. It minimizes the variance of
// log |h|^2 over the surface, R(c) = sum_f a_f (log q_f - mean)^2 / A, over real
// combinations h = sum_k c_k h_k (a_f the triangle areas, A their sum,
// q_f = |h_f|^2 = (|grad U|^2 + |grad V|^2) / 2 on triangle f, mean the
// area-weighted mean of log q). R = 0 exactly when |h| is constant; it is scale
// invariant and penalizes quads too large (|h| small) as much as too small.
#pragma once

#include "libquadmesh/param/face_map.h"

#include <vector>

namespace qm {

/// R(c) above, set up once for a basis: per triangle its area and the gradients of
/// Re and Im of every basis form (the objective is evaluated hundreds of times by
/// the descent; the gradients are O(triangles x forms) to compute).
class UniformityObjective {
 public:
  UniformityObjective(const TriangleSoup& soup, const std::vector<FaceMap>& basis);

  /// The number of coefficients.
  Eigen::Index dimension() const { return K_; }

  /// The same objective over the combinations basis * N, N a K x K' matrix
  /// (gradients combined linearly: no pass over the forms' values).
  UniformityObjective restricted(const Eigen::MatrixXd& N) const;

  /// R(c), and its gradient with respect to c when `gradient` is not null.
  double operator()(const Eigen::VectorXd& c, Eigen::VectorXd* gradient = nullptr) const;

 private:
  UniformityObjective() = default;
  std::size_t at(std::size_t f, Eigen::Index k) const {
    return 6 * (f * static_cast<std::size_t>(K_) + static_cast<std::size_t>(k));
  }
  Eigen::Index K_ = 0;
  std::vector<double> area_;
  std::vector<double> grad_;  ///< triangle f, form k: grad Re at at(f, k), grad Im 3 after
};

/// R(c) above for the combination `coefficients` of `basis` (0: uniform |h|).
double uniformity_ratio(const TriangleSoup& soup, const std::vector<FaceMap>& basis,
                        const Eigen::VectorXd& coefficients);

/// The unit coefficient vector minimizing the objective: projected gradient
/// descent on the sphere from every basis vector, the best local minimum kept.
Eigen::VectorXd most_uniform_combination(const TriangleSoup& soup, const std::vector<FaceMap>& basis);
Eigen::VectorXd most_uniform_combination(const UniformityObjective& objective);

/// The same among the c with constraints * c = 0 (one row per linear condition,
/// e.g. boundary_tips.h): the objective is minimized over an orthonormal basis of
/// the constraints' null space. Precondition: that null space is not {0}.
Eigen::VectorXd most_uniform_combination(const TriangleSoup& soup, const std::vector<FaceMap>& basis,
                                         const Eigen::MatrixXd& constraints);
Eigen::VectorXd most_uniform_combination(const UniformityObjective& objective, const Eigen::MatrixXd& constraints);

}  // namespace qm
