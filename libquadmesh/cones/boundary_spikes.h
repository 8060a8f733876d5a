// Boundary spikes finer than a quad (issue 18; method.md section 11).
//
// A scan's boundary can end in a spike held by a triangle or two: a tip of 20-45
// degrees a fraction of a quad long, where two holes come close (bunny-open). At
// the quad scale the boundary there is straight (boundary_corners.h), so the cone
// metric must open the tip to 180 degrees, a factor of four to eight in one
// triangle: its scale e^u grows like r^(pi / angle - 1) towards the tip, the
// metric's quads there reach thousands of times the size, and no placement is
// mapped. A quad mesh cannot follow such a spike anyway (it is shorter than a
// quad), so the cone route clips it: the triangles round its tip go, and the
// boundary runs along their far edges. The quads stay within the spike's height
// of the input.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <cstddef>

namespace qm {

/// A boundary vertex is a spike when its angle is below this (degrees): the
/// metric would open it by more than three times.
constexpr double spike_angle_deg = 60.0;

/// Removes, pass after pass (at most a few), the triangles round every spike of
/// `soup`'s boundary at the quad size `quad` (> 0): a boundary vertex of angle
/// below spike_angle_deg, all its edges shorter than `quad`, that is no corner at
/// the quad scale (boundary_corners.h), on a loop of more than three vertices,
/// whose inner edges end off the boundary (the surface stays manifold, its loops
/// as many) and whose triangles touch no spike clipped before in the pass. The
/// tip points go (drop_unreferenced_points: the other points are numbered anew,
/// in order). Returns the triangles removed: none on a CAD part, whose sharp
/// corners are corners at the quad scale. Precondition: an oriented manifold soup.
std::size_t clip_boundary_spikes(TriangleSoup& soup, double quad);

}  // namespace qm
