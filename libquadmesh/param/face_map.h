// Piecewise-linear maps of the triangles of S into the complex plane, stored per
// triangle corner (method.md sections 7-8).
//
// A closed complex 1-form on S is stored as a FaceMap whose triangles agree on
// every shared edge up to a translation: the value of the form on the edge i->j
// of triangle f is corners[f][j] - corners[f][i]. A map integrated on the surface
// cut into a disk is a FaceMap too; the translations across cut edges are then its
// periods. Corners follow the soup's corner order (soup.triangles[f][k]).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <Eigen/Core>

#include <array>
#include <complex>
#include <vector>

namespace qm {

using Complex = std::complex<double>;
using CornerValues = std::array<Complex, 3>;

struct FaceMap {
  std::vector<CornerValues> corners;  ///< per triangle, the image of its three corners
};

/// Twice the signed area of the image triangle (positive: orientation kept).
inline double image_area2(const CornerValues& c) {
  return std::imag(std::conj(c[1] - c[0]) * (c[2] - c[0]));
}

/// sum_k coefficients[k] * basis[k], triangle by triangle.
FaceMap linear_combination(const std::vector<FaceMap>& basis, const Eigen::VectorXd& coefficients);

/// factor * map (a rotation and scaling of the image).
FaceMap scaled(const FaceMap& map, Complex factor);

/// The complex conjugate map (the image mirrored: V -> -V).
FaceMap conjugated(const FaceMap& map);

/// Sum over triangles of the signed image area.
double total_image_area(const FaceMap& map);

/// Sum over triangles of |image area| / 3D area (the L2 norm squared of the form
/// when it is conformal: |h|^2 dA summed).
double image_area_sum(const FaceMap& map);

}  // namespace qm
