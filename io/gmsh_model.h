// Building a Gmsh model from an OutputMesh (for writers that add more to it, such as
// post-processing views). Call inside a GmshSession.
#pragma once

#include "io/gmsh_session.h"
#include "io/write_mesh.h"

#include <vector>

namespace qm::io {

/// Adds the mesh as model "quadmesh": nodes 1..n are points 0..n-1; returns the
/// element tag of every face (in face order). Line and point groups become named
/// physical groups, the faces the physical surface mesh.surface_group.
std::vector<std::size_t> add_to_gmsh_model(const OutputMesh& mesh);

/// Writes the current model's mesh to `path` (format from the extension); throws
/// qm::Error(bad_input) with Gmsh's error.
void write_gmsh_model(const std::string& path, const WriteOptions& options,
                      const GmshSession& session);

}  // namespace qm::io
