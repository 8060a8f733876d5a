// quadmesh: boundary-aligned quad meshes of surfaces with boundaries, from
// symmetric holomorphic differentials. See README.md for every option.
#include "io/read_surface.h"
#include "tools/common/exit_codes.h"
#include "tools/quadmesh/commands.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

namespace {

using namespace qm::tools;

/// CLI11 check of --size: a positive length or a percentage of the diagonal.
std::string size_or_percent(const std::string& v) {
  try {
    std::size_t used = 0;
    const double x = std::stod(v, &used);
    const bool percent = used + 1 == v.size() && v.back() == '%';
    if (x > 0 && (used == v.size() || percent)) return std::string();
  } catch (const std::exception&) {
  }
  return std::string("must be a positive length or a percentage such as 1.5%");
}

/// Stores a validated `size_or_percent` text: a length in `absolute`, or P% as P/100
/// in `relative`; an empty text leaves both as they are.
void set_length_or_percent(const std::string& text, double& absolute, double& relative) {
  if (text.empty()) return;
  if (text.back() == '%')
    relative = std::stod(text) / 100.0;
  else
    absolute = std::stod(text);
}

/// CLI11 check of --cad-timeout and --cad-memory: a finite number above 0.
std::string positive_finite(const std::string& v) {
  try {
    std::size_t used = 0;
    const double x = std::stod(v, &used);
    if (used == v.size() && std::isfinite(x) && x > 0) return std::string();
  } catch (const std::exception&) {
  }
  return std::string("must be a positive number");
}

/// The options that put Gmsh in its sandbox (io::CadSandbox), on `app` or a subcommand.
void add_cad_sandbox_options(CLI::App& app, CommonOptions& common) {
  app.add_option("--cad-timeout", common.cad_timeout,
                 "Seconds Gmsh may take to read and triangulate an input (default 300)")
      ->check(positive_finite);
  app.add_option("--cad-memory", common.cad_memory,
                 "GiB of memory Gmsh may use (default: 8 or 3/4 of the memory, the smaller)")
      ->check(positive_finite);
  app.add_flag("--allow-geo-commands", common.allow_geo_commands,
               ".geo input: allow SystemCall, writing files, Exit, and files outside its folder");
}

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
  add_cad_sandbox_options(app, common);

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
  std::string size_text;
  mesh_cmd->add_option("--size", size_text,
                       "Target quad edge length, or P% of the bounding-box diagonal (default: 1/60 of it)")
      ->check(size_or_percent);
  mesh_cmd->add_option("--quads", mesh.quads, "Target number of quads (instead of --size)")
      ->check(CLI::PositiveNumber);
  std::string form_choice = "auto";
  mesh_cmd->add_option("--form", form_choice,
                       "The differential: auto (most uniform |h|) or K, the K-th symmetric basis form (from 1)")
      ->check([](const std::string& v) {
        if (v == "auto") return std::string();
        try {
          std::size_t used = 0;
          if (std::stoi(v, &used) >= 1 && used == v.size()) return std::string();
        } catch (const std::exception&) {
        }
        return std::string("must be auto or a positive integer");
      });
  mesh_cmd->add_option("--coeffs", mesh.coefficients,
                       "Real coefficients c1,c2,... of h = sum c_k h_k over the symmetric basis")
      ->delimiter(',')
      ->excludes("--form");
  mesh_cmd->add_flag("--rotate", mesh.rotate, "Use i*h: the same grid turned by 90 degrees");
  mesh_cmd->add_flag("--no-smoothing", mesh.no_smoothing,
                     "Keep every quad corner where the extraction put it (no smoothing of the worst quads "
                     "or of the angles)");
  mesh_cmd->add_option("--corner-angle", mesh.corner_angle_deg,
                       "Boundary turning angle (degrees) above which a vertex is a corner put on the grid")
      ->check(CLI::Range(0.0, 180.0));
  mesh_cmd->add_option("--tip-angle", mesh.tip_angle_deg,
                       "With --form auto: boundary vertices where the surface turns this much or more "
                       "(degrees) get a zero of h, so four quads share the turn rather than two; above 360: none")
      ->check(CLI::Range(180.0, 720.0));
  std::string deviation_text;
  mesh_cmd->add_option("--max-deviation", deviation_text,
                       "Split quad strips where the quads are farther than D (or P% of the diagonal) from "
                       "the input; off: no refinement (default: half the quad size)")
      ->check([](const std::string& v) { return v == "off" || size_or_percent(v).empty() ? std::string() : std::string("must be off, a positive length or a percentage such as 0.5%"); });
  mesh_cmd->add_option("--report", mesh.report, "Write a JSON report (quality, zeros, quantization, timings)");
  mesh_cmd->add_option("--msh-version", mesh.msh_version, "MSH output version: 4.1 or 2.2")
      ->check(CLI::IsMember({4.1, 2.2}));

