// quadmesh mesh FILE -o OUT --each-component [--skip-unsupported]: an assembly's
// parts (CAD physical surface groups, or connected sets of triangles) each meshed
// on its own at one size, the whole model's, and written to one output with a
// physical surface per part (README "quadmesh mesh").
#include "io/atomic_file.h"
#include "io/write_mesh.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/topology/surface_parts.h"
#include "tools/common/exit_codes.h"
#include "tools/common/input_surface.h"
#include "tools/common/quality_json.h"
#include "tools/common/usage_error.h"
#include "tools/quadmesh/assembly_output.h"
#include "tools/quadmesh/mesh_steps.h"

#include <fmt/format.h>

#include <fstream>
#include <optional>

namespace qm::tools {

namespace {

using Json = nlohmann::ordered_json;

/// One part of the input and what became of it.
struct PartRun {
  SurfacePart part;
  InputSurface input;             ///< the part alone, analysed
  std::string unsupported;        ///< why the method cannot take it, or "" (meshed)
  std::optional<QuadMeshResult> result;
  std::optional<MeshSummary> summary;
  double seconds = 0;
};

/// The options that speak of one surface do not apply to an assembly.
void check_assembly_options(const MeshOptions& options, const CommonOptions& common) {
  if (common.largest_component)
    throw UsageError("--each-component meshes every part and --largest-component keeps one: give one of them");
  if (options.quads > 0)
    throw UsageError("--quads with --each-component: give --size, one size for every part");
  if (options.form >= 0 || !options.coefficients.empty())
    throw UsageError("--form K and --coeffs name one surface's forms: with --each-component every part uses "
                     "--form auto");
}

/// The quad size every part gets, as a length: --size, or P% of the whole model's
/// bounding-box diagonal, or 1/60 of it (README: "one size for the assembly").
double assembly_size(const MeshOptions& options, double diagonal) {
  if (options.size > 0) return options.size;
  if (options.size_relative > 0) return options.size_relative * diagonal;
  return diagonal / 60.0;
}

/// The parts, each analysed, with the reason the method cannot take it.
std::vector<PartRun> split_parts(const InputSurface& in, const Progress& progress) {
  std::vector<PartRun> runs;
  for (SurfacePart& part : surface_parts(in.surface.soup)) {
    PartRun run;
    run.input.surface = analyze_topology(part_soup(in.surface.soup, part));
    run.part = std::move(part);
    const Applicability verdict = assess_applicability(run.input.surface);
    if (!verdict.supported) run.unsupported = verdict.reason;
    runs.push_back(std::move(run));
  }
  progress.stage(fmt::format("{} parts", runs.size()));
  return runs;
}

/// Without --skip-unsupported, parts the method cannot take fail the run: one
/// line listing them (exit 4), before any output.
void require_all_supported(const std::string& input, const std::vector<PartRun>& runs) {
  std::vector<std::string> refused;
  for (const PartRun& run : runs)
    if (!run.unsupported.empty()) refused.push_back(fmt::format("{} ({})", run.part.name, run.unsupported));
  if (refused.empty()) return;
  throw Error(ErrorCode::unsupported,
              fmt::format("{}: {} of {} parts cannot be meshed: {}; give --skip-unsupported to mesh the others "
                          "without them",
                          input, refused.size(), runs.size(), fmt::join(refused, "; ")));
}

/// Meshes one supported part; a part the mesher refuses as unsupported (a closed
/// one) is marked so, any other failure names the part.
void mesh_part(PartRun& run, const MeshOptions& options, double size, const Progress& progress) {
  const Progress part_progress(true);
  MeshOptions part_options = options;
  part_options.size = size;
  part_options.size_relative = 0;
  QuadMeshOptions mesher = quad_mesh_options(part_options);
  progress.stage(fmt::format("meshing part {} ({} triangles)", run.part.name, run.part.triangles.size()));
  try {
    run.result = mesh_quads(run.input.surface.soup, mesher);
    run.summary = summarize(run.input, *run.result, part_options, part_progress.elapsed());
    run.seconds = part_progress.elapsed();
    require_conforming(*run.summary, *run.result);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::unsupported)
      throw Error(e.code(), fmt::format("part {}: {}", run.part.name, e.what()), e.option());
    run.unsupported = e.what();
    run.result.reset();
    run.summary.reset();
  }
}

Json part_json(const PartRun& run) {
  const TopologyReport& t = run.input.surface.report;
  Json j;
  j["name"] = run.part.name;
  j["status"] = run.summary ? "meshed" : "unsupported";
  j["reason"] = run.unsupported;
  j["triangles"] = run.part.triangles.size();
  j["input"] = {{"euler_characteristic", t.euler_characteristic}, {"boundary_loops", t.boundary_loop_count()}};
  if (!run.summary) return j;
  j["seconds"] = run.seconds;
  j["quality"] = run.summary->report["quality"];
  j["report"] = run.summary->report;
  return j;
}

/// The whole report (--report): the assembly's quality against the whole input,
/// then one entry per part with its own report.
Json assembly_report(const MeshOptions& options, double size, const QuadQuality& quality,
                     const std::vector<PartRun>& runs, double seconds) {
  Json j;
  j["input"] = options.input;
  j["output"] = options.output;
  j["each_component"] = true;
  j["size"] = size;
  j["size_rule"] = options.size > 0 ? "--size, a length, for every part"
                                    : "a share of the whole model's bounding-box diagonal, for every part";
  j["quality"] = quality_json(quality);
  Json parts = Json::array();
  std::size_t meshed = 0;
  for (const PartRun& run : runs) {
    parts.push_back(part_json(run));
    meshed += run.summary ? 1 : 0;
  }
  j["totals"] = {{"parts", runs.size()}, {"meshed", meshed}, {"unsupported", runs.size() - meshed},
                 {"quads", quality.quads}};
  j["parts"] = parts;
  j["timings"] = {{"total", seconds}};
  return j;
}

void print_parts(const std::vector<PartRun>& runs, const QuadQuality& quality, double size, double seconds) {
  fmt::print("{:<24} {:<11} {:>7} {:>9} {:>7} {:>10} {:>4} {:>6} {:>8}\n", "part", "status", "quads", "irregular",
             "min SJ", "angle dev", "chi", "loops", "seconds");
  std::size_t meshed = 0;
  for (const PartRun& run : runs) {
    if (!run.summary) {
      fmt::print("{:<24} {:<11} {}\n", run.part.name, "unsupported", run.unsupported);
      continue;
    }
    ++meshed;
    const QuadQuality& q = run.summary->quality;
    fmt::print("{:<24} {:<11} {:>7} {:>9} {:>7.3f} {:>10.2f} {:>4} {:>6} {:>8.2f}\n", run.part.name, "meshed",
               q.quads, q.irregular_interior, q.min_scaled_jacobian, q.angle_dev_mean, q.euler_characteristic,
               q.boundary_loops, run.seconds);
  }
  fmt::print("total: {} of {} parts meshed, {} quads, min SJ {:.3f}, size {:.4g} (the whole model's), {:.2f} s\n",
             meshed, runs.size(), quality.quads, quality.min_scaled_jacobian, size, seconds);
}

}  // namespace

