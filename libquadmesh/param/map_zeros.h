// Zeros of a face map on S (method.md section 6, "What discrete forms really do"),
// counted on S itself rather than on the double.
//
// Image angle at a vertex: the sum of its corner angles in the image. An interior
// vertex of angle 2 pi (m + 1) is a zero of order m (a quad vertex of valence
// 4 (m + 1)); a boundary vertex of angle pi (m + 1) is a boundary zero of order m
// counted on the double (a boundary vertex with 2 (m + 1) quads). Zeros inside
// triangles show up as folds: vertices joined by flipped triangles form clusters.
// Over the double: 2 * (interior orders) + (boundary orders) = 2G - 2 = -2 chi.
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

namespace qm {

struct MapZero {
  std::vector<int> vertices;     ///< the cluster (a single vertex when no fold)
  int flipped_triangles = 0;
  int order = 0;                 ///< interior: order on S; boundary: order on the double
  bool on_boundary = false;
  int representative = -1;       ///< where the zero is placed: smallest |h|, on the boundary if boundary
};

struct MapZeros {
  std::vector<int> vertex_order;  ///< interior: round(angle / 2pi) - 1; boundary: round(angle / pi) - 1
  std::vector<char> flipped;      ///< per triangle: image area <= 0
  std::size_t flipped_count = 0;
  std::vector<MapZero> zeros;     ///< clusters with a nonzero order or a fold
  int doubled_order_sum = 0;      ///< 2 * interior orders + boundary orders (= 2G - 2)
};

/// Zeros of `map` (a closed form as a FaceMap) on the oriented soup S.
MapZeros map_zeros(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& map);

}  // namespace qm
