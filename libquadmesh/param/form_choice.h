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

namespace qm {

/// R(c) above for the combination `coefficients` of `basis` (0: uniform |h|).
double uniformity_ratio(const TriangleSoup& soup, const std::vector<FaceMap>& basis,
                        const Eigen::VectorXd& coefficients);

/// The unit coefficient vector minimizing the objective: projected gradient
/// descent on the sphere from every basis vector, the best local minimum kept.
Eigen::VectorXd most_uniform_combination(const TriangleSoup& soup, const std::vector<FaceMap>& basis);

/// The same among the c with constraints * c = 0 (one row per linear condition,
/// e.g. boundary_tips.h): the objective is minimized over an orthonormal basis of
/// the constraints' null space. Precondition: that null space is not {0}.
Eigen::VectorXd most_uniform_combination(const TriangleSoup& soup, const std::vector<FaceMap>& basis,
                                         const Eigen::MatrixXd& constraints);

}  // namespace qm
