#include "libquadmesh/quality/triangle_quality.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace qm {

TriangleQuality triangle_quality(const TriangleSoup& soup) {
  TriangleQuality q;
  q.triangles = soup.triangles.size();
  q.min_angle_deg = 180;
  for (const Triangle& t : soup.triangles) {
    double lo = 180, hi = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = soup.points[t[(k + 1) % 3]] - soup.points[t[k]];
      const Vec3 b = soup.points[t[(k + 2) % 3]] - soup.points[t[k]];
      const double angle = angle_between(a, b) * 180.0 / M_PI;
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
    q.min_angle_deg = std::min(q.min_angle_deg, lo);
    q.max_angle_deg = std::max(q.max_angle_deg, hi);
    if (lo < 5) ++q.slivers;
    if (hi > 90) ++q.obtuse;
  }
  if (soup.triangles.empty()) q.min_angle_deg = 0;
  return q;
}

}  // namespace qm
