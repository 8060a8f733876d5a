#include "tools/common/input_surface.h"

#include <Eigen/Geometry>
#include <fmt/format.h>

namespace qm::tools {

double total_area(const TriangleSoup& soup) {
  double area = 0;
  for (const Triangle& t : soup.triangles) {
    const Vec3& a = soup.points[static_cast<std::size_t>(t[0])];
    area += 0.5 * (soup.points[static_cast<std::size_t>(t[1])] - a)
                      .cross(soup.points[static_cast<std::size_t>(t[2])] - a)
                      .norm();
  }
  return area;
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
