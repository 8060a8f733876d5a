#include "tools/common/input_surface.h"

#include "io/write_mesh.h"

#include <fmt/format.h>

namespace qm::tools {

bool output_path_usable(const std::string& path, io::Format only) {
  try {
    io::check_output_path(path);
    if (only != io::Format::unknown && io::format_of(path) != only)
      throw Error(ErrorCode::bad_input, fmt::format("{}: this output must be a .msh file", path));
  } catch (const Error& e) {
    fmt::print(stderr, "quadmesh: error: {}\n", e.what());
    return false;
  }
  return true;
}

InputSurface load_input_surface(const std::string& path, const io::ReadOptions& read,
                                bool largest_only, const Progress& progress) {
  InputSurface in;
  progress.stage(fmt::format("reading {}", path));
  in.file = io::read_surface(path, read);
  progress.stage(fmt::format("analysing topology ({} vertices, {} triangles)",
                             in.file.soup.points.size(), in.file.soup.triangles.size()));
  in.surface = analyze_topology(std::move(in.file.soup));
  in.file.soup = {};
  if (largest_only && in.surface.report.components.count > 1) {
    in.dropped_components = static_cast<std::size_t>(in.surface.report.components.count - 1);
    progress.stage(fmt::format("keeping the largest of {} components",
                               in.surface.report.components.count));
    in.surface = largest_component(in.surface);
  }
  return in;
}

}  // namespace qm::tools
