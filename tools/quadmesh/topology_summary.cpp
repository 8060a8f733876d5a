#include "tools/quadmesh/topology_summary.h"

#include "tools/quadmesh/library_wording.h"

#include <fmt/format.h>

#include <algorithm>

namespace qm::tools {

namespace {

const char* format_name(io::Format f) {
  switch (f) {
    case io::Format::obj: return "OBJ";
    case io::Format::off: return "OFF";
    case io::Format::ply: return "PLY";
    case io::Format::stl: return "STL";
    case io::Format::msh: return "MSH";
    case io::Format::geo: return "GEO";
    case io::Format::step: return "STEP";
    case io::Format::brep: return "BREP";
    case io::Format::iges: return "IGES";
    default: return "?";
  }
}

const char* case_name(SurfaceCase c) {
  switch (c) {
    case SurfaceCase::invalid: return "invalid";
    case SurfaceCase::several_components: return "several_components";
    case SurfaceCase::non_orientable: return "non_orientable";
    case SurfaceCase::disk: return "disk";
    case SurfaceCase::sphere: return "sphere";
    case SurfaceCase::annulus: return "annulus";
    case SurfaceCase::open_negative: return "open_negative";
    case SurfaceCase::closed: return "closed";
  }
  return "?";
}

struct EdgeLengths {
  double min = 0, mean = 0, max = 0, diagonal = 0;
};

EdgeLengths edge_lengths(const TriangleSoup& soup) {
  EdgeLengths out;
  if (soup.points.empty()) return out;
  Vec3 lo = soup.points.front(), hi = lo;
  for (const Vec3& p : soup.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  out.diagonal = (hi - lo).norm();
  out.min = std::numeric_limits<double>::infinity();
  double sum = 0;
  std::size_t n = 0;
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const double l = (soup.points[t[k]] - soup.points[t[(k + 1) % 3]]).norm();
      out.min = std::min(out.min, l);
      out.max = std::max(out.max, l);
      sum += l;
      ++n;
    }
  out.mean = n ? sum / static_cast<double>(n) : 0.0;
  return out;
}

std::vector<std::size_t> loop_lengths(const TopologyReport& r) {
  std::vector<std::size_t> lengths;
  for (const auto& loop : r.boundary.loops) lengths.push_back(loop.size());
  return lengths;
}

}  // namespace

nlohmann::ordered_json topology_json(const InputSurface& in, const Applicability& verdict) {
  const TopologyReport& r = in.surface.report;
  const EdgeLengths lengths = edge_lengths(in.surface.soup);
  nlohmann::ordered_json j;
  j["format"] = format_name(in.file.format);
  j["vertices"] = r.vertices;
  j["faces"] = r.faces;
  j["edges"] = r.edges;
  j["components"] = r.components.count;
  j["boundary_loops"] = r.boundary_loop_count();
  j["boundary_cycles"] = r.boundary.loops.size();
  j["boundary_cycle_lengths"] = loop_lengths(r);
  j["genus"] = r.genus >= 0 ? nlohmann::ordered_json(r.genus) : nlohmann::ordered_json(nullptr);
  j["euler_characteristic"] = r.euler_characteristic;
  j["manifold"] = r.manifold();
  j["edge_manifold"] = r.edge_manifold();
  j["vertex_manifold"] = r.vertex_manifold();
  j["orientable"] = r.orientation.orientable;
  j["consistently_oriented"] = r.orientation.consistent;
  j["triangles_reoriented"] = r.orientation.orientable ? r.orientation.flip_count : 0;
  j["unreferenced_vertices_dropped"] = r.unreferenced_points;
  j["polygons_split"] = in.file.polygons_split;
  j["components_dropped"] = in.dropped_components;
  j["defects"] = {{"nonfinite_vertices", r.nonfinite_vertices.size()},
                  {"repeated_vertex_triangles", r.repeated_corner_faces.size()},
                  {"zero_area_triangles", r.zero_area_faces.size()},
                  {"duplicate_triangles", r.duplicate_faces.size()},
                  {"nonmanifold_edges", r.nonmanifold_edges.size()},
                  {"nonmanifold_vertices", r.nonmanifold_vertices.size()}};
  j["bounding_box_diagonal"] = lengths.diagonal;
  j["edge_length"] = {{"min", lengths.min}, {"mean", lengths.mean}, {"max", lengths.max}};
  if (in.file.cad_mesh_size > 0) j["cad_mesh_size"] = in.file.cad_mesh_size;
  j["cad_curve_edges"] = in.surface.soup.cad.edges.size();
  nlohmann::ordered_json groups = nlohmann::ordered_json::array();
  for (const auto& g : in.surface.soup.cad.groups)
    groups.push_back({{"tag", g.tag}, {"name", g.name}, {"curves", g.curves}});
  j["physical_curves"] = groups;
  j["supported"] = verdict.supported;
  j["case"] = case_name(verdict.kind);
  j["reason"] = command_line_wording(verdict.reason);
  j["doubled_genus"] =
      verdict.doubled_genus >= 0 ? nlohmann::ordered_json(verdict.doubled_genus) : nlohmann::ordered_json(nullptr);
  return j;
}

std::string topology_text(const InputSurface& in, const Applicability& verdict) {
  const TopologyReport& r = in.surface.report;
  const EdgeLengths lengths = edge_lengths(in.surface.soup);
  std::string out;
  auto line = [&](const char* key, const std::string& value) {
    out += fmt::format("{:<12}{}\n", key, value);
  };
  line("format", format_name(in.file.format));
  line("vertices", fmt::format("{}{}", r.vertices,
                               r.unreferenced_points
                                   ? fmt::format(" ({} unreferenced dropped)", r.unreferenced_points)
                                   : ""));
  line("triangles", fmt::format("{}{}", r.faces,
                                in.file.polygons_split
                                    ? fmt::format(" ({} polygons split)", in.file.polygons_split)
                                    : ""));
  line("edges", std::to_string(r.edges));
  line("components", fmt::format("{}{}", r.components.count,
                                 in.dropped_components
                                     ? fmt::format(" ({} smaller dropped)", in.dropped_components)
                                     : ""));
  const std::size_t cycles = r.boundary.loops.size();
  line("boundaries",
       cycles == 0 ? std::string("0")
       : cycles == static_cast<std::size_t>(r.boundary_loop_count())
           ? fmt::format("{} (edges per loop: {})", cycles, fmt::join(loop_lengths(r), ", "))
           : fmt::format("{} connected ({} cycles touching at pinched vertices; edges per cycle: {})",
                         r.boundary_loop_count(), cycles, fmt::join(loop_lengths(r), ", ")));
  line("manifold", fmt::format("edges {}, vertices {}", r.edge_manifold() ? "yes" : "NO",
                               r.vertex_manifold() ? "yes" : "NO"));
  line("orientable", !r.orientation.orientable ? "NO"
                     : r.orientation.consistent
                         ? "yes, consistently oriented"
                         : fmt::format("yes ({} triangles reoriented)", r.orientation.flip_count));
  std::vector<std::string> defects;
  auto defect = [&](std::size_t n, const char* what) {
    if (n) defects.push_back(fmt::format("{} {}", n, what));
  };
  defect(r.nonfinite_vertices.size(), "non-finite vertices");
  defect(r.repeated_corner_faces.size(), "triangles with a repeated vertex");
  defect(r.zero_area_faces.size(), "zero-area triangles");
  defect(r.duplicate_faces.size(), "duplicate triangles");
  defect(r.nonmanifold_edges.size(), "non-manifold edges");
  defect(r.nonmanifold_vertices.size(), "non-manifold vertices");
  line("defects", defects.empty() ? "none" : fmt::format("{}", fmt::join(defects, ", ")));
  line("chi", std::to_string(r.euler_characteristic));
  line("genus", r.genus >= 0 ? std::to_string(r.genus) : "undefined");
  line("size", fmt::format("bounding-box diagonal {:.6g}, edge length {:.4g} / {:.4g} / {:.4g} "
                           "(min / mean / max)",
                           lengths.diagonal, lengths.min, lengths.mean, lengths.max));
  if (!in.surface.soup.cad.groups.empty())
    line("cad", fmt::format("{} physical curve groups, {} edges on CAD curves",
                            in.surface.soup.cad.groups.size(), in.surface.soup.cad.edges.size()));
  line("verdict", command_line_wording(verdict.reason));
  return out;
}

}  // namespace qm::tools
