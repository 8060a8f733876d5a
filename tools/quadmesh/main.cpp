// quadmesh: boundary-aligned quad meshes of surfaces with boundaries, from
// symmetric holomorphic differentials. See README.md for every option.
#include "io/read_surface.h"
#include "libquadmesh/core/parallel.h"
#include "tools/common/exit_codes.h"
#include "tools/common/heap_settings.h"
#include "tools/common/usage_error.h"
#include "tools/quadmesh/commands.h"
#include "tools/quadmesh/library_wording.h"
#include "tools/quadmesh/option_checks.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

namespace {

using namespace qm::tools;

/// Stores a validated `size_or_percent` text: a length in `absolute`, or P% as P/100
/// in `relative`; an empty text leaves both as they are.
void set_length_or_percent(const std::string& text, double& absolute, double& relative) {
  if (text.empty()) return;
  if (text.back() == '%')
    relative = std::stod(text) / 100.0;
  else
    absolute = std::stod(text);
}

/// The options that put Gmsh in its sandbox (io::CadSandbox), on `app` or a subcommand.
void add_cad_sandbox_options(CLI::App& app, CommonOptions& common) {
  checked(app.add_option("--cad-timeout", common.cad_timeout,
                         "Seconds Gmsh may take to read and triangulate an input (default 300)"),
          seconds());
  checked(app.add_option("--cad-memory", common.cad_memory,
                         "GiB of memory Gmsh may use (default: 8 or 3/4 of the memory, the smaller)"),
          gibibytes());
  app.add_flag("--allow-geo-commands", common.allow_geo_commands,
               ".geo input: allow SystemCall, writing files, Exit, and files outside its folder");
}

void add_threads_option(CLI::App& app, CommonOptions& common) {
  app.add_option("--threads", common.threads,
                 "Worker threads for the loops whose iterations are independent and, from two, for two cone "
                 "placements at a time (default: all cores); the results are the same bit for bit whatever "
                 "the number")
      ->type_name("UINT:N")
      ->check(CLI::Range(std::size_t{1}, std::size_t{4096}));
}

void print_error(const std::string& message) noexcept {
  try {
    fmt::print(stderr, "quadmesh: error: {}\n", command_line_wording(message));
  } catch (
      ...) {  // stderr unwritable (a full disk, a file size limit): the exit status still says it
  }
}

/// The first argument that is neither an option nor an option's value: the
/// command the user meant, or "" (CLI11 says only "A subcommand is required").
std::string first_word(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.empty() || arg[0] != '-') return arg;
    if (arg.find('=') != std::string::npos) continue;
    for (const CLI::Option* option : app.get_options())
      if (option->check_name(arg) && option->get_items_expected_min() > 0) ++i;  // skip its value
  }
  return std::string();
}

