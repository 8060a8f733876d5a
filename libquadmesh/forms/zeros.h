// Zeros of a holomorphic form and their orders (method.md section 6, "What
// discrete forms really do").
//
// Integrating h over each triangle gives its image in the plane. The image
// angles around a vertex add up to 2 pi (m + 1) for a zero of order m. Zeros
// mostly fall inside triangles and show up as folds (negatively oriented
// images), so vertices joined by folded triangles form clusters whose order is
// their vertex orders plus their folded triangles; cluster orders sum to 2G - 2.
#pragma once

#include "libquadmesh/forms/doubled_surface.h"

#include <Eigen/Core>

#include <vector>

namespace qm {

struct ZeroCluster {
  std::vector<int> vertices;  ///< vertices of D in the cluster
  int flipped_triangles = 0;
  int order = 0;              ///< sum of vertex orders + flipped triangles
  int representative = -1;    ///< the vertex with the smallest |h| (a vertex of S when possible)
  bool on_boundary = false;   ///< contains a vertex of the boundary of S (its own mirror)
};

struct FormZeros {
  std::vector<int> vertex_order;     ///< per vertex of D: round(angle / 2 pi) - 1
  std::vector<char> flipped;         ///< per face of D: image negatively oriented
  std::size_t flipped_count = 0;
  std::vector<ZeroCluster> clusters; ///< on D, every cluster with order != 0 or a fold
  int order_sum = 0;                 ///< sum of cluster orders over D (= 2G - 2)
};

/// Zeros of h = re + i im (edge values along halfedge(e, 0)).
FormZeros form_zeros(const DoubledSurface& d, const Eigen::VectorXd& re, const Eigen::VectorXd& im);

}  // namespace qm
