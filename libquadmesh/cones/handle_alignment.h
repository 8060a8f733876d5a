// Aligning the cross field around the handles of S (method.md section 11: the
// holonomy of the field around every non-contractible loop must be a multiple of
// pi/2; a trivial connection fixes what the cones leave [Crane, Desbrun,
// Schroeder 2010]).
//
// On a surface of genus g > 0 the field propagated along a tree of triangles
// (cross_field.h) meets itself, around each of the 2g handle loops, turned by an
// angle that no cone set chosen independently of it makes a multiple of pi/2. A
// rotation added to the connection across every inner edge that is a closed form
// (its sum around every vertex 0: the cones and the boundary vertices keep their
// turning) changes those holonomies by its periods. The forms here are the
// Poincare duals of 2g cycles of inner edges, one through each handle (a
// tree-cotree decomposition with every hole capped): crossing its cycle from right
// to left adds 1, its periods are intersection numbers. Each is then made harmonic
// on the graph of triangles (uniform weights) with the triangles at the boundary
// held at 0, which spreads the turn over the handle instead of putting it on one
// seam and keeps every boundary loop where it was.
#pragma once

#include "libquadmesh/param/internal/surface_adjacency.h"

#include <array>
#include <vector>

namespace qm {

/// A rotation on the inner edges: per triangle and side k (corner k to k + 1), the
/// turn added crossing that side out of the triangle; the twin side holds its
/// negative, boundary sides hold 0.
using SideForm = std::vector<std::array<double, 3>>;

/// The harmonic forms dual to the handle cycles (2g of them on a surface of genus
/// g whose boundary vertices all have an inner edge; fewer cycles are found where
/// a tree path would need a boundary edge). Empty on a genus-0 surface.
/// Precondition: the soup is connected.
std::vector<SideForm> handle_forms(const TriangleSoup& soup, const SurfaceAdjacency& adjacency);

/// Per triangle, the turn sum_k forms[k] at side s times coefficient[k].
SideForm combined_form(const std::vector<SideForm>& forms, const std::vector<double>& coefficient);

/// The largest |sum of a form around a vertex| (closedness; 0 up to round-off).
double max_vertex_curl(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const SideForm& form);

}  // namespace qm
