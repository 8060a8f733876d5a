// quadmesh compare FILE [--size H|P%] [--out DIR] [--timeout S] [--gmsh PATH]:
// ours and Gmsh's quad meshing on the same input and size, in one run, each in a
// child process with a time limit; every mesh measured by the same quality module
// against the same reference (README "quadmesh compare").
//
// Test hook: QUADMESH_COMPARE_CRASH=NAME[,NAME...] makes those methods' child
// processes raise SIGSEGV instead of running (they must then be reported as
// `crashed` while the tool still succeeds).
#include "io/atomic_file.h"
#include "io/file_format.h"
#include "io/read_polygon_mesh.h"
#include "io/write_mesh.h"
#include "tools/common/crash_hook.h"
#include "tools/common/exit_codes.h"
#include "tools/common/input_surface.h"
#include "tools/common/output_paths.h"
#include "tools/common/usage_error.h"
#include "tools/compare/child_process.h"
#include "tools/compare/comparison_report.h"
#include "tools/compare/methods.h"
#include "tools/render/mesh_svg.h"
#include "libquadmesh/quality/hausdorff.h"
#include "tools/quadmesh/commands.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace qm::tools {

namespace {

namespace fs = std::filesystem;

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();  // the last buffer is written here: check after it
  if (!out)
    throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the file", path.string()));
}

/// Every file compare writes into its folder (README "quadmesh compare").
std::vector<std::string> files_written() {
  std::vector<std::string> names = {"input.msh", "report.json", "report.md", kAngleHistogramFile,
                                    kJacobianHistogramFile, "gmsh-version.log"};
  for (const Method& method : comparison_methods(MethodSetup{})) {
    names.push_back(method.mesh_file);
    if (!method.script_file.empty()) names.push_back(method.script_file);
    names.push_back(method.name + ".log");
    names.push_back(picture_file(method));
  }
  return names;
}

/// Before any work: --out usable, and the input none of the files written there.
void check_files(const fs::path& input, const fs::path& dir) {
  check_output_folder({"--out", dir.string()});
  for (const std::string& name : files_written())
    if (same_file(input.string(), (dir / name).string()))
      throw UsageError(fmt::format("--out {}: compare writes {} there, which is the input; give --out another folder",
                                   dir.string(), name));
}

/// The first error message in a method's log: ours print "quadmesh: error: ...",
/// Gmsh "Error   : ..."; "" if there is none.
std::string first_error_line(const std::string& log_path) {
  std::ifstream in(log_path);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("quadmesh: error: ", 0) == 0) return line.substr(17, 300);
    if (line.rfind("Error", 0) == 0) {
      const auto text = line.find_first_not_of(" :", 5);
      return text == std::string::npos ? line.substr(0, 300) : line.substr(text, 300);
    }
  }
  return {};
}

/// How every mesh is drawn: from the direction that shows the most of the
/// reference, at the reference's scale, so that the pictures compare.
struct PictureSetup {
  View view;
  Frame frame;
  MeshPictureOptions options;
};

/// The picture size in the report: three side by side.
constexpr double kPictureWidth = 360, kPictureMaxHeight = 330;

PictureSetup picture_setup(const TriangleSoup& reference) {
  PolygonMesh triangles;
  triangles.points = reference.points;
  for (const Triangle& t : reference.triangles)
    triangles.faces.push_back({t[0], t[1], t[2]});
  PictureSetup setup;
  setup.view = view_toward(most_area_direction(triangles));
  setup.frame = frame_fitting(reference.points, setup.view, kPictureWidth, kPictureMaxHeight);
  setup.options.coloring = FaceColoring::scaled_jacobian;
  setup.options.width = kPictureWidth;
  setup.options.max_height = kPictureMaxHeight;
  return setup;
}

