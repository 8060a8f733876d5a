#include "libquadmesh/core/triangle_soup.h"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <cmath>

namespace qm {

std::string describe_vertex(const TriangleSoup& soup, int i) {
  const Vec3& p = soup.points[static_cast<std::size_t>(i)];
  return fmt::format("vertex {} at ({:.6g}, {:.6g}, {:.6g})", soup.point_label(i), p.x(), p.y(),
                     p.z());
}

std::string describe_triangle(const TriangleSoup& soup, int f) {
  const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
  return fmt::format("triangle {} (vertices {}, {}, {})", soup.triangle_label(f),
                     soup.point_label(t[0]), soup.point_label(t[1]), soup.point_label(t[2]));
}

double angle_between(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

double corner_angle(const TriangleSoup& soup, std::size_t f, int k) {
  const Triangle& t = soup.triangles[f];
  const Vec3& p = soup.points[static_cast<std::size_t>(t[static_cast<std::size_t>(k)])];
  return angle_between(soup.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 1) % 3)])] - p,
                       soup.points[static_cast<std::size_t>(t[static_cast<std::size_t>((k + 2) % 3)])] - p);
}

double mean_edge_length(const TriangleSoup& soup) {
  double sum = 0;
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k) sum += (soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm();
  return soup.triangles.empty() ? 0.0 : sum / (3.0 * static_cast<double>(soup.triangles.size()));
}

}  // namespace qm
