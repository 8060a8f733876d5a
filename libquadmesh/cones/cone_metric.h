// The flat cone metric e^(2u) g with prescribed cones (method.md section 11;
// [Ben-Chen, Gotsman, Bunin 2008], [Sawhney & Crane 2017]), linearized: one solve
// with the cotan Laplacian,
//   L u = K_target - K,
// where K is the surface's curvature per vertex (angle defect inside, geodesic
// curvature on the boundary: cone_set.h vertex_curvature) and K_target the cones'
// (target_curvature). L is the cotan Laplacian over the inner edges,
// (L u)_i = sum_j w_ij (u_i - u_j), w_ij = (cot alpha + cot beta) / 2: the sum
// of the discrete *du across the inner edges around a vertex, which is what turns
// the cross field there (cross_field.h), so that the field turns by exactly the
// cones' angles at every vertex, the boundary ones included (a boundary edge
// carries no transport; with it, as in the Neumann Laplacian, the field would miss
// the boundary by up to degrees). The right side sums to 0 by Gauss-Bonnet, so u is
// fixed up to a constant, chosen so that the metric keeps the surface's area:
//   sum_f area_f e^(2 u_f) = sum_f area_f   (u_f the mean over f's corners).
// Quad size, at a uniform target h, is h e^(-u).
#pragma once

#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace qm {

/// The factored Laplacian, for many cone sets on one surface (cone placement). It
/// keeps the metrics it solved for (up to remembered_values doubles of them, the
/// oldest dropped first) and gives a target asked for again the same u without a
/// solve: the placement weighs one cone set more than once (a pair settled, then
/// measured), and a placement made again away from some cones repeats the steps
/// of the first up to where it must differ (bunny-open: 170 of 560 solves). Not
/// to be used by two threads at once.
class ConeMetricSolver {
 public:
  /// The Laplacian is factored at the first solve, which throws qm::Error (solver)
  /// if it cannot be.
  ConeMetricSolver(const TriangleSoup& soup, const SurfaceAdjacency& adjacency);
  ~ConeMetricSolver();
  ConeMetricSolver(const ConeMetricSolver&) = delete;
  ConeMetricSolver& operator=(const ConeMetricSolver&) = delete;
  /// u for these targets (see cone_metric below); with a quad size tip_size > 0,
  /// the log scale the sizes are judged by: u plus tip_scale_offset (tip_scale.h).
  Eigen::VectorXd solve(const std::vector<double>& target_curvature, const std::vector<double>& surface_curvature,
                        double tip_size = 0) const;
  /// (L + epsilon I)^-1 x: u up to its constant, for a right side x that sums to 0.
  Eigen::VectorXd apply_inverse(const Eigen::VectorXd& x) const;
  /// The surface it was made for.
  const TriangleSoup& soup() const { return soup_; }
  const SurfaceAdjacency& adjacency() const { return adjacency_; }

 private:
  struct Factor;
  struct Remembered;
  /// u as solve() without a tip size (remembered by its targets).
  Eigen::VectorXd metric(const std::vector<double>& target_curvature,
                         const std::vector<double>& surface_curvature) const;
  const Factor& factor() const;
  const TriangleSoup& soup_;
  const SurfaceAdjacency& adjacency_;
  mutable std::unique_ptr<Factor> factor_;
  std::unique_ptr<Remembered> remembered_;
};

/// u per vertex. A vertex whose inner edges carry no weight (a corner in one
/// triangle, or in two right triangles) takes the mean of its neighbours' u. Precondition: the targets satisfy Gauss-Bonnet against the
/// surface (require_gauss_bonnet); the soup is connected. Throws qm::Error:
/// unsupported when such a vertex is asked to turn by other than its own
/// angle; solver if the Laplacian cannot be factored.
Eigen::VectorXd cone_metric(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                            const std::vector<double>& target_curvature, const std::vector<double>& surface_curvature);

/// The discrete *du across the inner edge a->b: w_ab (u_b - u_a), from the
/// cotangents at the third corners of the edge's two triangles.
inline double conformal_rotation(double cot_opposite_f, double cot_opposite_g, double u_a, double u_b) {
  return 0.5 * (cot_opposite_f + cot_opposite_g) * (u_b - u_a);
}

}  // namespace qm
