// Gmsh post-processing views: a mesh with per-element fields that the Gmsh GUI shows
// (File > Open VIEWS.msh), written atomically like every output.
#pragma once

#include "io/write_mesh.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace qm::io {

/// A vector per face (|faces| x 3): Gmsh "ElementData" with 3 components.
struct FaceVectorView {
  std::string name;
  Eigen::MatrixX3d vectors;
};

/// A value per face corner (|faces| x 3, corners in the face's order): Gmsh
/// "ElementNodeData", discontinuous across faces (values on a cut surface).
struct CornerScalarView {
  std::string name;
  Eigen::MatrixX3d values;
};

/// Writes mesh (triangles only) with its groups, then every view, to a .msh file.
void write_views(const std::string& path, const OutputMesh& mesh,
                 const std::vector<FaceVectorView>& vectors,
                 const std::vector<CornerScalarView>& scalars);

}  // namespace qm::io