int run_mesh_each_component(const MeshOptions& options, const CommonOptions& common) {
  check_assembly_options(options, common);
  check_mesh_files(options);
  const Progress progress(common.quiet);
  const io::ReadOptions read = mesh_read_options(options, common);
  check_cad_quad_estimate(options, read);
  const InputSurface in = load_input_surface(options.input, read, false, progress);
  const double diagonal = bounding_box_diagonal(in.surface.soup.points, in.surface.soup.triangles);
  const double size = assembly_size(options, diagonal);
  MeshOptions sized = options;
  sized.size = size;
  sized.size_relative = 0;
  check_quad_estimate(sized, in.surface.soup);

  std::vector<PartRun> runs = split_parts(in, progress);
  if (!options.skip_unsupported) require_all_supported(options.input, runs);
  for (PartRun& run : runs)
    if (run.unsupported.empty()) mesh_part(run, options, size, progress);
  if (!options.skip_unsupported) require_all_supported(options.input, runs);  // closed parts the mesher refused

  std::vector<PartOutput> outputs;
  for (const PartRun& run : runs)
    if (run.result) outputs.push_back({run.part.name, output_mesh(*run.result)});
  if (outputs.empty())
    throw Error(ErrorCode::unsupported, fmt::format("{}: none of its {} parts can be meshed; no output was written",
                                                    options.input, runs.size()));
  const io::OutputMesh assembly = assembly_output(outputs);
  progress.stage("measuring the assembly's quality");
  PolygonMesh merged;
  merged.points = assembly.points;
  merged.faces = assembly.faces;
  const QuadQuality quality = quad_quality(merged, &in.surface.soup);
  const double seconds = progress.elapsed();
  const Json report = assembly_report(options, size, quality, runs, seconds);

  progress.stage(fmt::format("writing {}", options.output));
  try {  // the mesh and the report appear together or not at all
    io::AtomicFiles files;
    io::WriteOptions write;
    write.msh_version = options.msh_version;
    files.add(options.output, [&](const std::string& temporary) { io::write_mesh(temporary, assembly, write); });
    if (!options.report.empty())
      files.add(options.report, [&](const std::string& temporary) {
        std::ofstream out(temporary);
        out << report.dump(2, ' ', false, Json::error_handler_t::replace) << '\n';
        out.close();
        if (!out) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the report", options.report));
      });
    files.commit();
  } catch (const Error& e) {
    throw UsageError(fmt::format("{}; no output was written", e.what()));
  }
  print_parts(runs, quality, size, seconds);
  for (const PartRun& run : runs)
    if (run.result)
      warn_about_result(*run.summary, *run.result,
                        bounding_box_diagonal(run.input.surface.soup.points, run.input.surface.soup.triangles));
  return exit_ok;
}

}  // namespace qm::tools
