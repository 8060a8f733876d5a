#include "libquadmesh/topology/internal/coordinate_range.h"

#include <cmath>
#include <limits>

namespace qm {

CoordinateRange coordinate_range(const TriangleSoup& soup) {
  CoordinateRange r;
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Vec3& p = soup.points[i];
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
    const double magnitude = p.cwiseAbs().maxCoeff();
    if (r.largest_vertex < 0 || magnitude > r.largest_magnitude) {
      r.largest_vertex = static_cast<int>(i);
      r.largest_magnitude = magnitude;
    }
  }
  if (r.largest_vertex >= 0) r.diagonal = (hi - lo).norm();
  return r;
}

}  // namespace qm
