// Reading a polygon (quad or quad-dominant) mesh, e.g. a result to be measured by
// `quadmesh quality`. Unlike read_surface, faces are kept as they are.
#pragma once

#include "libquadmesh/quality/quad_quality.h"

#include <string>

namespace qm::io {

/// The faces of a mesh file with their points, unreferenced points dropped.
///  - .obj .off .ply (CGAL): every polygon of the file, in its own orientation;
///  - every other readable format (Gmsh SDK): the 3-node triangles and 4-node quads
///    of all entities (Gmsh's CCW node order), points in order of first use.
/// Throws qm::Error(bad_input) with a one-line message "<path>: <problem>" on a
/// missing, empty, unreadable or unparsable file, a face with fewer than three
/// vertices or one out of range, or a file without triangles or quads.
PolygonMesh read_polygon_mesh(const std::string& path);

}  // namespace qm::io
