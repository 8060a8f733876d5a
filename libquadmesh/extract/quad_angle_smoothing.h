// Angle smoothing: regular interior quad corners moved on S so that the corner
// angles come closer to 90 degrees (method.md section 10 reports their mean
// deviation; issue 4 asks for at most 5 degrees).
//
// Where |h| varies fast (round small holes, beside convex corners and zeros) the
// pulled-back grid lines curve within a cell, and the quads, whose sides are the
// straight chords between lattice points, lose their right angles although the
// grid's lines still cross at right angles. Moving each regular interior point
// (valence 4, off the boundary; the singular vertices and every boundary point
// stay) to lower the sum of the deviations |angle - 90| of the corners of its four
// quads (the measure issue 4 bounds; squared deviations lower the spread but can
// raise the mean), in the manner of angle-based smoothing [Zhou & Shimada 2000], takes
// most of that back without touching the grid's structure.
// Each move is a step down the numerical gradient in the tangent plane, put back
// on S by closest point, and kept only if the sum went down and the smallest scaled
// Jacobian of its quads stays at least min(before, keep_jacobian). Then the quads
// that came out worse (a scaled Jacobian below min(before, keep_jacobian) with the
// final normals; a deviation from S grown past max(before, max_deviation), on
// either side, S's side sampled at its vertices: a point sliding along a curved
// part makes its quads cut across S or leaves a tip of S farther away) have their
// corners and their neighbours' put back (all of them if that is not enough).
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"

#include <vector>

namespace qm {

struct QuadAngleSmoothingOptions {
  int rounds = 4;               ///< sweeps over the points at most; one that moves nothing ends it
  /// Then, while the quads' mean corner deviation from 90 degrees is above this
  /// (degrees; 0: never), up to extra_rounds more sweeps: a plate whose squared holes
  /// leave 5.03 degrees after four sweeps has 4.63 after eight.
  double target_mean_deg = 0;
  int extra_rounds = 8;
  double max_move = 0;          ///< no point ends farther than this from where it started (0: no limit)
  /// A move may lower a quad's scaled Jacobian (sound_scaled_jacobian,
  /// quad_quality.h: Verdict's, capped by the normal consistency) down to this, no further.
  double keep_jacobian = 0.5;
  /// A quad's deviation from S may grow up to this (or stay where it was, if that
  /// was more); 0: no check.
  double max_deviation = 0;
  /// A quad's mean edge may not cross this (from at most this before to above it
  /// after); 0: no check. The largest quad the size band allows: a plate with two
  /// slots, its quads within 2.97 x the size as mapped, had one at 3.01 x after
  /// the moves.
  double max_mean_edge = 0;
  /// A point moves only while a corner of its quads is this far from 90 degrees
  /// or farther: the corners of a point within it cannot gain more, and such points
  /// are most of a fine grid (issue 21: the sweep's cost follows the quads that
  /// need it, not all of them).
  double min_corner_deviation_deg = 3.0;
};

struct QuadAngleSmoothingReport {
  std::size_t moved_points = 0;  ///< distinct points moved
  double angle_dev_before = 0;   ///< mean |corner angle - 90| over every quad corner, degrees
  double angle_dev_after = 0;
};

/// Precondition: `boundary_loop_of_point` has one entry per point (-1: interior);
/// `fixed` is empty or has one entry per point (non-zero: the point stays, e.g.
/// a corner the fitting put on a protrusion's tip). Moved points become face
/// locations of `surface`. When the mean deviation does not come out lower, nothing
/// is moved.
QuadAngleSmoothingReport smooth_quad_angles(const TriangleSoup& surface, LatticeQuads& quads,
                                            const std::vector<int>& boundary_loop_of_point,
                                            const std::vector<char>& fixed,
                                            const QuadAngleSmoothingOptions& options = {});

}  // namespace qm
