// quadmesh: boundary-aligned quad meshes of surfaces with boundaries, from
// symmetric holomorphic differentials. See README.md for every option.
#include "tools/common/exit_codes.h"
#include "tools/quadmesh/commands.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>

namespace {

using namespace qm::tools;

void print_error(const std::string& message) {
  fmt::print(stderr, "quadmesh: error: {}\n", message);
}

int run(int argc, char** argv) {
  CLI::App app{"quadmesh: boundary-aligned pure-quad meshes from symmetric holomorphic differentials",
               "quadmesh"};
  app.set_version_flag("--version", "quadmesh 0.1.0");
  app.require_subcommand(1);
  CommonOptions common;
  app.add_flag("-q,--quiet", common.quiet, "No progress lines on stderr");
  app.add_flag("--largest-component", common.largest_component,
               "Keep only the largest connected component of the input");
  app.add_option("--cad-mesh-size", common.cad_mesh_size,
                 "CAD input: Gmsh triangle size (default: a third of the quad size)")
      ->check(CLI::NonNegativeNumber);

  InfoOptions info;
  CLI::App* info_cmd = app.add_subcommand("info", "Topology of a surface and whether the method applies");
  info_cmd->add_option("FILE", info.input, "Input surface")->required();
  info_cmd->add_flag("--json", info.json, "Print one JSON object instead of text");

  FormsOptions forms;
  CLI::App* forms_cmd =
      app.add_subcommand("forms", "Symmetric holomorphic differentials, their zeros and residuals");
  forms_cmd->add_option("FILE", forms.input, "Input surface")->required();
  forms_cmd->add_flag("--json", forms.json, "Print one JSON object instead of text");
  forms_cmd->add_option("-o,--output", forms.views,
                        "Write the input with the forms as Gmsh views (.msh) to this file");
  forms_cmd->add_flag("--remesh", forms.remesh,
                      "Remesh isotropically first (boundary kept): cures slivers and coarse obtuse meshes");
  forms_cmd->add_flag("--repair", forms.repair,
                      "Cure negative cotangent weights: flip where flat, split elsewhere (after --remesh)");
  forms_cmd->add_option("--remesh-size", forms.remesh_size,
                        "Target edge length of --remesh (default: 0.4 x the mean edge length)")
      ->check(CLI::PositiveNumber);

  MeshOptions mesh;
  CLI::App* mesh_cmd = app.add_subcommand("mesh", "Quad-mesh a surface");
  mesh_cmd->add_option("FILE", mesh.input, "Input surface")->required();
  mesh_cmd->add_option("-o,--output", mesh.output, "Output mesh (format from the extension)")
      ->required();
  mesh_cmd->add_option("--size", mesh.size,
                       "Target quad edge length (default: 1/60 of the bounding-box diagonal)")
      ->check(CLI::PositiveNumber);
  mesh_cmd->add_option("--msh-version", mesh.msh_version, "MSH output version: 4.1 or 2.2")
      ->check(CLI::IsMember({4.1, 2.2}));

  // Options given after the subcommand apply too (quadmesh mesh f.obj -o g.msh --quiet).
  for (CLI::App* sub : {info_cmd, forms_cmd, mesh_cmd}) {
    sub->add_flag("-q,--quiet", common.quiet, "No progress lines on stderr");
    sub->add_flag("--largest-component", common.largest_component,
                  "Keep only the largest connected component of the input");
    sub->add_option("--cad-mesh-size", common.cad_mesh_size,
                    "CAD input: Gmsh triangle size (default: a third of the quad size)")
        ->check(CLI::NonNegativeNumber);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return exit_usage;
  }
  if (info_cmd->parsed()) return run_info(info, common);
  if (forms_cmd->parsed()) return run_forms(forms, common);
  return run_mesh(mesh, common);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const qm::Error& e) {
    print_error(e.what());
    return exit_code_for(e.code());
  } catch (const std::exception& e) {
    print_error(fmt::format("internal error: {}", e.what()));
    return exit_internal;
  }
}
