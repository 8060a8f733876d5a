#include "libquadmesh/cones/tip_shear.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace qm {

namespace {

/// A 3D direction in triangle f's local frame (face_geometry.h: corner 0 at 0,
/// corner 1 on the positive real axis), projected onto its plane and made unit;
/// nothing when the triangle or the projection is degenerate.
std::optional<Complex> in_local_frame(const TriangleSoup& soup, std::size_t f, const Vec3& direction) {
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

/// The affine shape (conformal, anticonformal) that takes the unit directions t1
/// and t2 (t2 counter-clockwise of t1 by less than a half turn) to omega and
/// i omega: a t1 + b conj(t1) = omega, a t2 + b conj(t2) = i omega.
std::pair<Complex, Complex> wedge_to_right_angle(Complex t1, Complex t2, Complex omega) {
  const Complex i(0, 1);
  const Complex det = t1 * std::conj(t2) - t2 * std::conj(t1);
  return {(omega * std::conj(t2) - i * omega * std::conj(t1)) / det, (t1 * i * omega - t2 * omega) / det};
}

}  // namespace

FitShape tip_shear(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<AcuteTip>& tips,
                   const CrossField& field, double size) {
  FitShape shape;
  shape.conformal.assign(soup.triangles.size(), Complex(1, 0));
  shape.anticonformal.assign(soup.triangles.size(), Complex(0, 0));
  std::vector<double> weight(soup.triangles.size(), 0.0);
  for (const AcuteTip& tip : tips) {
    const VertexRing ring = vertex_ring(soup, adjacency, tip.vertex);
    if (ring.neighbours.size() < 2) continue;
    const Vec3& p = soup.points[static_cast<std::size_t>(tip.vertex)];
    // the boundary edges: the first along the loop, the second counter-clockwise of it
    const Vec3 edge1 = soup.points[static_cast<std::size_t>(ring.neighbours.front())] - p;
    const Vec3 edge2 = soup.points[static_cast<std::size_t>(ring.neighbours.back())] - p;
    const double reach = std::min(tip.reach, shear_radius_quads * size);
    const double fade = (1 - full_shear_share) * reach;
    std::unordered_map<int, double> distance;
    for (const auto& [w, d] : tip.near)
      if (d < reach) distance[w] = d;
    for (const auto& [w, d] : tip.near) {
      if (!(d < reach)) break;
      for (int g : adjacency.vertex_faces[static_cast<std::size_t>(w)]) {
        const auto f = static_cast<std::size_t>(g);
        double mean = 0;
        for (int c : soup.triangles[f]) {
          const auto it = distance.find(c);
          mean += it == distance.end() ? reach : it->second;
        }
        mean /= 3;
        const double share = std::clamp((reach - mean) / fade, 0.0, 1.0);
        if (share <= weight[f]) continue;
        const std::optional<Complex> t1 = in_local_frame(soup, f, edge1), t2 = in_local_frame(soup, f, edge2);
        if (!t1 || !t2) continue;
        const double opening = std::arg(*t2 / *t1);
        if (!(opening > 0) || !(opening < M_PI / 2)) continue;
        // the lattice axis the field's chart gives the first edge: the images'
        // bisectors matched (the field turns by 90 degrees - a across the tip, so
        // each edge is within half of that of its axis)
        const Complex frame = std::polar(1.0, -field.angle[f]);
        const double turns = std::round(std::arg(frame * *t1 * std::polar(1.0, opening / 2 - M_PI / 4)) / (M_PI / 2));
        const Complex omega = std::polar(1.0, turns * M_PI / 2);
        const auto [a, b] = wedge_to_right_angle(*t1, *t2, omega / frame);
        weight[f] = share;
        shape.conformal[f] = Complex(1, 0) + share * (a - Complex(1, 0));
        shape.anticonformal[f] = share * b;
      }
    }
  }
  return shape;
}

}  // namespace qm
