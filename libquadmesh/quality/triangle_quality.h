// Quality of the input triangulation, as far as the forms care (method.md section
// 6): slivers and obtuse angles degrade the cotangent Laplacian and the Hodge star.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

namespace qm {

struct TriangleQuality {
  double min_angle_deg = 0;     ///< smallest corner angle
  double max_angle_deg = 0;     ///< largest corner angle
  std::size_t slivers = 0;      ///< triangles with an angle under 5 degrees
  std::size_t obtuse = 0;       ///< triangles with an angle over 90 degrees
  std::size_t triangles = 0;
};

TriangleQuality triangle_quality(const TriangleSoup& soup);

}  // namespace qm
