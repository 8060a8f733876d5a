#include "tools/common/exit_codes.h"
#include "tools/quadmesh/commands.h"
#include "tools/quadmesh/topology_summary.h"

#include <fmt/format.h>

namespace qm::tools {

int run_info(const InfoOptions& info, const CommonOptions& common) {
  const Progress progress(common.quiet || info.json);
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  const InputSurface in = load_input_surface(info.input, read, common.largest_component, progress);
  const Applicability verdict = assess_applicability(in.surface);
  if (info.json)
    fmt::print("{}\n", topology_json(in, verdict).dump(2));
  else
    fmt::print("{}", topology_text(in, verdict));
  return verdict.supported ? exit_ok : exit_code_for(verdict.code);
}

}  // namespace qm::tools
