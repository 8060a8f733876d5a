#include "libquadmesh/cones/tip_shear.h"

#include "libquadmesh/cones/internal/face_geometry.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <unordered_map>

namespace qm {

namespace {

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
        const std::optional<Complex> t1 = local_direction(soup, f, edge1), t2 = local_direction(soup, f, edge2);
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
