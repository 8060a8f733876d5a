// A protrusion's cap (method.md section 11: "protrusion tips and the ends of arms
// get the valence-3 cones"). On an ear or a stub the conformal factor u of the
// cone metric falls all along the tube towards the tip: summed over a region, the
// metric's equation L u = K_target - K is the flux of u out of it, and a cap that
// holds 2 pi of the surface's curvature with no cone in it leaves the flux of
// 2 pi to every cross-section below, so the quads grow exponentially towards the
// tip. Four valence-3 cones in the cap (four quarter turns) take the flux away.
// One pair at a time cannot get there: the settling of the cones moves a lone cap
// cone out again (cone_placement.cpp add_cone_pairs).
#pragma once

#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <vector>

namespace qm {

/// The vertices of the connected region (through the triangles) where u < level
/// that holds `seed` (seed first, then breadth first).
std::vector<int> sublevel_region(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                                 int seed, double level);

/// The quarter turns the cap round `seed` lacks: over sublevel_region(u, seed,
/// level), the surface's curvature (`curvature`, per vertex: cone_metric.h
/// vertex_curvature) less what `cones` give it, in quarter turns, rounded. 0 when
/// the region reaches the boundary (an arm's end, not a cap: its corners carry
/// cones already).
int cap_quarter_turns(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<double>& curvature,
                      const Eigen::VectorXd& u, double level, int seed, const std::vector<Cone>& cones);

}  // namespace qm
