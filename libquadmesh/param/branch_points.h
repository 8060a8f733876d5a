// Where the parameterization really branches (method.md section 9: the singular
// vertices are lattice points "by construction"; this checks and restores it).
//
// The untangling (barrier_untangle.h) starts from a folded map, so it is free to
// change winding numbers: a fold next to a zero can come out as a positive map that
// turns twice around a neighbour of the cone and once around the cone itself. Every
// triangle is then positive, but the branch point is off the lattice and the
// extraction finds a cell that covers its square twice (dropped). The image angle
// of a vertex (the sum of its corner angles in the image; 2 pi times the winding
// number inside, pi times it on the boundary) tells where the map branches.
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/param/zero_stars.h"

#include <vector>

namespace qm {

/// The sum of the image corner angles (signed, in (-pi, pi) each) at every vertex.
std::vector<double> image_angles(const TriangleSoup& soup, const FaceMap& param);

/// A vertex whose image angle exceeds the one its role prescribes (2 pi inside, pi
/// on the boundary, ZeroVertex::image_angle() at a cone) by at least pi / 2.
struct HiddenCone {
  int vertex = -1;
  double image_angle = 0;
  double expected = 0;
};

/// Precondition: `param` positive (untangled) near the vertices reported.
std::vector<HiddenCone> hidden_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                     const FaceMap& param, const std::vector<ZeroVertex>& cones);

struct SnapReport {
  std::size_t hidden = 0;   ///< hidden cones found
  std::size_t snapped = 0;  ///< of them, moved onto a lattice point
};

/// Moves every hidden cone onto its nearest lattice point (U and V rounded inside,
/// U only on the boundary, whose V is already an integer), with a disk around it in
/// the image: the vertices at image distance d < R from it are translated by
/// delta (1 - s(d / R)), s the smoothstep, R = max(3 |delta|, 1/2) but short of
/// the nearest other cone, so that the blend stretches the image by at most
/// 1.5 |delta| / R < 1/2 (no new fold away from the boundary). Boundary vertices
/// in the disk take only the U part. Chart copies move together (seams stay integer
/// translations). `pinned[v]` = 1 is set for the snapped vertices; the caller
/// untangles what the blend folded (next to a boundary) with them pinned.
SnapReport snap_hidden_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, FaceMap& param,
                             const std::vector<ZeroVertex>& cones, std::vector<char>& pinned);

/// The cones as the map has them: a cone whose image angle is off its order by at
/// least pi / 2 takes the order of its angle (a zero left with the angle of an
/// ordinary vertex is dropped; a corner stays a corner), and every hidden cone is
/// added as a zero of the order of its angle (2 pi (m + 1) inside, pi (m + 1) on the
/// boundary). The orders still sum to what the topology requires.
std::vector<ZeroVertex> mapped_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                     const FaceMap& param, const std::vector<ZeroVertex>& cones);

}  // namespace qm
