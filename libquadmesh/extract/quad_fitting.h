// Fitting the quads to S where they cut across it (beyond the method): on a
// protrusion the quads are several times the requested size (1 / (s |h|) grows
// as |h| decays), and a tip or a ridge of S between their corners is cut off.
// Chord splitting (deviation_refinement.h) pays for that with whole rows of quads
// that wind round the body; moving a few corners onto the tip costs nothing.
// Where a sample of S is farther than a tolerance from the quads, the regular
// interior corners of its nearest quad are tried on S towards it; a move is kept
// when it lowers the largest distance between the quads around it and S (both
// ways) and keeps their scaled Jacobian. The grid's structure, and so the
// singular vertices, are untouched.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"

#include <cstddef>
#include <vector>

namespace qm {

struct QuadFittingOptions {
  double tolerance = 0;  ///< samples of S farther than this (absolute, > 0) from the quads pull corners
  /// A move may not take the smallest sound_scaled_jacobian (quad_quality.h:
  /// Verdict's, capped by the normal consistency) of its quads below this (or
  /// below its value before the move, when that is lower).
  double min_scaled_jacobian = 0.35;
  int rounds = 8;  ///< at most; a round that moves nothing ends it
};

struct QuadFittingReport {
  std::size_t moved_points = 0;  ///< distinct points moved
  double deviation_before = 0;   ///< largest quad_deviation(), before
  /// and after: an upper bound of it (each sample of S measured against the quad
  /// it was last assigned to), equal unless a sample came nearer to another quad
  double deviation_after = 0;
};

/// A move is evaluated on the quads at the point and the samples of S assigned to
/// them, against the quads sharing a point with those (its ring); the
/// tries are the corner on S at 1, 0.6 and 0.3 of the way to the sample.
/// Precondition: `boundary_loop_of_point` has one entry per point (-1: interior).
/// Points move on `surface`; their `locations` become face locations there. When
/// the largest deviation or the smallest scaled Jacobian comes out worse as a
/// whole, every move is undone.
QuadFittingReport fit_quads_to_surface(const TriangleSoup& surface, LatticeQuads& quads,
                                       const std::vector<int>& boundary_loop_of_point,
                                       const QuadFittingOptions& options);

}  // namespace qm
