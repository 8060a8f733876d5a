// Integrating a closed edge 1-form on the surface cut open into a disk (method.md
// section 8, seed paper Alg. 4.5), here as a preview: a breadth-first spanning tree
// of the faces of S (faces 0..face_count-1 of D) fixes the cut, and every triangle
// corner gets its own value, so level sets show the grid lines and the jumps across
// the cut show the periods.
#pragma once

#include "libquadmesh/core/mesh.h"

#include <Eigen/Core>

namespace qm {

/// Per-corner values (face_count x 3, corners as face_corners in core/mesh.h) of the integral of
/// `form` (edge values along halfedge(e, 0)), 0 at the first corner of face 0.
/// Faces are reached only across edges between faces < face_count.
Eigen::MatrixX3d integrate_on_cut_surface(const Mesh& mesh, const Eigen::VectorXd& form,
                                          std::size_t face_count);

}  // namespace qm
