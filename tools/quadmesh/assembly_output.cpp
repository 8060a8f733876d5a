#include "tools/quadmesh/assembly_output.h"

#include <fmt/format.h>

#include <map>

namespace qm::tools {

namespace {

/// "boundary_k" names the part's own loops (quad_output.cpp): they are made
/// unique across parts; CAD names are the model's and stay as they are.
std::string line_group_name(const std::string& part, const std::string& group) {
  return group.rfind("boundary_", 0) == 0 ? fmt::format("{}_{}", part, group) : group;
}

}  // namespace

io::OutputMesh assembly_output(const std::vector<PartOutput>& parts) {
  io::OutputMesh out;
  std::map<std::string, std::size_t> line_index, point_index;
  for (const PartOutput& part : parts) {
    const int offset = static_cast<int>(out.points.size());
    out.points.insert(out.points.end(), part.mesh.points.begin(), part.mesh.points.end());
    io::SurfaceGroup group{part.name, {}};
    for (const auto& face : part.mesh.faces) {
      std::vector<int> shifted = face;
      for (int& v : shifted) v += offset;
      group.faces.push_back(static_cast<int>(out.faces.size()));
      out.faces.push_back(std::move(shifted));
    }
    out.surface_groups.push_back(std::move(group));
    for (const io::LineGroup& lines : part.mesh.line_groups) {
      const std::string name = line_group_name(part.name, lines.name);
      if (!line_index.count(name)) {
        line_index[name] = out.line_groups.size();
        out.line_groups.push_back({name, {}});
      }
      auto& edges = out.line_groups[line_index[name]].edges;
      for (const auto& e : lines.edges) edges.push_back({e[0] + offset, e[1] + offset});
    }
    for (const io::PointGroup& points : part.mesh.point_groups) {
      if (!point_index.count(points.name)) {
        point_index[points.name] = out.point_groups.size();
        out.point_groups.push_back({points.name, {}});
      }
      auto& list = out.point_groups[point_index[points.name]].points;
      for (int p : points.points) list.push_back(p + offset);
    }
  }
  return out;
}

}  // namespace qm::tools
