// Size refinement of a cone route's quads (beyond the method): where a few quads
// are a little larger than the size band allows (issue 18: none above 3 x the
// size), the chords (quad_chords.h) through them are split. A cone metric's
// largest quads sit where its cones are few (between a wheel's bore and its
// lightening holes: one 3.09 x the size); a finer lattice shrinks every quad, and
// the cones placed again at its size move with it, while a chord split halves only
// the strips through the large quads and adds no irregular vertex: the cones, the
// corners' quad counts, chi and the boundary loops stay as they are.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <cstddef>
#include <vector>

namespace qm {

struct SizeRefinementOptions {
  double size = 0;           ///< the requested quad size (> 0), the ratios' unit
  double max_ratio = 3.0;    ///< the chords through the quads whose mean edge is above max_ratio x size are split
  int max_rounds = 4;
  /// A round may not turn a quad over nor take the smallest scaled Jacobian
  /// (sound_scaled_jacobian, quad_quality.h) below this (or below its value
  /// before, when that is lower): it is undone, and the refinement stops.
  double min_scaled_jacobian = 0.3;
};

struct SizeRefinementReport {
  double max_ratio_before = 0;  ///< the largest quad's mean edge / size, before
  double max_ratio_after = 0;   ///< and after
  std::size_t chords_split = 0;
  std::size_t quads_added = 0;
  int rounds = 0;
  int rounds_undone = 0;
};

/// Splits the chords through the quads above options.max_ratio x options.size,
/// round by round (a near-square quad both its chords, another the chord across
/// its long sides), until none is above it, a round is undone or max_rounds are
/// done. New points are placed on `surface` (on its boundary for boundary edges);
/// `boundary_loop_of_point` (per quad point, the boundary loop or -1) is extended
/// for them. Precondition: options.size > 0; `adjacency` is surface's.
SizeRefinementReport refine_to_size(const TriangleSoup& surface, const SurfaceAdjacency& adjacency,
                                    LatticeQuads& quads, std::vector<int>& boundary_loop_of_point,
                                    const SizeRefinementOptions& options);

}  // namespace qm
