#include "libquadmesh/param/branch_points.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace qm {

namespace {

/// A boundary this close to an interior branch point (image radius, cells) may
/// forbid its nearer level (lattice_level)...
constexpr double boundary_search_radius = 1.5;
/// ...when the boundary's V is within this of that level (cells).
constexpr double same_level_tolerance = 1e-3;
/// The snapped disk: image radius three times the snap, at least this (cells),
/// and short of a kept vertex by this factor of its distance.
constexpr double min_snap_radius = 0.5;
constexpr double keep_clearance = 0.9;

/// The integer V for an interior branch point b with image p: the nearer of the two
/// integers around p.imag(), unless a boundary within 1.5 cells of b lies at that
/// level (a branch point on a boundary's level folds the strip between them; see
/// quantization.h), then the other one.
double lattice_level(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& param, int b,
                     Complex p) {
  const std::unordered_map<int, double> ball = image_ball(soup, adjacency, param, b, boundary_search_radius);
  // images in b's chart, spread from b through the ball's triangles
  std::unordered_map<int, Complex> value{{b, p}};
  std::vector<int> frontier{b};
  std::vector<double> boundary_levels;
  while (!frontier.empty()) {
    std::vector<int> next;
    for (int u : frontier)
      for (int f : adjacency.vertex_faces[static_cast<std::size_t>(u)]) {
        const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
        const CornerValues& c = param.corners[static_cast<std::size_t>(f)];
        const int i = static_cast<int>(std::find(t.begin(), t.end(), u) - t.begin());
        for (int k = 0; k < 3; ++k) {
          const int w = t[k];
          if (value.count(w) || !ball.count(w)) continue;
          value[w] = value[u] + c[static_cast<std::size_t>(k)] - c[static_cast<std::size_t>(i)];
          if (adjacency.boundary_vertex[static_cast<std::size_t>(w)]) boundary_levels.push_back(value[w].imag());
          next.push_back(w);
        }
      }
    frontier.swap(next);
  }
  const double nearest = std::round(p.imag());
  const double other = nearest + (p.imag() >= nearest ? 1.0 : -1.0);
  for (double level : boundary_levels)
    if (std::abs(level - nearest) < same_level_tolerance) return other;
  return nearest;
}

}  // namespace

std::vector<double> image_angles(const TriangleSoup& soup, const FaceMap& param) {
  std::vector<double> angle(soup.points.size(), 0.0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const CornerValues& c = param.corners[f];
    for (int i = 0; i < 3; ++i) {
      const Complex to_next = c[static_cast<std::size_t>((i + 1) % 3)] - c[static_cast<std::size_t>(i)];
      const Complex to_prev = c[static_cast<std::size_t>((i + 2) % 3)] - c[static_cast<std::size_t>(i)];
      if (std::abs(to_next) == 0 || std::abs(to_prev) == 0) continue;
      angle[static_cast<std::size_t>(soup.triangles[f][i])] += std::arg(to_prev / to_next);
    }
  }
  return angle;
}

namespace {

/// hidden_cones() from the image angles already summed.
std::vector<HiddenCone> hidden_cones(const SurfaceAdjacency& adjacency, const std::vector<double>& angle,
                                     const std::vector<ZeroVertex>& cones) {
  std::vector<double> expected(angle.size());
  for (std::size_t v = 0; v < expected.size(); ++v) expected[v] = adjacency.boundary_vertex[v] ? M_PI : 2 * M_PI;
  for (const ZeroVertex& z : cones) expected[static_cast<std::size_t>(z.vertex)] = z.image_angle();
  std::vector<HiddenCone> hidden;
  for (std::size_t v = 0; v < angle.size(); ++v)
    if (!adjacency.vertex_faces[v].empty() && angle[v] > expected[v] + M_PI / 2)
      hidden.push_back({static_cast<int>(v), angle[v], expected[v]});
  return hidden;
}

}  // namespace

