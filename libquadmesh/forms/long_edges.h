// Triangles larger than the quads (method.md section 9: the quad vertices are
// interpolated linearly in the triangles of S, so a triangle wider than a cell
// carries its one linear map, with the Galerkin form's non-conformality, across
// several quads). Splitting such triangles before the forms are computed gives the
// map the resolution of the quads where the input is coarse, and keeps every
// input vertex (unlike isotropic remeshing, which moves them all).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

namespace qm {

/// Longest-edge bisection: while a triangle's longest edge is longer than
/// `max_length`, that edge is split at its midpoint (each of its one or two
/// triangles into two; a triangle takes one split per pass). CAD curve edges are
/// split with their curve; new points get label -1 and new triangles their
/// parent's label. Where the input has flat faces (two neighbours in one plane:
/// a CAD part's STL), the needles each pass leaves there (an angle under 10
/// degrees) are flipped to the Delaunay diagonal of the two triangles at an edge,
/// within one plane and never across a CAD curve: a face of slivers is split
/// into about as many triangles as its area needs, not fanned out into needles.
/// A scan (no two triangles in one plane) is bisected only. Returns the number of
/// splits. Precondition: an oriented manifold soup; max_length > 0.
std::size_t split_long_edges(TriangleSoup& soup, double max_length);

/// The fraction of the surface's area in triangles with an edge longer than
/// `max_length` (0 for an empty soup).
double long_edge_area_fraction(const TriangleSoup& soup, double max_length);

}  // namespace qm
