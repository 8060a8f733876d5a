#include "libquadmesh/extract/internal/closest_location.h"

namespace qm {

std::array<double, 3> barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a, w = p - a;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), wu = w.dot(u), wv = w.dot(v);
  const double det = uu * vv - uv * uv;
  if (det <= 0) return {1.0, 0.0, 0.0};
  const double y = (vv * wu - uv * wv) / det, z = (uu * wv - uv * wu) / det;
  return {1 - y - z, y, z};
}

std::pair<Vec3, SurfaceLocation> closest_location(const TriangleSoup& surface, const TriangleTree& tree,
                                                  const Vec3& guess) {
  const auto [p, f] = tree.closest(guess);
  const Triangle& t = surface.triangles[static_cast<std::size_t>(f)];
  SurfaceLocation loc;
  loc.kind = SurfaceLocation::Kind::face;
  loc.face = f;
  loc.barycentric = barycentric(p, surface.points[static_cast<std::size_t>(t[0])],
                                surface.points[static_cast<std::size_t>(t[1])],
                                surface.points[static_cast<std::size_t>(t[2])]);
  return {p, loc};
}

}  // namespace qm