/// One line for a command line CLI11 refused.
std::string parse_error_line(const CLI::ParseError& e, const CLI::App& app,
                             const std::vector<CLI::App*>& commands, int argc, char** argv) {
  bool command_given = false;
  for (const CLI::App* command : commands)
    command_given = command_given || command->parsed();
  const bool no_command =
      dynamic_cast<const CLI::RequiredError*>(&e) || dynamic_cast<const CLI::ExtrasError*>(&e);
  if (command_given || !no_command) return fmt::format("{} (see quadmesh --help)", e.what());
  std::vector<std::string> names;
  for (const CLI::App* command : commands)
    names.push_back(command->get_name());
  const std::string word = first_word(app, argc, argv);
  if (word.empty())
    return fmt::format("a command is required (commands: {})", fmt::join(names, ", "));
  return fmt::format("unknown command '{}' (commands: {})", word, fmt::join(names, ", "));
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
  checked(app.add_option("--cad-mesh-size", common.cad_mesh_size,
                         "CAD input: Gmsh triangle size (default: 0.75 x the quad size, finer where curves and surfaces bend; mesh with auto: 0.6, 0.45 and 0.33 x in turn when its quads do not conform, with a warning)"),
          positive_length());
  add_cad_sandbox_options(app, common);
  add_threads_option(app, common);

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
  checked(
      forms_cmd->add_option("--remesh-size", forms.remesh_size,
                            "Target edge length of --remesh (default: 0.4 x the mean edge length)"),
      positive_length());
  checked(
      forms_cmd
          ->add_option(
              "--max-triangles", forms.max_triangles,
              "Refuse a --remesh-size that implies more triangles than this (area / (0.433 H^2))")
          ->capture_default_str(),
      whole_count());

  MeshOptions mesh;
  CLI::App* mesh_cmd = app.add_subcommand("mesh", "Quad-mesh a surface");
  mesh_cmd->add_option("FILE", mesh.input, "Input surface")->required();
  mesh_cmd->add_option("-o,--output", mesh.output, "Output mesh (format from the extension)")
      ->required();
  std::string size_text;
  checked(mesh_cmd->add_option(
              "--size", size_text,
              "Target quad edge length, or P% of the bounding-box diagonal (default: 1/60 of it)"),
          length_or_percent());
  checked(mesh_cmd->add_option("--quads", mesh.quads, "Target number of quads (instead of --size)"),
          whole_count());
  checked(mesh_cmd
              ->add_option(
                  "--max-quads", mesh.max_quads,
                  "Refuse, before the forms, a --size or --quads that implies more quads than this")
              ->capture_default_str(),
          whole_count());
  std::string form_choice = "auto";
  checked(
      mesh_cmd->add_option(
          "--form", form_choice,
          "The differential: auto (most uniform |h|) or K, the K-th symmetric basis form (from 1)"),
      form_number());
  checked(
      mesh_cmd
          ->add_option("--coeffs", mesh.coefficients,
                       "Real coefficients c1,c2,... of h = sum c_k h_k over the symmetric basis")
          ->delimiter(',')
          ->excludes("--form"),
      coefficient());
  mesh_cmd->add_flag("--rotate", mesh.rotate, "Use i*h: the same grid turned by 90 degrees");
  mesh_cmd
      ->add_option("--singularities", mesh.singularities,
                   "abel: the differential's zeros only; auto: quarter-turn cones where the Abel quads miss "
                   "[0.5, 2] x the size or a corner's quad count (abel when --form, --coeffs or --rotate is given)")
      ->check(CLI::IsMember({"abel", "auto"}))
      ->capture_default_str();
  mesh_cmd
      ->add_option("--cone-placement", mesh.cone_placement,
                   "With auto, where the interior cones go: greedy (at the extremes of the conformal factor) or "
                   "cross-field (the smoothest boundary-aligned cross field's singularities)")
      ->check(CLI::IsMember({"greedy", "cross-field"}))
      ->capture_default_str();
  mesh_cmd->add_flag("--no-coarsening", mesh.no_coarsening,
                     "Mesh the input's own triangles even where they are far finer than the quads need "
                     "(by default a working triangulation of the input's points, edges a third of the size)");
  mesh_cmd->add_flag("--no-smoothing", mesh.no_smoothing,
                     "Keep every quad corner where the extraction put it (no smoothing of the worst quads "
                     "or of the angles)");
  checked(mesh_cmd->add_option(
              "--corner-angle", mesh.corner_angle_deg,
              "Boundary turning angle (degrees) above which a vertex is a corner put on the grid"),
          degrees(0.0, 180.0, true));
  checked(mesh_cmd->add_option(
              "--tip-angle", mesh.tip_angle_deg,
              "With --form auto: boundary vertices where the surface turns this much or more "
              "(degrees) get a zero of h, so four quads share the turn rather than two; above "
              "360: none"),
          degrees(180.0, 720.0, false));
  std::string deviation_text;
  checked(mesh_cmd->add_option(
              "--max-deviation", deviation_text,
              "Split quad strips where the quads are farther than D (or P% of the diagonal) from "
              "the input; off: no refinement (default: half the quad size)"),
          length_or_percent(true));
  mesh_cmd->add_option("--report", mesh.report, "Write a JSON report (quality, zeros, quantization, timings)");
  checked(mesh_cmd->add_option("--msh-version", mesh.msh_version, "MSH output version: 4.1 or 2.2"),
          msh_version());
  mesh_cmd->add_option("--order", mesh.order,
                       "Element order: 1 (4-node quads) or 2 (8-node quads, nodes on the input surface)");
  mesh_cmd->add_flag("--complete", mesh.complete, "With --order 2: 9-node quads (a node inside each quad)");
  mesh_cmd->add_option("--element-type", mesh.element_type,
                       "Solver decks (.inp .bdf .unv): the element type (CPS4, S8R, CQUAD8, ..., or plane-stress, "
                       "plane-strain, shell; default: plane stress in the z = 0 plane, else shell)");
  mesh_cmd->add_flag("--each-component", mesh.each_component,
                     "Mesh every part (CAD physical surface group or connected set of triangles) on its own, at "
                     "the whole model's size, into one output with a physical surface per part");
  mesh_cmd->add_flag("--skip-unsupported", mesh.skip_unsupported,
                     "With --each-component: leave out the parts the method cannot take (a disk, a sphere, a "
                     "non-manifold part), listed with their reason, instead of failing");

  QualityOptions quality;
  CLI::App* quality_cmd =
      app.add_subcommand("quality", "Quality of a quad mesh: scaled Jacobian, angles, valences, topology");
  quality_cmd->add_option("MESH", quality.input, "Mesh to measure (triangles and quads)")->required();
  quality_cmd->add_option("--reference", quality.reference,
                          "Input surface for the two-sided Hausdorff distance");
  std::string quality_size;
  checked(quality_cmd->add_option("--size", quality_size,
                                  "Target quad size the quad sizes are set against, or P% of the bounding-box "
                                  "diagonal (the reference's, else the mesh's)"),
          length_or_percent());
  quality_cmd->add_flag("--json", quality.json, "Print one JSON object instead of text");

  CompareOptions compare;
  CLI::App* compare_cmd = app.add_subcommand(
      "compare", "Ours against Gmsh's quad meshing on the same input and size: reports, pictures, meshes");
  compare_cmd->add_option("FILE", compare.input, "Input surface")->required();
  std::string compare_size;
  checked(compare_cmd->add_option(
              "--size", compare_size,
              "Target quad edge length, or P% of the bounding-box diagonal (default: 1/60 of it)"),
          length_or_percent());
  compare_cmd->add_option("--out", compare.out_dir,
                          "Folder for report.md, report.json, the pictures and every mesh "
                          "(default: compare-<input name>)");
  checked(compare_cmd->add_option("--timeout", compare.timeout,
                                  "Seconds each method may run (default 120)"),
          seconds());
  compare_cmd->add_option("--gmsh", compare.gmsh, "The Gmsh program of the baselines (default: gmsh)");

  BatchOptions batch;
  CLI::App* batch_cmd = app.add_subcommand(
      "batch", "Mesh every part of a list (CSV or folder), each in a child process, N at once; resumable");
  batch_cmd->add_option("LIST", batch.list, "CSV of file,size,options rows, or a folder of input files");
  batch_cmd->add_option("--out", batch.out_dir, "Folder for the parts' meshes, reports, logs and the summary");
  checked(batch_cmd->add_option("--jobs", batch.jobs, "Rows meshed at once (default 1)"), whole_count());
  checked(batch_cmd->add_option("--size", batch.size,
                                "Size of the rows that give none: a length or P% (default: mesh's, 1/60 of the "
                                "diagonal)"),
          length_or_percent());
  checked(batch_cmd->add_option("--timeout", batch.timeout, "Seconds each row may run (default 600)"), seconds());
  checked(batch_cmd->add_option("--row", batch.row, "Run row K of LIST alone (from 1; a Slurm array task), no summary"),
          whole_count());
  batch_cmd->add_flag("--prepare", batch.prepare,
                      "Write DIR/list.json and print the number of rows, run nothing (before a Slurm array)");
  batch_cmd->add_option("--collect", batch.collect_dir,
                        "Write DIR/summary.json and summary.md from the rows DIR holds (after --row runs)");

  RenderOptions render;
  CLI::App* render_cmd = app.add_subcommand(
      "render", "A picture of a quad (or mixed) mesh as SVG: faces coloured by quality, singular vertices marked");
  render_cmd->add_option("MESH", render.input, "Mesh to draw (triangles and quads)")->required();
  render_cmd->add_option("-o,--output", render.output, "The picture (.svg)")->required();
  checked(render_cmd->add_option("--color", render.color,
                                 "Colour the faces by: sj (Verdict scaled Jacobian), angle (largest corner angle "
                                 "deviation), size (mean edge length / --size), none (default sj)"),
          one_of({"sj", "angle", "size", "none"}));
  std::string view_text;
  checked(render_cmd->add_option("--view", view_text,
                                 "Direction towards the viewer, x,y,z (default: the one that shows the most area)"),
          direction());
  std::string render_size;
  checked(render_cmd->add_option("--size", render_size,
                                 "Reference length of --color size, or P% of the bounding-box diagonal "
                                 "(default: the mean edge length)"),
          length_or_percent());
  checked(render_cmd->add_option("--width", render.width,
                                 "Width of the drawing in pixels; the legend and margins add 220 (default 640)"),
          picture_width());

  // Options given after the subcommand apply too (quadmesh mesh f.obj -o g.msh --quiet).
  for (CLI::App* sub : {info_cmd, forms_cmd, mesh_cmd, quality_cmd, compare_cmd, batch_cmd, render_cmd}) {
    sub->add_flag("-q,--quiet", common.quiet, "No progress lines on stderr");
    sub->add_flag("--largest-component", common.largest_component,
                  "Keep only the largest connected component of the input");
    checked(sub->add_option("--cad-mesh-size", common.cad_mesh_size,
                            "CAD input: Gmsh triangle size (default: 0.75 x the quad size, finer where curves and surfaces bend; mesh with auto: 0.6, 0.45 and 0.33 x in turn when its quads do not conform, with a warning)"),
            positive_length());
    add_cad_sandbox_options(*sub, common);
    add_threads_option(*sub, common);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // one line, like every other error (CLI11's own would add a second)
    print_error(parse_error_line(e, app, {info_cmd, forms_cmd, mesh_cmd, quality_cmd, compare_cmd, batch_cmd, render_cmd},
                                 argc, argv));
    return exit_usage;
  }
  const qm::ThreadLimit threads(common.threads);
  qm::io::CadSandbox& sandbox = qm::io::default_cad_sandbox();  // every read gets it
  sandbox.timeout_seconds = common.cad_timeout;
  sandbox.memory_gib = common.cad_memory;
  sandbox.allow_geo_commands = common.allow_geo_commands;
  if (info_cmd->parsed()) return run_info(info, common);
  if (forms_cmd->parsed()) return run_forms(forms, common);
  if (quality_cmd->parsed()) {
    set_length_or_percent(quality_size, quality.size, quality.size_relative);
    return run_quality(quality, common);
  }
  if (batch_cmd->parsed()) return run_batch(batch, common);
  if (compare_cmd->parsed()) {
    set_length_or_percent(compare_size, compare.size, compare.size_relative);
    return run_compare(compare, common);
  }
  if (render_cmd->parsed()) {
    double xyz[3];
    if (parse_direction(view_text, xyz)) render.view = {xyz[0], xyz[1], xyz[2]};
    set_length_or_percent(render_size, render.size, render.size_relative);
    return run_render(render, common);
  }
  if (form_choice != "auto") mesh.form = std::stoi(form_choice) - 1;
  // a differential chosen by hand asks for its quads: the Abel route, unless auto is named too
  if (mesh_cmd->count("--singularities") == 0 && (mesh.form >= 0 || !mesh.coefficients.empty() || mesh.rotate))
    mesh.singularities = "abel";
  set_length_or_percent(size_text, mesh.size, mesh.size_relative);
  if (deviation_text == "off")
    mesh.max_deviation = -1;
  else
    set_length_or_percent(deviation_text, mesh.max_deviation, mesh.max_deviation_relative);
  return run_mesh(mesh, common);
}

}  // namespace

int main(int argc, char** argv) {
  qm::tools::keep_freed_memory();
  try {
    return run(argc, argv);
  } catch (const UsageError& e) {  // a bad option value or output path
    print_error(e.what());
    return exit_usage;
  } catch (const qm::Error& e) {
    print_error(e.what());
    return exit_code_for(e.code());
  } catch (const std::exception& e) {
    print_error(fmt::format("internal error: {}", e.what()));
    return exit_internal;
  }
}
