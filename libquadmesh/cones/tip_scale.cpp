#include "libquadmesh/cones/tip_scale.h"

#include "libquadmesh/cones/internal/edge_distance.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace qm {

namespace {

/// The exponent k above which a corner's scale is taken as singular.
constexpr double min_tip_exponent = 0.4;
/// The turning of the tip's loop against its targets, summed outwards from the
/// tip, that ends the reach, as a share of the tip's own.
constexpr double max_other_turning = 0.25;
/// The outer share of the reach whose mean u caps the lift.
constexpr double rim_share = 0.2;

}  // namespace

std::vector<AcuteTip> acute_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<double>& target_curvature,
                                 const std::vector<double>& surface_curvature, double size) {
  std::vector<AcuteTip> tips;
  if (!(size > 0)) return tips;
  const double radius = tip_radius_quads * size;
  for (std::size_t v = 0; v < soup.points.size(); ++v) {
    if (!adjacency.boundary_vertex[v] || target_curvature[v] == 0) continue;
    const double angle = M_PI - surface_curvature[v], target = M_PI - target_curvature[v];
    if (!(angle > 0) || !(target / angle - 1 > min_tip_exponent)) continue;
    const int loop = adjacency.loop_of_vertex[v];
    const double excess = std::abs(target_curvature[v] - surface_curvature[v]);
    double turning = 0;
    AcuteTip tip{static_cast<int>(v), target / angle - 1, radius, {}};
    tip.near = vertices_within(soup, adjacency, tip.vertex, tip.reach, [&](int w) {
      const auto sw = static_cast<std::size_t>(w);
      if (!adjacency.boundary_vertex[sw]) return false;
      if (adjacency.loop_of_vertex[sw] != loop) return true;
      turning += std::abs(target_curvature[sw] - surface_curvature[sw]);
      return turning > max_other_turning * excess;
    });
    if (tip.reach < min_tip_reach_quads * size) continue;
    tips.push_back(std::move(tip));
  }
  return tips;
}

Eigen::VectorXd tip_scale_offset(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<AcuteTip>& tips, const Eigen::VectorXd& u) {
  Eigen::VectorXd offset = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(soup.points.size()));
  for (const AcuteTip& tip : tips) {
    // u's mean on the rim: the most the sizes are lifted to
    double rim = 0, on_rim = 0;
    for (const auto& [w, d] : tip.near)
      if (d >= (1 - rim_share) * tip.reach) {
        rim += u[w];
        on_rim += 1;
      }
    if (on_rim == 0) continue;
    rim /= on_rim;
    std::unordered_map<int, double> added;
    for (const auto& [w, d] : tip.near) {
      if (d <= 0) continue;
      const double add = std::max(0.0, std::min(tip.exponent * std::log(tip.reach / d), rim - u[w]));
      offset[w] += add;
      added[w] = add;
    }
    // the tip's own u is the discretization's of the singularity (far below its
    // neighbours'): it takes their mean, lifted
    const VertexRing ring = vertex_ring(soup, adjacency, tip.vertex);
    double lifted = 0;
    for (int w : ring.neighbours) lifted += u[w] + added[w];
    if (!ring.neighbours.empty()) {
      lifted /= static_cast<double>(ring.neighbours.size());
      offset[static_cast<Eigen::Index>(tip.vertex)] += std::max(0.0, lifted - u[tip.vertex]);
    }
  }
  return offset;
}

}  // namespace qm
