// Boundary tips: boundary vertices round which the surface turns almost a full
// turn (the end of a slit, the sharp corner of a hole that is one missing
// triangle, the bottom of a V-notch), and the linear condition on a symmetric
// form for a zero there (method.md sections 6-7; beyond the paper).
//
// Near a boundary vertex p with 3D angle theta (the angles of its triangles at p
// summed), z = w^(pi / theta) maps the flattened fan (w, p at 0, the boundary edge
// that follows p on its loop along the positive real axis) onto a half-disk. A
// symmetric form is real on the boundary (V constant there), so
//   h = sum_n f_n z^n dz,  f_n real,  U + iV - (U + iV)(p) = sum_n f_n z^(n+1) / (n+1).
// Where f_0 != 0 the image angle at p is pi: two quads share theta, each corner
// theta / 2 (173.5 degrees and scaled Jacobian 0.11 at a 347-degree tip). Where
// f_0 = 0 (a boundary zero of order 1 on the double) the image angle is 2 pi and
// four quads of theta / 4 meet at p. f_0 is linear in the form, so the tips become
// linear constraints of the form choice (form_choice.h).
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <vector>

namespace qm {

struct BoundaryTip {
  int vertex = -1;
  double angle = 0;  ///< the 3D angle of the surface at the vertex (radians)
};

/// The boundary vertices whose 3D angle is at least `min_angle` (radians), at most
/// one per boundary loop (the widest on it: the parity of the sign changes of dU
/// along a loop puts a second zero on the same loop anyway), the widest first.
std::vector<BoundaryTip> boundary_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                       double min_angle);

/// The row r (one value per basis form) with r . c = f_0 above for the form
/// sum_k c_k basis[k] at the boundary vertex `tip`: the least-squares fit of the
/// first three terms of the expansion to the form's values along the edges from
/// the tip to its ring, each edge weighted by 1 / |w|^(pi / theta) so that every
/// edge counts the same for the leading term. Precondition: `tip` is a boundary
/// vertex of `soup`; the basis forms are real along the boundary (Im constant).
Eigen::RowVectorXd tip_leading_coefficient(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                           const std::vector<FaceMap>& basis, int tip);

struct TipChoice {
  Eigen::VectorXd coefficients;       ///< auto's form with a zero at each kept tip (unit vector)
  Eigen::VectorXd free_coefficients;  ///< auto's form without them (form_choice.h)
  std::vector<BoundaryTip> tips;      ///< the tips kept
};

/// Auto's form with zeros at the boundary tips (boundary_tips() with
/// `min_angle`), added widest first and each kept only while the uniformity ratio
/// (form_choice.h) stays within `max_ratio` times that of the form without tips:
/// on a scan with many small sliver holes every tip would take one of the G
/// directions of the forms, and the form left can be far from uniform (20 against
/// 4.7 with six tips). At most G - 1 tips.
TipChoice most_uniform_with_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<FaceMap>& basis, double min_angle, double max_ratio = 1.5);

}  // namespace qm
