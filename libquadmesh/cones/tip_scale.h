// Acute corners: the cone metric opens a corner of angle a on S to its q quarter
// turns, and its scale vanishes there like r^k, k = q pi / 2a - 1 (a 45-degree
// corner in one quad: like r; a 30-degree one: like r^2). The quads swell towards
// such a tip, to many times the size, and the placement spends interior cones on
// it; a map sheared at the tip (the tip's quad a parallelogram) keeps them near
// the size. The sizes the cones are placed for and the map is fitted to leave that
// singular part out near the tip (the field keeps the metric as it is: its
// turning needs it).
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <vector>

namespace qm {

/// How far from a tip (in quads) its singular part is left out, at most...
constexpr double tip_radius_quads = 12.0;
/// ...and how far at least: a tip whose loop turns back nearer (a scan's tooth, a
/// fillet that ends at the tip) is no acute corner at the quad scale, and is left
/// as it is.
constexpr double min_tip_reach_quads = 2.0;

/// A boundary cone sharper than its quads, with how far from it its singular part
/// is left out (tip_scale_offset).
struct AcuteTip {
  int vertex = -1;
  double exponent = 0;  ///< k = target angle / angle on S - 1
  double reach = 0;     ///< R
  std::vector<std::pair<int, double>> near;  ///< the vertices within R, nearest first, with their distance
};

/// The acute tips as tip_scale_offset finds them: every boundary vertex whose k
/// is above 0.4 and whose reach R is at least min_tip_reach_quads x size. None
/// when size is 0.
std::vector<AcuteTip> acute_tips(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<double>& target_curvature,
                                 const std::vector<double>& surface_curvature, double size);

/// Per vertex, what the sizes add to the cone metric's log scale `u` near the
/// acute tips (acute_tips: boundary vertices whose target angle, pi -
/// target_curvature, is more than 1.4 x their angle on S, pi - surface_curvature:
/// k above 0.4, so a 60-degree corner in one quad is one): k log(R / d) at the
/// vertices a distance d < R from a tip along the edges, but no more than lifts u
/// to its mean over the last fifth of that reach (never above the sizes round it:
/// a 20-degree tip's k of 3.5 would lift its triangles far past them, and the map
/// folds there); the tip itself, whose u is the discretization's of the
/// singularity, its neighbours' mean, lifted. R is tip_radius_quads x the quads'
/// size, or less: the distance to the first vertex of another boundary loop, or to
/// where the tip's own loop turns otherwise than the targets ask by more than a
/// quarter of the tip's excess (another corner; a fillet that ends at the tip,
/// whose turn makes up for it); a tip whose R comes out under min_tip_reach_quads
/// x size is none.
Eigen::VectorXd tip_scale_offset(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const std::vector<AcuteTip>& tips, const Eigen::VectorXd& u);

}  // namespace qm
