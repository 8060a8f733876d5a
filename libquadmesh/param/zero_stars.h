// Zeros become vertices with a fine enough star (method.md section 6, "What
// discrete forms really do"; issue: "zeros become vertices").
//
// A zero of order m is placed at a vertex z (the cluster's representative). The
// quantized map is later fixed on z's star to the local model z^(m+1) (see
// quantization.h), which is fold-free only if every corner at z spans less than
// pi / (m + 1) of the scaled angle (2 pi around an interior vertex, pi at a
// boundary vertex, rescaled from the 3D angle sum). Corners that are too wide are
// bisected by splitting the opposite edge at its midpoint; every face map is
// carried over exactly (a closed form is linear along the split edge).
#pragma once

#include <cmath>
#include <functional>
#include <unordered_map>

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

namespace qm {

/// A cone of the parameterization: a zero of h placed at a vertex, or a sharp
/// boundary corner (order 0: its image angle is pi, whatever its 3D angle).
struct ZeroVertex {
  int vertex = -1;
  int order = 0;            ///< interior: on S; boundary: on the double
  bool on_boundary = false;
  bool corner = false;      ///< a sharp boundary corner rather than a zero
  /// The total image angle: 2 pi (m + 1) inside, pi (m + 1) on the boundary.
  double image_angle() const { return (on_boundary ? M_PI : 2 * M_PI) * (order + 1); }
};

/// The vertices within `radius` of `source` in the image metric of `map` (shortest
/// paths along edges, edge length |map(e)|), with their distances; `source` at 0.
std::unordered_map<int, double> image_ball(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                           const FaceMap& map, int source, double radius);

/// The same, grown in order of distance until a vertex (other than `source`) for
/// which `stop_at` is true is reached: that vertex is the last one settled.
std::unordered_map<int, double> image_ball(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                           const FaceMap& map, int source, double radius,
                                           const std::function<bool(int)>& stop_at);

/// Zeros closer than `radius` in the image of `map` (shortest paths along edges,
/// edge length |map(e)|) cannot be separated by the grid (two zeros of one boundary
/// loop can, down to radius / 10: they need distinct integers U only, which the
/// quantization gives consecutive ones; zeros of two loops are never merged, each
/// loop turns by its own zeros): they are merged into one
/// zero whose order is the sum of theirs (counted on the double when the merged
/// zero is on the boundary), placed at the boundary zero of highest order if there
/// is one, else at the zero of highest order. Before that, an interior zero of
/// order m within 0.75 radius of the boundary (it would round onto the boundary's
/// level) becomes a boundary zero of order 2m at the nearest boundary vertex: on
/// the double it meets its mirror image there.
std::vector<ZeroVertex> merge_close_zeros(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                          const FaceMap& map, std::vector<ZeroVertex> zeros, double radius);

/// Sharp boundary corners as order-0 cones (skipping `taken` vertices): vertices
/// where the boundary turns by more than `corner_angle_deg`, measured between the
/// chords to the boundary points at arc length `scale` on either side (so that a
/// jagged scanned boundary is smooth at the quad size), that turn at least 0.6 of
/// that within a quarter of `scale` (a smooth bend, e.g. a small round hole, turns in
/// proportion to the distance), turn more than 2.5 times the loop's median turning
/// (a coarse polygon around a round hole turns at every vertex), and are the
/// sharpest within `scale` along their loop.
std::vector<ZeroVertex> boundary_corners(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                         double corner_angle_deg, double scale,
                                         const std::vector<ZeroVertex>& taken);


/// Adds the sharp boundary `corners` to `zeros`. A boundary zero closer than
/// `radius` to a corner in the image of `map` could not take a different lattice
/// point from it: that zero moves onto the corner vertex (the corner is where the
/// boundary really turns) and the corner is not added separately.
std::vector<ZeroVertex> add_corners(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const FaceMap& map,
                                    std::vector<ZeroVertex> zeros, const std::vector<ZeroVertex>& corners,
                                    double radius);

/// The largest image angle of a triangle corner of a model star, in radians: the
/// 3D corner angle times image_angle / (3D angle sum at the cone) stays below it.
constexpr double max_model_corner_angle = 0.6 * M_PI;

/// Splits edges opposite the zeros until every star is fine enough; returns the
/// number of splits. The soup's new points get label -1 and CAD curve edges are
/// split with their curve; `maps` are updated in place.
std::size_t refine_zero_stars(TriangleSoup& soup, std::vector<FaceMap*> maps,
                              const std::vector<ZeroVertex>& zeros);

/// Splits the edge {a, b} at its midpoint (its one or two triangles into two each).
void split_edge(TriangleSoup& soup, std::vector<FaceMap*>& maps, int a, int b);

}  // namespace qm