/// Runs one method in its child process and measures (quad sizes against `size`)
/// and draws its mesh.
MethodRun run_method(const Method& method, const fs::path& dir, const TriangleSoup& reference, double size,
                     double timeout, const PictureSetup& drawing) {
  MethodRun run;
  run.method = method;
  std::error_code ignored;
  fs::remove(dir / method.mesh_file, ignored);  // never measure a previous run's mesh
  fs::remove(dir / picture_file(method), ignored);  // nor show its picture
  if (!method.script_file.empty()) write_text(dir / method.script_file, method.script);

  ChildOptions child;
  child.timeout_seconds = timeout;
  child.log_path = (dir / (method.name + ".log")).string();
  child.working_dir = dir.string();
  child.crash_on_purpose = crash_requested("QUADMESH_COMPARE_CRASH", method.name);
  const ChildResult result = run_child(method.argv, child);
  run.status = result.status;
  run.seconds = result.seconds;
  run.detail = result.detail;
  if (result.status == ChildStatus::failed) {
    const std::string error = first_error_line(child.log_path);
    if (!error.empty()) run.detail += ": " + error;
  }
  if (result.status != ChildStatus::ok) return run;

  try {
    const PolygonMesh mesh = io::read_polygon_mesh((dir / method.mesh_file).string());
    run.quality = quad_quality(mesh, &reference, size);
    run.samples = quad_shape_samples(mesh);
    MeshPictureOptions options = drawing.options;
    options.title = method.name;
    run.picture = mesh_picture(mesh, *run.quality, drawing.view, drawing.frame, options).svg;
  } catch (const Error& e) {
    run.status = ChildStatus::failed;
    run.detail = fmt::format("no usable mesh: {}", e.what());
  }
  return run;
}

/// The Gmsh program as the children run it: a path with a '/' made absolute, since
/// each method runs in the output folder; a bare name is looked up in PATH.
std::string program_for_children(const std::string& program) {
  return program.find('/') == std::string::npos ? program : fs::absolute(program).string();
}

/// What `gmsh --version` prints (Gmsh writes it on stderr), or "".
std::string gmsh_version(const std::string& gmsh, const fs::path& dir) {
  ChildOptions child;
  child.timeout_seconds = 20;
  child.log_path = (dir / "gmsh-version.log").string();
  const ChildResult result = run_child({gmsh, "--version"}, child);
  std::ifstream in(child.log_path);
  std::string version;
  std::getline(in, version);
  in.close();
  std::error_code ignored;
  fs::remove(child.log_path, ignored);
  return result.status == ChildStatus::ok ? version : std::string();
}

std::string summary_line(const MethodRun& run) {
  if (!run.quality)
    return fmt::format("{:<32} {:<8} {:>8.2f} s  {}", run.method.name, status_name(run.status),
                       run.seconds, run.detail);
  const QuadQuality& q = *run.quality;
  return fmt::format(
      "{:<32} {:<8} {:>8.2f} s  {:>7} quads {:>5} tri  min SJ {:6.3f}  angle dev {:5.2f} deg  "
      "{:>5} irregular",
      run.method.name, status_name(run.status), run.seconds, q.quads, q.triangles,
      q.min_scaled_jacobian, q.angle_dev_mean, q.irregular_interior);
}

}  // namespace

