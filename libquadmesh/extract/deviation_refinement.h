// Size adaptivity without new singularities (beyond the method): the quad size of
// a conformal parameterization is 1 / (s |h|), and |h| is small on protrusions and
// near rounded convex turns of the boundary, where the quads become several times
// the requested size and cut across the surface. Where the quads deviate from S by
// more than a tolerance, the chords (quad_chords.h) through the worst quads are
// split, within a quad budget. Splitting adds only regular vertices, so the
// singular vertices stay exactly the zeros; new points are placed on S (on its
// boundary for boundary edges) by closest-point projection.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <array>
#include <cstddef>
#include <vector>

namespace qm {

struct DeviationRefinementOptions {
  double tolerance = 0;         ///< largest distance allowed between the quads and S (absolute; > 0)
  std::size_t max_quads = 0;    ///< no split that would take the quad count above this
  int max_rounds = 40;
  /// Then, while the count is below this, the chords through the quads above 0.8
  /// of the largest deviation are split (one round at a time, within min_quads):
  /// what is left of a budget goes to the largest deviations. 0: none.
  std::size_t min_quads = 0;
  /// A round may not take the smallest scaled Jacobian (sound_scaled_jacobian,
  /// quad_quality.h: Verdict's, capped by the normal consistency) below this (or below its
  /// value before the refinement, when that is lower).
  double min_scaled_jacobian = 0.3;
};

struct DeviationRefinementReport {
  double deviation_before = 0;  ///< estimated max distance between the quads and S, before
  double deviation_after = 0;   ///< and after
  std::size_t chords_split = 0;
  std::size_t quads_added = 0;
  int rounds = 0;
  bool tolerance_met = false;   ///< after the rounds within max_quads (before the min_quads rounds)
  /// splits undone: they turned a quad over (or made one too thin). The round is
  /// tried again one quad's chords at a time, leaving out those that fail alone;
  /// the refinement stops when 8 such tries fail
  int rounds_undone = 0;
};

/// The points of a quad (corners in order) whose distance to S is its side of
/// the deviation: its centre, the centroids of its triangles v0v1v2 and v0v2v3,
/// and its edge midpoints (the corners are on S).
std::array<Vec3, 7> quad_deviation_samples(const std::array<Vec3, 4>& corners);

/// The quads' triangles v0v1v2 and v0v2v3 (split as the quality module splits
/// them), each with its quad as id (degenerate ones left out: it may be empty).
TriangleTree quad_triangle_tree(const LatticeQuads& quads);

/// The quad's side of the deviation: the largest distance from its
/// quad_deviation_samples() to S (`surface`: a tree on S's triangles).
double quad_to_surface(const TriangleTree& surface, const std::array<Vec3, 4>& corners);
/// quad_to_surface() of every quad, in order, on the worker threads (core/parallel.h).
std::vector<double> quads_to_surface(const TriangleTree& surface, const LatticeQuads& quads);

/// Per quad, the estimated deviation: the largest distance from a sample of the quad
/// (its two triangles split along the diagonal v0v2, as in the quality module) to S,
/// and from a sample of S (vertices, edge midpoints, centroids) whose nearest quad
/// it is to that quad.
std::vector<double> quad_deviation(const TriangleSoup& surface, const LatticeQuads& quads);

/// The same with the tree on S's triangles and the samples of S given (the
/// vertices alone make a cheaper estimate of S's side).
std::vector<double> quad_deviation(const TriangleTree& surface, const std::vector<Vec3>& surface_samples,
                                   const LatticeQuads& quads);

/// S's side of the deviation is measured at these points: S's vertices where its
/// mean edge is at most half the tolerance (every point of S is then within about a
/// quarter of the tolerance from one: a fine scan needs no more), else its
/// vertices, edge midpoints and triangle centroids.
std::vector<Vec3> deviation_samples(const TriangleSoup& surface, double tolerance);

/// Splits chords until every quad's deviation is within options.tolerance, the
/// budget is spent, or a round brings nothing; then up to options.min_quads. `boundary_loop_of_point` (per quad
/// point, the boundary loop or -1) is extended for the new points; the new points'
/// locations refer to `surface`.
DeviationRefinementReport refine_to_deviation(const TriangleSoup& surface,
                                              const SurfaceAdjacency& adjacency, LatticeQuads& quads,
                                              std::vector<int>& boundary_loop_of_point,
                                              const DeviationRefinementOptions& options);

}  // namespace qm
