#include "libquadmesh/cones/internal/face_geometry.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace qm {

CornerValues local_corners(const TriangleSoup& soup, std::size_t f) {
  const Triangle& t = soup.triangles[f];
  const Vec3& p0 = soup.points[static_cast<std::size_t>(t[0])];
  const Vec3 a = soup.points[static_cast<std::size_t>(t[1])] - p0;
  const Vec3 b = soup.points[static_cast<std::size_t>(t[2])] - p0;
  const double la = a.norm();
  const double x = la > 0 ? a.dot(b) / la : 0.0;
  const double y = la > 0 ? a.cross(b).norm() / la : 0.0;
  return {Complex(0, 0), Complex(la, 0), Complex(x, y)};
}

std::optional<Complex> local_direction(const TriangleSoup& soup, std::size_t f, const Vec3& direction) {
  const Triangle& t = soup.triangles[f];
  const Vec3& p0 = soup.points[static_cast<std::size_t>(t[0])];
  const Vec3 a = soup.points[static_cast<std::size_t>(t[1])] - p0;
  const Vec3 b = soup.points[static_cast<std::size_t>(t[2])] - p0;
  const double la = a.norm();
  if (!(la > 0)) return std::nullopt;
  const Vec3 x = a / la;
  const Vec3 across = b - b.dot(x) * x;
  if (!(across.norm() > 0)) return std::nullopt;
  const Vec3 y = across / across.norm();
  const Complex local(direction.dot(x), direction.dot(y));
  if (!(std::abs(local) > 1e-12 * direction.norm())) return std::nullopt;
  return local / std::abs(local);
}

std::array<double, 3> corner_cotangents(const TriangleSoup& soup, std::size_t f) {
  const Triangle& t = soup.triangles[f];
  std::array<double, 3> cot{};
  for (int i = 0; i < 3; ++i) {
    const Vec3& p = soup.points[static_cast<std::size_t>(t[i])];
    const Vec3 a = soup.points[static_cast<std::size_t>(t[(i + 1) % 3])] - p;
    const Vec3 b = soup.points[static_cast<std::size_t>(t[(i + 2) % 3])] - p;
    // a degenerate corner gets a large finite weight rather than an infinite one
    cot[static_cast<std::size_t>(i)] = a.dot(b) / std::max(a.cross(b).norm(), 1e-12 * a.norm() * b.norm() + 1e-300);
  }
  return cot;
}

}  // namespace qm
