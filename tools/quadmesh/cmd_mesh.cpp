#include "io/write_mesh.h"
#include "libquadmesh/pipeline/mesh_quads.h"
#include "tools/common/exit_codes.h"
#include "tools/common/input_surface.h"
#include "tools/quadmesh/commands.h"
#include "tools/quadmesh/quad_output.h"

#include <fmt/format.h>

#include <filesystem>

namespace qm::tools {

namespace {
/// The report's folder must exist (any extension; .json is the habit).
bool report_path_usable(const std::string& path) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty() || std::filesystem::is_directory(folder)) return true;
  fmt::print(stderr, "quadmesh: error: {}: the folder {} does not exist\n", path, folder.string());
  return false;
}
}  // namespace

int run_mesh(const MeshOptions& options, const CommonOptions& common) {
  if (!output_path_usable(options.output)) return exit_usage;
  if (!options.report.empty() && !report_path_usable(options.report)) return exit_usage;
  const Progress progress(common.quiet);
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  read.quad_size = options.size;
  read.quad_size_relative = options.size_relative;
  const InputSurface in = load_input_surface(options.input, read, common.largest_component, progress);
  require_supported(in.surface);
  progress.stage(assess_applicability(in.surface).reason);

  QuadMeshOptions mesher;
  mesher.form = options.form;
  mesher.coefficients = options.coefficients;
  mesher.rotate = options.rotate;
  mesher.size = options.size;
  mesher.size_relative = options.size_relative;
  mesher.quads = options.quads;
  mesher.corner_angle_deg = options.corner_angle_deg;
  const QuadMeshResult result =
      mesh_quads(in.surface.soup, mesher, [&](const std::string& stage) { progress.stage(stage); });

  progress.stage("measuring quality");
  const MeshSummary summary = summarize(in, result, options, progress.elapsed());
  progress.stage(fmt::format("writing {}", options.output));
  io::WriteOptions write;
  write.msh_version = options.msh_version;
  io::write_mesh(options.output, output_mesh(result), write);
  if (!options.report.empty()) write_report(options.report, summary);
  print_summary(summary);
  return exit_ok;
}

}  // namespace qm::tools
