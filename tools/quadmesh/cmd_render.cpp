// quadmesh render MESH -o PICTURE.svg [--color sj|angle|size|none] [--view x,y,z]
// [--size H|P%]: a picture of a quad (or mixed) mesh, as a self-contained SVG
// (README "quadmesh render").
#include "io/atomic_file.h"
#include "io/read_polygon_mesh.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/quality/quad_quality.h"
#include "tools/common/exit_codes.h"
#include "tools/common/output_paths.h"
#include "tools/common/progress.h"
#include "tools/common/usage_error.h"
#include "tools/quadmesh/commands.h"
#include "tools/render/mesh_svg.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>

namespace qm::tools {

namespace {

namespace fs = std::filesystem;

/// The drawing's largest height, as a share of its width: a tall mesh is drawn
/// narrower rather than as a long strip.
constexpr double kHeightPerWidth = 0.875;

/// Before any work: -o an .svg file that can be written, and not the input.
void check_files(const RenderOptions& options) {
  std::string extension = fs::path(options.output).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".svg")
    throw UsageError(fmt::format("-o {}: the picture is written as SVG; give a file name ending in .svg",
                                 options.output));
  check_output_location({"-o", options.output});
  check_distinct({{"the input", options.input}, {"-o", options.output}});
}

/// A mesh the picture can be made of: finite coordinates (read_polygon_mesh
/// checks the rest: faces, indices, counts).
void require_finite(const PolygonMesh& mesh, const std::string& path) {
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if (!mesh.points[i].allFinite())
      throw Error(ErrorCode::bad_input,
                  fmt::format("{}: point {} has a coordinate that is not a finite number", path, i + 1));
}

/// The reference length of --color size: --size, P% of the bounding-box diagonal,
/// or the mesh's mean edge length.
double reference_size(const RenderOptions& options, const PolygonMesh& mesh, const QuadQuality& q,
                      std::string& label) {
  if (options.size > 0) {
    label = fmt::format("{:g} (--size)", options.size);
    return options.size;
  }
  if (options.size_relative > 0) {
    Vec3 lo = mesh.points.front(), hi = lo;
    for (const Vec3& p : mesh.points) {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    label = fmt::format("{:g}% of the diagonal (--size)", 100 * options.size_relative);
    return options.size_relative * (hi - lo).norm();
  }
  label = "(the mean edge length; --size sets it)";
  return q.edge_length_mean;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw Error(ErrorCode::bad_input, fmt::format("{}: cannot write the file", path));
}

}  // namespace

int run_render(const RenderOptions& options, const CommonOptions& common) {
  const Progress progress(common.quiet);
  check_files(options);
  progress.stage(fmt::format("reading {}", options.input));
  const PolygonMesh mesh = io::read_polygon_mesh(options.input);
  require_finite(mesh, options.input);

  progress.stage("measuring quality");
  const QuadQuality quality = quad_quality(mesh, nullptr);
  MeshPictureOptions picture;
  picture.coloring = *face_coloring_named(options.color);  // checked while parsing
  picture.size = reference_size(options, mesh, quality, picture.size_label);
  picture.title = fs::path(options.input).filename().string();
  picture.width = options.width;
  picture.max_height = options.width * kHeightPerWidth;
  const Vec3 toward = options.view.empty()
                          ? most_area_direction(mesh)
                          : Vec3(options.view[0], options.view[1], options.view[2]);
  const View view = view_toward(toward);
  Frame frame;
  try {
    frame = frame_fitting(mesh.points, view, picture.width, picture.max_height);
  } catch (const Error& e) {
    throw Error(ErrorCode::bad_input, fmt::format("{}: {}", options.input, e.what()));
  }

  progress.stage(fmt::format("drawing the faces seen from ({:.3f}, {:.3f}, {:.3f})", view.toward_viewer.x(),
                             view.toward_viewer.y(), view.toward_viewer.z()));
  const MeshPicture drawn = mesh_picture(mesh, quality, view, frame, picture);
  try {
    io::write_atomically(options.output, [&](const std::string& temporary) { write_text(temporary, drawn.svg); });
  } catch (const Error& e) {
    throw UsageError(fmt::format("{}; no picture was written", e.what()));
  }
  fmt::print("{}: {} of {} faces shown, {} singular vertices marked\n", options.output, drawn.faces_drawn,
             mesh.faces.size(), drawn.marked);
  return exit_ok;
}

}  // namespace qm::tools
