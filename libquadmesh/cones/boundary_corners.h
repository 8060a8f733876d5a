// The corners of a boundary at a length scale (issue 18; method.md section 11).
//
// A boundary vertex of interior angle a wants max(1, round(a / 90 deg)) quads: a
// corner cone. On a CAD part a corner is one vertex, straight or smooth on both
// sides, and its angle is its own. A scan's boundary (or a hole cut out of one)
// turns at every vertex, by up to 90 degrees either way, in teeth and steps finer
// than a quad: no quad mesh puts a quad point on each, nor should. So a corner is
// where the boundary turns within a window of the quad scale, at the vertex that
// turns most that way; the quality module counts corners (corner_quads.h) and the
// cone placement puts its corner cones (cone_placement.h) by this one definition.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <vector>

namespace qm {

/// A boundary vertex is a corner when its angle, seen at the window's scale, is
/// more than this far from 180 degrees: 45 puts the change of quad count half-way.
constexpr double corner_angle_tolerance_deg = 45.0;

/// The window, in quad edges: half a quad each way, so that two corners a quad
/// apart are both seen, and a tooth smaller than half a quad is not.
constexpr double corner_window_quads = 0.5;

/// A staircase is four or more corners in a row along a loop (two steps or more),
/// each turning the other way from the one before and less than this many quads
/// from it (a scan's voxel steps): a lattice can give such a step no height but 0
/// or a whole quad, twice the step, and the map folds between the two. Its corners
/// are not corners; an odd count keeps its net quarter turn at its sharpest corner
/// that turns that way. A low step alone, or a step and a half (a shoulder, a
/// notch, a coarse hole polygon's jog), keeps its corners.
constexpr double staircase_step_quads = 0.75;

/// A corner of a boundary loop, seen at a length scale.
struct BoundaryCorner {
  int vertex = -1;
  double angle_deg = 0;  ///< the interior angle: 180 minus the boundary's turning within the window
};

/// The corners of `surface`'s boundary at the scale `window` (> 0, a length):
/// boundary vertices where the chords to the boundary points `window` before and
/// after along the loop meet at more than `tolerance_deg` from straight, and the
/// geodesic turning within the window (the sum of pi minus the angle sums) does
/// too, and that turn that way more than any other vertex within the window (a
/// spike whose sides turn back more than it turns is not where its window's turn
/// is) and by at least half the window's turn themselves (a hole a few quads round
/// or a fillet, whose turn is spread, has none). A CAD corner (straight or smooth
/// on both sides) is found with its exact angle; the teeth of a scanned boundary
/// smaller than the window are not corners; its steps are, at their sharp vertex,
/// unless they make a staircase (staircase_step_quads, a quad being twice the
/// window). Sorted by vertex. Precondition: `surface` is a manifold triangle surface.
std::vector<BoundaryCorner> boundary_corners(const TriangleSoup& surface, double window,
                                             double tolerance_deg = corner_angle_tolerance_deg);

/// The quads a corner of interior angle `angle_deg` wants: max(1, round(angle / 90)).
int corner_quads_wanted(double angle_deg);

}  // namespace qm
