// One output mesh for an assembly's parts (quadmesh mesh --each-component): the
// parts' meshes side by side, one physical surface per part.
#pragma once

#include "io/write_mesh.h"

#include <string>
#include <vector>

namespace qm::tools {

struct PartOutput {
  std::string name;     ///< the part's physical surface name
  io::OutputMesh mesh;  ///< the part alone, as `quadmesh mesh` writes one surface
};

/// The parts' meshes in one: points and faces appended in part order (no point
/// is shared between parts), a surface group per part named after it. A part's
/// line group keeps its name when it comes from CAD (a physical curve: the same
/// name in several parts makes one group) and is called "PART_boundary_k" when it
/// is the part's own boundary_k; point groups of the same name are merged.
io::OutputMesh assembly_output(const std::vector<PartOutput>& parts);

}  // namespace qm::tools