  QualityOptions quality;
  CLI::App* quality_cmd =
      app.add_subcommand("quality", "Quality of a quad mesh: scaled Jacobian, angles, valences, topology");
  quality_cmd->add_option("MESH", quality.input, "Mesh to measure (triangles and quads)")->required();
  quality_cmd->add_option("--reference", quality.reference,
                          "Input surface for the two-sided Hausdorff distance");
  quality_cmd->add_flag("--json", quality.json, "Print one JSON object instead of text");

  CompareOptions compare;
  CLI::App* compare_cmd = app.add_subcommand(
      "compare", "Ours against Gmsh's quad meshing on the same input and size: reports, pictures, meshes");
  compare_cmd->add_option("FILE", compare.input, "Input surface")->required();
  std::string compare_size;
  compare_cmd->add_option("--size", compare_size,
                          "Target quad edge length, or P% of the bounding-box diagonal (default: 1/60 of it)")
      ->check(size_or_percent);
  compare_cmd->add_option("--out", compare.out_dir,
                          "Folder for report.md, report.json, the pictures and every mesh "
                          "(default: compare-<input name>)");
  compare_cmd->add_option("--timeout", compare.timeout, "Seconds each method may run (default 120)")
      ->check(CLI::PositiveNumber);
  compare_cmd->add_option("--gmsh", compare.gmsh, "The Gmsh program of the baselines (default: gmsh)");

  // Options given after the subcommand apply too (quadmesh mesh f.obj -o g.msh --quiet).
  for (CLI::App* sub : {info_cmd, forms_cmd, mesh_cmd, quality_cmd, compare_cmd}) {
    sub->add_flag("-q,--quiet", common.quiet, "No progress lines on stderr");
    sub->add_flag("--largest-component", common.largest_component,
                  "Keep only the largest connected component of the input");
    sub->add_option("--cad-mesh-size", common.cad_mesh_size,
                    "CAD input: Gmsh triangle size (default: a third of the quad size)")
        ->check(CLI::NonNegativeNumber);
    add_cad_sandbox_options(*sub, common);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // one line, like every other error (CLI11's own would add a second)
    fmt::print(stderr, "quadmesh: error: {} (see quadmesh --help)\n", e.what());
    return exit_usage;
  }
  qm::io::CadSandbox& sandbox = qm::io::default_cad_sandbox();  // every read gets it
  sandbox.timeout_seconds = common.cad_timeout;
  sandbox.memory_gib = common.cad_memory;
  sandbox.allow_geo_commands = common.allow_geo_commands;
  if (info_cmd->parsed()) return run_info(info, common);
  if (forms_cmd->parsed()) return run_forms(forms, common);
  if (quality_cmd->parsed()) return run_quality(quality, common);
  if (compare_cmd->parsed()) {
    set_length_or_percent(compare_size, compare.size, compare.size_relative);
    return run_compare(compare, common);
  }
  if (form_choice != "auto") mesh.form = std::stoi(form_choice) - 1;
  set_length_or_percent(size_text, mesh.size, mesh.size_relative);
  if (deviation_text == "off")
    mesh.max_deviation = -1;
  else
    set_length_or_percent(deviation_text, mesh.max_deviation, mesh.max_deviation_relative);
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
