// Fillets (issue 18). A CAD part's corners are often rounded: a plate's outline
// with fillets of a few quads' radius, a bracket's inner radius. At the quad scale
// (boundary_corners.h, half a quad each way) such an arc turns too little at any
// one vertex to be a corner, so the cone metric must take its quarter turn
// inside, from a valence-3 cone near a convex one. The
// greedy placement puts cones of one sign only (the slotted plate's: valence 5,
// round its slot and holes), and a pair added at a time shifts the conformal
// factor across the whole part (a valence-5 cone by the slot and a valence-3 one
// by a fillet: 90% of the area in the band before the pair, about half after it,
// the fillets on the slot's side in quads far larger). cone_placement.h
// fillet_cones puts one cone beside each fillet corner found here, before the
// others. (A corner cone at the arc's middle instead, one quad there: 97% of the
// slotted plate's quads in the band, but the corner quads' angle at that point is
// the arc's, near 180 degrees: Verdict's scaled Jacobian 0.22.)
//
// A fillet corner: a boundary vertex where the loop turns by 60-120 degrees either
// way within fillet_window_quads quads on each side, while the flanks beyond (as
// long again) turn by less than fillet_flank_deg each: an arc between two straight
// or gently curved edges, not a hole's circle or a slot's end, whose turn goes on.
// It sits at the middle of the turn (the vertex where the turns before it and
// after it are nearest equal) and is not within the window of a corner at the
// quad scale; a loop shorter than four windows (a hole's circle) has none.
#pragma once

#include "libquadmesh/cones/boundary_corners.h"
#include "libquadmesh/core/triangle_soup.h"

#include <vector>

namespace qm {

/// The window each way, in quads, within which a fillet turns: quarter arcs up to
/// about 4 x fillet_window_quads / pi = 3.2 quads in radius (the slotted plate's
/// 8 mm fillets at 1.5% of its diagonal: 2.9 quads).
constexpr double fillet_window_quads = 2.5;

/// The most each flank (the next fillet_window_quads along the loop) may turn.
constexpr double fillet_flank_deg = 20.0;

/// The fillet corners of `surface` for quads of edge `size` (> 0), none of them a
/// corner at the quad scale or within the window of one; sorted by vertex.
/// Precondition: `surface` is a manifold triangle surface.
std::vector<BoundaryCorner> fillet_corners(const TriangleSoup& surface, double size);

/// Whether a fillet corner is convex (its interior angle below 180 degrees).
inline bool convex_fillet(const BoundaryCorner& fillet) { return fillet.angle_deg < 180; }

}  // namespace qm
