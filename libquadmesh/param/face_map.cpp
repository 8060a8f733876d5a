#include "libquadmesh/param/face_map.h"

#include "libquadmesh/core/error.h"

#include <cmath>

namespace qm {

FaceMap linear_combination(const std::vector<FaceMap>& basis, const Eigen::VectorXd& coefficients) {
  QM_ASSERT(!basis.empty() && static_cast<std::size_t>(coefficients.size()) == basis.size());
  FaceMap out;
  out.corners.assign(basis[0].corners.size(), CornerValues{});
  for (std::size_t k = 0; k < basis.size(); ++k) {
    const double c = coefficients[static_cast<Eigen::Index>(k)];
    if (c == 0) continue;
    for (std::size_t f = 0; f < out.corners.size(); ++f)
      for (int i = 0; i < 3; ++i) out.corners[f][i] += c * basis[k].corners[f][i];
  }
  return out;
}

FaceMap scaled(const FaceMap& map, Complex factor) {
  FaceMap out = map;
  for (CornerValues& c : out.corners)
    for (Complex& z : c) z *= factor;
  return out;
}

FaceMap conjugated(const FaceMap& map) {
  FaceMap out = map;
  for (CornerValues& c : out.corners)
    for (Complex& z : c) z = std::conj(z);
  return out;
}

double total_image_area(const FaceMap& map) {
  double sum = 0;
  for (const CornerValues& c : map.corners) sum += 0.5 * image_area2(c);
  return sum;
}

double image_area_sum(const FaceMap& map) {
  double sum = 0;
  for (const CornerValues& c : map.corners) sum += 0.5 * std::abs(image_area2(c));
  return sum;
}

}  // namespace qm
