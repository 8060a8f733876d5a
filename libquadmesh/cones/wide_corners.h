// Triangle corners the cone metric opens too wide to map (method.md section 11).
//
// The flat cone metric moves all of the surface's curvature to the cones: a vertex
// in n quads gets the total angle n pi/2, and its triangles' corners open in
// proportion, a corner of angle a at a vertex of total angle A to about
// a n (pi/2) / A. A corner opened to pi or more cannot be mapped without folding
// its triangle, whatever the quantization does: a valence-5 cone at the midpoint
// of a split edge (a 161-degree corner becomes 201 degrees: pig), a 270-degree
// corner on a coarse polygon spanned by one or two triangles. Such corners are
// bisected before the map: the edge opposite them is split where the corner's
// bisector meets it (the new point lies on the edge, so the surface is unchanged).
#pragma once

#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

namespace qm {

/// The widest a corner may open (radians): below pi with a margin, as the fit
/// bends the metric's angles near cones.
constexpr double max_opened_corner = 0.95 * M_PI;

/// The widest a corner at a boundary vertex the metric turns may open (radians):
/// wider, its triangle is split (split_turned_boundary).
constexpr double max_turned_corner = 0.5 * M_PI;

/// Per triangle corner (3 f + k), the angle the cone metric opens it to: its angle
/// times n pi/2 over its vertex's total angle, n from quads_per_vertex.
std::vector<double> opened_corners(const TriangleSoup& soup, const std::vector<int>& quads);

struct WideCornerSplits {
  std::size_t splits = 0;
  SurfaceAdjacency adjacency;  ///< of the soup as the splits leave it
};

/// Splits the edge opposite every corner at a cone (a vertex in other than 4
/// quads inside, 2 on the boundary: a regular vertex keeps about its own angles)
/// opened wider than `max_opened` (radians),
/// pass after pass until none is (at most 8 passes); returns the splits and the
/// soup's adjacency afterwards (built once per pass: the caller need not). Points
/// keep their indices (the cones stay where they are); new points are regular.
/// CAD curve edges are split with their curve. Precondition: an oriented manifold
/// soup; `cones` valid for it (quads_per_vertex).
WideCornerSplits split_wide_corners(TriangleSoup& soup, const std::vector<Cone>& cones,
                               double max_opened = max_opened_corner);

/// Splits, at every boundary vertex whose angle in its quads (quads_per_vertex)
/// differs from its own by more than its inner edges can turn (the sum of their
/// cotangent weights: a turn over that would make the cone metric's u jump by more
/// than 1 there), the edge opposite each of its corners the metric opens wider
/// than max_turned_corner, or else its widest corner's, as split_wide_corners
/// does, pass after pass. Such a vertex is a tooth of a scanned boundary that the
/// corners at the quad scale make straight (boundary_corners.h), or a corner whose
/// angle at that scale is not its own, in one or two triangles whose one inner
/// edge has little weight, or none; unsplit, u would jump by tens there (the scale
/// by 10^20) or the metric could not turn it at all. An edge that bisects a corner
/// of angle a has weight sin(a) / (2 sin(b) sin(c)), b and c the triangle's other
/// two angles. Nothing on a CAD part, whose corners are their own angle.
/// Precondition as split_wide_corners.
WideCornerSplits split_turned_boundary(TriangleSoup& soup, const std::vector<Cone>& cones);

}  // namespace qm
