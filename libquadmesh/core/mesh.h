// The one mesh type of the core (docs/style.md item 4): a CGAL Surface_mesh
// over an exact-predicates kernel. Per-element data lives in property maps or in
// Eigen vectors indexed by the mesh's indices.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <array>

namespace qm {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point3>;

/// Builds the halfedge mesh of a consistently oriented, manifold soup (the soup of
/// a supported AnalyzedSurface). Vertex i and face f of the mesh are point i and
/// triangle f of the soup. Precondition: the soup passed assess_applicability.
Mesh to_surface_mesh(const TriangleSoup& soup);

/// The vertices of triangle f in the order used for per-corner data and soups:
/// target(h) for h around f starting at halfedge(f).
std::array<int, 3> face_corners(const Mesh& mesh, Mesh::Face_index f);

/// The soup of a mesh without removed elements whose first vertices are those of
/// `before` (same indices): their labels are kept, added vertices get label -1.
TriangleSoup soup_of(const Mesh& mesh, const TriangleSoup& before);

}  // namespace qm