std::vector<HiddenCone> hidden_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                     const FaceMap& param, const std::vector<ZeroVertex>& cones) {
  return hidden_cones(adjacency, image_angles(soup, param), cones);
}

SnapReport snap_hidden_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                             const std::vector<ZeroVertex>& cones, std::vector<char>& pinned) {
  SnapReport report;
  const std::vector<double> angle = image_angles(soup, param);
  const std::vector<HiddenCone> hidden = hidden_cones(adjacency, angle, cones);
  report.hidden = hidden.size();
  // the cones that branch where they should stay where they are
  std::vector<char> keep(soup.points.size(), 0);
  for (const ZeroVertex& z : cones)
    if (std::abs(angle[static_cast<std::size_t>(z.vertex)] - z.image_angle()) < M_PI / 2)
      keep[static_cast<std::size_t>(z.vertex)] = 1;
  for (const HiddenCone& h : hidden) {
    const int b = h.vertex;
    const bool boundary = adjacency.boundary_vertex[static_cast<std::size_t>(b)];
    const int f0 = adjacency.vertex_faces[static_cast<std::size_t>(b)].front();
    const Triangle& t0 = soup.triangles[static_cast<std::size_t>(f0)];
    const int k0 = static_cast<int>(std::find(t0.begin(), t0.end(), b) - t0.begin());
    const Complex p = param.corners[static_cast<std::size_t>(f0)][static_cast<std::size_t>(k0)];
    Complex delta(std::round(p.real()) - p.real(), 0.0);
    if (!boundary) delta.imag(lattice_level(soup, adjacency, param, b, p) - p.imag());
    double radius = std::max(3 * std::abs(delta), min_snap_radius);
    for (const auto& [v, d] : image_ball(soup, adjacency, param, b, radius))
      if (keep[static_cast<std::size_t>(v)] && v != b) radius = std::min(radius, keep_clearance * d);
    const std::unordered_map<int, double> disk = image_ball(soup, adjacency, param, b, radius);
    for (const auto& [v, d] : disk) {
      const double s = std::clamp(d / radius, 0.0, 1.0);
      Complex move = delta * (1 - s * s * (3 - 2 * s));
      if (adjacency.boundary_vertex[static_cast<std::size_t>(v)]) move.imag(0);
      for (int f : adjacency.vertex_faces[static_cast<std::size_t>(v)]) {
        const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
        for (int i = 0; i < 3; ++i)
          if (t[i] == v) param.corners[static_cast<std::size_t>(f)][static_cast<std::size_t>(i)] += move;
      }
    }
    // b and its star translate rigidly (the blend is flat near b): pinned together,
    // no later untangling can move the branch off b
    pinned[static_cast<std::size_t>(b)] = 1;
    for (int v : vertex_ring(soup, adjacency, b).neighbours) pinned[static_cast<std::size_t>(v)] = 1;
    keep[static_cast<std::size_t>(b)] = 1;
    ++report.snapped;
  }
  return report;
}

std::vector<ZeroVertex> mapped_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                     const FaceMap& param, const std::vector<ZeroVertex>& cones) {
  const std::vector<double> angle = image_angles(soup, param);
  auto order_of = [&](int v) {
    const double unit = adjacency.boundary_vertex[static_cast<std::size_t>(v)] ? M_PI : 2 * M_PI;
    return static_cast<int>(std::lround(angle[static_cast<std::size_t>(v)] / unit)) - 1;
  };
  std::vector<ZeroVertex> out;
  for (ZeroVertex z : cones) {
    if (!z.corner && std::abs(angle[static_cast<std::size_t>(z.vertex)] - z.image_angle()) >= M_PI / 2) {
      z.order = order_of(z.vertex);
      if (z.order <= 0) continue;
    }
    out.push_back(z);
  }
  for (const HiddenCone& h : hidden_cones(adjacency, angle, cones))
    out.push_back({h.vertex, order_of(h.vertex), static_cast<bool>(adjacency.boundary_vertex[static_cast<std::size_t>(h.vertex)]), false});
  return out;
}

}  // namespace qm
