#include "libquadmesh/param/boundary_tips.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/param/form_choice.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace qm {

std::vector<BoundaryTip> boundary_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                       double min_angle) {
  std::vector<BoundaryTip> tips;
  for (const auto& loop : adjacency.boundary_loops) {
    BoundaryTip widest;
    for (int v : loop) {
      if (adjacency.vertex_faces[static_cast<std::size_t>(v)].empty()) continue;
      const VertexRing ring = vertex_ring(soup, adjacency, v);
      const std::vector<double> angles = ring_angles(soup, ring, v);
      const double angle = std::accumulate(angles.begin(), angles.end(), 0.0);
      if (angle >= min_angle && angle > widest.angle) widest = {v, angle};
    }
    if (widest.vertex >= 0) tips.push_back(widest);
  }
  std::stable_sort(tips.begin(), tips.end(),
                   [](const BoundaryTip& a, const BoundaryTip& b) { return a.angle > b.angle; });
  return tips;
}

Eigen::RowVectorXd tip_leading_coefficient(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                           const std::vector<FaceMap>& basis, int tip) {
  const VertexRing ring = vertex_ring(soup, adjacency, tip);
  QM_ASSERT_MSG(ring.boundary, "tip_leading_coefficient: not a boundary vertex");
  const std::vector<double> angles = ring_angles(soup, ring, tip);
  const double theta = std::accumulate(angles.begin(), angles.end(), 0.0);
  QM_ASSERT(theta > 0);
  const double exponent = M_PI / theta;  // z = w^exponent
  // the flattened ring: neighbour j at polar angle phi_j, distance r_j
  const std::size_t J = ring.neighbours.size();
  constexpr int terms = 3;
  // rows 2j, 2j+1: Re and Im of  sum_n f_n z_j^(n+1) / (n+1) = value of the form on p -> n_j
  Eigen::MatrixXd A(2 * J, terms);
  std::vector<double> weight(J);
  double phi = 0;
  for (std::size_t j = 0; j < J; ++j) {
    const Vec3 e = soup.points[static_cast<std::size_t>(ring.neighbours[j])] - soup.points[static_cast<std::size_t>(tip)];
    const double rz = std::pow(e.norm(), exponent);  // |z_j|
    weight[j] = rz > 0 ? 1.0 / rz : 0.0;
    for (int n = 0; n < terms; ++n) {
      const Complex zn = std::polar(std::pow(rz, n + 1), (n + 1) * exponent * phi) / double(n + 1);
      A(2 * j, n) = weight[j] * zn.real();
      A(2 * j + 1, n) = weight[j] * zn.imag();
    }
    if (j < angles.size()) phi += angles[j];
  }
  // f = P b with P the least-squares solve; f_0 is the first row of P
  const Eigen::MatrixXd P = A.completeOrthogonalDecomposition().pseudoInverse();
  Eigen::RowVectorXd row(static_cast<Eigen::Index>(basis.size()));
  for (std::size_t k = 0; k < basis.size(); ++k) {
    Eigen::VectorXd b(2 * J);
    for (std::size_t j = 0; j < J; ++j) {
      const Complex d = weight[j] * edge_value(adjacency, basis[k], tip, ring.neighbours[j]);
      b[2 * j] = d.real();
      b[2 * j + 1] = d.imag();
    }
    row[static_cast<Eigen::Index>(k)] = P.row(0).dot(b);
  }
  return row;
}

TipChoice most_uniform_with_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<FaceMap>& basis, double min_angle, double max_ratio) {
  TipChoice choice;
  choice.free_coefficients = most_uniform_combination(soup, basis);
  choice.coefficients = choice.free_coefficients;
  if (basis.size() < 2) return choice;
  const double limit = max_ratio * uniformity_ratio(soup, basis, choice.free_coefficients);
  Eigen::MatrixXd rows(0, static_cast<Eigen::Index>(basis.size()));
  for (const BoundaryTip& tip : boundary_tips(soup, adjacency, min_angle)) {
    if (choice.tips.size() + 1 >= basis.size()) break;
    Eigen::RowVectorXd row = tip_leading_coefficient(soup, adjacency, basis, tip.vertex);
    if (!(row.norm() > 0)) continue;
    Eigen::MatrixXd trial(rows.rows() + 1, rows.cols());
    trial << rows, row.normalized();
    const Eigen::VectorXd c = most_uniform_combination(soup, basis, trial);
    if (!(uniformity_ratio(soup, basis, c) <= limit)) continue;
    rows = trial;
    choice.coefficients = c;
    choice.tips.push_back(tip);
  }
  return choice;
}

}  // namespace qm
