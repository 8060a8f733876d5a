// One round of chord splitting (quad_chords.h) through the quads a per-quad
// measure puts above a threshold, with the new points placed on S: what the
// deviation refinement (deviation_refinement.h) and the size refinement
// (size_refinement.h) both do, each with its own measure.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/internal/closest_location.h"
#include "libquadmesh/extract/lattice_quads.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/quality/internal/triangle_tree.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace qm {

/// Places new points on S: boundary midpoints on S's boundary, the others on S
/// (closest point).
class ChordPointPlacement {
 public:
  ChordPointPlacement(const TriangleSoup& s, const SurfaceAdjacency& adjacency, const TriangleTree& surface);
  std::pair<Vec3, SurfaceLocation> on_surface(const Vec3& guess) const;
  std::pair<Vec3, SurfaceLocation> on_boundary(const Vec3& guess) const;

 private:
  const Vec3& point(int v) const { return s_.points[static_cast<std::size_t>(v)]; }
  const TriangleSoup& s_;
  const SurfaceAdjacency& adjacency_;
  const TriangleTree& surface_;
  std::vector<std::pair<int, int>> ends_;  ///< per boundary segment, its two vertices
  SegmentTree boundary_;
};

/// Per quad, the value a refinement brings down (its deviation from S, its size).
using QuadMeasure = std::function<std::vector<double>(const LatticeQuads&)>;

/// One round: splits the chords through the quads whose `values` exceed
/// `threshold`, largest first, as long as the quad count stays within `max_quads`,
/// taking no further quad once `max_chosen` chords are taken (a near-square quad
/// gives two; another quad its chord across its long sides) and leaving out the
/// `forbidden` ones (quad, direction); places the new points (extending
/// `boundary_loop_of_point`) and sets `values` to `measure` of the new quads.
/// Returns the number of chords split; `chosen_crossings` says which.
std::size_t split_chord_round(const ChordPointPlacement& placement, const QuadMeasure& measure, LatticeQuads& quads,
                              std::vector<int>& boundary_loop_of_point, std::vector<double>& values,
                              double threshold, std::size_t max_quads,
                              const std::vector<std::pair<int, int>>& forbidden, std::size_t max_chosen,
                              std::vector<std::pair<int, int>>& chosen_crossings);

/// split_chord_round, undone (quads, boundary_loop_of_point and values put back)
/// when it turns more quads over than `inverted` or takes the smallest scaled
/// Jacobian below `jacobian_floor`: a new point placed on S by closest point can
/// fall where the split quads turn over or get thin. Returns the chords split (0:
/// none was chosen), nothing when the round was undone; after a kept round
/// `inverted` is its count.
std::optional<std::size_t> split_chord_round_or_undo(const ChordPointPlacement& placement, const QuadMeasure& measure,
                                                     LatticeQuads& quads, std::vector<int>& boundary_loop_of_point,
                                                     std::vector<double>& values, double threshold,
                                                     std::size_t max_quads,
                                                     const std::vector<std::pair<int, int>>& forbidden,
                                                     std::size_t max_chosen,
                                                     std::vector<std::pair<int, int>>& chosen_crossings,
                                                     std::size_t& inverted, double jacobian_floor);

/// The quads with a corner whose scaled Jacobian (the quality module's,
/// sound_scaled_jacobians) is <= 0, and the smallest scaled Jacobian (1 without quads).
std::pair<std::size_t, double> inverted_quad_count(const LatticeQuads& quads);

}  // namespace qm
