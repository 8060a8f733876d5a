#include "io/write_mesh.h"
#include "tools/common/exit_codes.h"
#include "tools/common/input_surface.h"
#include "tools/quadmesh/commands.h"

#include <fmt/format.h>

namespace qm::tools {

int run_mesh(const MeshOptions& mesh, const CommonOptions& common) {
  if (!output_path_usable(mesh.output)) return exit_usage;
  const Progress progress(common.quiet);
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  read.quad_size = mesh.size;
  const InputSurface in = load_input_surface(mesh.input, read, common.largest_component, progress);
  require_supported(in.surface);
  progress.stage(assess_applicability(in.surface).reason);
  throw Error(ErrorCode::unsupported,
              "the quad mesher is not implemented yet: the input passed every check, no output "
              "was written");
}

}  // namespace qm::tools