int run_compare(const CompareOptions& options, const CommonOptions& common) {
  const Progress progress(common.quiet);
  const fs::path input = fs::absolute(options.input);
  const fs::path dir = options.out_dir.empty() ? fs::path("compare-" + input.stem().string())
                                               : fs::path(options.out_dir);
  check_files(input, dir);

  // The reference: the input triangulation as `quadmesh mesh` reads it.
  io::ReadOptions read;
  read.cad_mesh_size = common.cad_mesh_size;
  read.quad_size = options.size;
  read.quad_size_relative = options.size_relative;
  InputSurface in = load_input_surface(input.string(), read, common.largest_component, progress);
  double diagonal = bounding_box_diagonal(in.surface.soup.points, in.surface.soup.triangles);
  const double size = options.size > 0            ? options.size
                      : options.size_relative > 0 ? options.size_relative * diagonal
                                                  : diagonal / 60.0;
  const bool cad = io::is_cad(io::format_of(input.string()));
  if (cad && options.size <= 0) {
    // Gmsh's CAD bounding box is not the triangulation's: triangulate again at the
    // absolute size every method gets, so the reference is our method's input.
    read.quad_size = size;
    in = load_input_surface(input.string(), read, common.largest_component, progress);
    diagonal = bounding_box_diagonal(in.surface.soup.points, in.surface.soup.triangles);
  }
  const TriangleSoup& reference = in.surface.soup;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw UsageError(fmt::format("{}: cannot create the output folder{}", dir.string(),
                                 ec ? ": " + ec.message() : std::string()));
  progress.stage(
      fmt::format("writing the reference triangulation {}", (dir / "input.msh").string()));
  try {
    io::write_mesh((dir / "input.msh").string(), io::output_mesh_of(reference));
  } catch (const Error& e) {
    throw UsageError(e.what());
  }

  ComparisonReport report;
  report.input = options.input;
  report.size = size;
  report.diagonal = diagonal;
  report.timeout_seconds = options.timeout;
  report.gmsh_version = gmsh_version(options.gmsh, dir);
  report.gmsh_program = options.gmsh;
  report.reference_points = reference.points.size();
  report.reference_triangles = reference.triangles.size();
  {
    PolygonMesh triangles;
    triangles.points = reference.points;
    for (const Triangle& t : reference.triangles)
      triangles.faces.push_back({t[0], t[1], t[2]});
    const QuadQuality topology = quad_quality(triangles, nullptr);
    report.reference_euler_characteristic = topology.euler_characteristic;
    report.reference_boundary_loops = topology.boundary_loops;
  }

  MethodSetup setup;
  setup.input = input.string();
  setup.cad = cad;
  setup.triangulation = "input.msh";
  setup.size = size;
  setup.self = own_executable();
  setup.gmsh = program_for_children(options.gmsh);
  if (common.largest_component) setup.mesh_extra_args.push_back("--largest-component");
  if (common.cad_mesh_size > 0) {
    setup.mesh_extra_args.push_back("--cad-mesh-size");
    setup.mesh_extra_args.push_back(fmt::format("{:.17g}", common.cad_mesh_size));
  }
  setup.gmsh_version = report.gmsh_version;
  const PictureSetup drawing = picture_setup(reference);
  report.view = drawing.view.toward_viewer;
  for (const Method& method : comparison_methods(setup)) {
    if (!method.skipped_because.empty()) {
      progress.stage(fmt::format("skipping {}: {}", method.name, method.skipped_because));
      report.skipped.push_back(method);
      continue;
    }
    progress.stage(fmt::format("running {} (limit {:g} s)", method.name, options.timeout));
    report.runs.push_back(run_method(method, dir, reference, size, options.timeout, drawing));
    const MethodRun& run = report.runs.back();
    progress.stage(fmt::format("{}: {} after {:.2f} s{}", method.name, status_name(run.status),
                               run.seconds, run.detail.empty() ? "" : ": " + run.detail));
  }

  progress.stage(fmt::format("writing the reports into {}", dir.string()));
  try {  // the reports appear together or not at all
    io::AtomicFiles reports;
    const auto add = [&](const fs::path& path, const std::string& text) {
      reports.add(path.string(), [&](const std::string& temporary) { write_text(temporary, text); });
    };
    add(dir / "report.json", report_json(report).dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n");
    add(dir / kAngleHistogramFile, angle_histogram_svg(report));
    add(dir / kJacobianHistogramFile, jacobian_histogram_svg(report));
    add(dir / "report.md", report_markdown(report));
    for (const MethodRun& run : report.runs)
      if (!run.picture.empty()) add(dir / picture_file(run.method), run.picture);
    reports.commit();
  } catch (const Error& e) {
    throw UsageError(fmt::format("{}; no report was written", e.what()));
  }

  fmt::print("{} at size {:.4g}: {}\n", options.input, size, (dir / "report.md").string());
  for (const MethodRun& run : report.runs)
    fmt::print("  {}\n", summary_line(run));
  for (const Method& method : report.skipped)
    fmt::print("  {:<32} skipped   {}\n", method.name, method.skipped_because);
  fmt::print("{}\n", report_verdict(report));
  return exit_ok;
}

}  // namespace qm::tools
