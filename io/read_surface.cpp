#include "io/read_surface.h"

#include "io/cgal_polygon_soup.h"
#include "io/gmsh_nodes.h"
#include "io/gmsh_session.h"
#include "io/text_diagnostics.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/mesh.h"

#include <fmt/format.h>
#include <gmsh.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unordered_map>

namespace qm::io {

namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::bad_input, message); }

/// Appends polygon `corners` as triangles (a fan from its first corner).
std::size_t add_polygon(TriangleSoup& soup, const std::vector<int>& corners, std::int64_t label) {
  for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
    soup.triangles.push_back({corners[0], corners[i], corners[i + 1]});
    soup.triangle_labels.push_back(label);
  }
  return corners.size() > 3 ? 1 : 0;
}

SurfaceFile read_with_cgal(const std::string& path, Format format) {
  PolygonSoup read;
  if (!read_cgal_polygon_soup(path, read)) fail(fmt::format("{}: could not parse the file", path));
  const auto& points = read.points;
  const auto& polygons = read.polygons;
  SurfaceFile file;
  file.format = format;
  const std::int64_t base = format == Format::obj ? 1 : 0;  // OBJ counts from 1
  for (std::size_t i = 0; i < points.size(); ++i) {
    file.soup.points.push_back(points[i]);
    file.soup.point_labels.push_back(static_cast<std::int64_t>(i) + base);
  }
  std::vector<int> corners;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    corners.clear();
    for (std::size_t v : polygons[f]) {
      if (v >= points.size())
        fail(fmt::format("{}: face {} refers to vertex {}, but the file has {} vertices", path,
                         f + base, v + base, points.size()));
      corners.push_back(static_cast<int>(v));
    }
    if (corners.size() < 3)
      fail(fmt::format("{}: face {} has {} vertices", path, f + base, corners.size()));
    file.polygons_split += add_polygon(file.soup, corners, static_cast<std::int64_t>(f) + base);
  }
  return file;
}

double bounding_box_diagonal() {
  double x0, y0, z0, x1, y1, z1;
  gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
  return std::sqrt((x1 - x0) * (x1 - x0) + (y1 - y0) * (y1 - y0) + (z1 - z0) * (z1 - z0));
}

bool has_surface_elements() {
  std::vector<int> types;
  std::vector<std::vector<std::size_t>> tags, nodes;
  gmsh::model::mesh::getElements(types, tags, nodes, 2, -1);
  return !types.empty();
}

/// Triangulates the CAD model loaded in Gmsh; returns the triangle size used.
double triangulate_cad(const std::string& path, const ReadOptions& options,
                       const GmshSession& session) {
  std::vector<std::pair<int, int>> surfaces;
  gmsh::model::getEntities(surfaces, 2);
  if (surfaces.empty()) fail(fmt::format("{}: the model has no surface to mesh", path));
  const double diagonal = bounding_box_diagonal();
  const double quad_size = options.quad_size > 0          ? options.quad_size
                           : options.quad_size_relative > 0 ? options.quad_size_relative * diagonal
                                                            : diagonal / 60.0;
  const double size = options.cad_mesh_size > 0 ? options.cad_mesh_size : quad_size / 3.0;
  if (has_surface_elements()) return 0.0;  // the script meshed itself
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  try {
    gmsh::model::mesh::generate(2);
  } catch (...) {
  }
  const std::string error = session.first_error();
  if (!error.empty()) fail(fmt::format("{}: Gmsh could not triangulate it: {}", path, error));
  return size;
}

void collect_cad_curves(const std::unordered_map<std::size_t, int>& node_index, CadCurves& cad) {
  std::vector<std::pair<int, int>> curves;
  gmsh::model::getEntities(curves, 1);
  for (const auto& [dim, tag] : curves) {
    std::vector<int> types;
    std::vector<std::vector<std::size_t>> element_tags, element_nodes;
    gmsh::model::mesh::getElements(types, element_tags, element_nodes, dim, tag);
    for (std::size_t k = 0; k < types.size(); ++k) {
      std::string name;
      int edim = 0, order = 0, count = 0, primary = 0;
      std::vector<double> local;
      gmsh::model::mesh::getElementProperties(types[k], name, edim, order, count, local, primary);
      if (edim != 1) continue;
      for (std::size_t e = 0; e < element_tags[k].size(); ++e) {
        const auto a = node_index.find(element_nodes[k][e * count]);
        const auto b = node_index.find(element_nodes[k][e * count + 1]);
        if (a != node_index.end() && b != node_index.end())
          cad.edges.push_back({a->second, b->second, tag});
      }
    }
  }
  std::vector<std::pair<int, int>> groups;
  gmsh::model::getPhysicalGroups(groups, 1);
  for (const auto& [dim, tag] : groups) {
    PhysicalCurveGroup group;
    group.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, group.name);
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, group.curves);
    cad.groups.push_back(std::move(group));
  }
}

SurfaceFile read_with_gmsh(const std::string& path, Format format, const ReadOptions& options) {
  GmshSession session;
  try {
    gmsh::open(path);
  } catch (...) {
  }
  std::string error = session.first_error();
  if (!error.empty()) fail(fmt::format("{}: Gmsh could not read it: {}", path, error));

  SurfaceFile file;
  file.format = format;
  if (is_cad(format)) file.cad_mesh_size = triangulate_cad(path, options, session);

  // Only nodes used by surface elements become points, in order of first use.
  GmshNodes nodes(path);
  auto point_of = [&](std::size_t tag) { return nodes.use(tag, file.soup.points, &file.soup.point_labels); };

  std::vector<int> types;
  std::vector<std::vector<std::size_t>> element_tags, element_nodes;
  gmsh::model::mesh::getElements(types, element_tags, element_nodes, 2, -1);
  std::vector<int> corners;
  for (std::size_t k = 0; k < types.size(); ++k) {
    std::string name;
    int dim = 0, order = 0, count = 0, primary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(types[k], name, dim, order, count, local, primary);
    for (std::size_t e = 0; e < element_tags[k].size(); ++e) {
      corners.clear();
      for (int c = 0; c < primary; ++c) corners.push_back(point_of(element_nodes[k][e * count + c]));
      file.polygons_split +=
          add_polygon(file.soup, corners, static_cast<std::int64_t>(element_tags[k][e]));
    }
  }
  collect_cad_curves(nodes.used(), file.soup.cad);
  return file;
}

}  // namespace

SurfaceFile read_surface(const std::string& path, const ReadOptions& options) {
  const Format format = check_input_file(path);
  SurfaceFile file = (format == Format::obj || format == Format::off || format == Format::ply)
                         ? read_with_cgal(path, format)
                         : read_with_gmsh(path, format, options);
  if (file.soup.triangles.empty())
    fail(fmt::format("{}: no triangles found (the file holds {} vertices and no surface elements)",
                     path, file.soup.points.size()));
  return file;
}

}  // namespace qm::io
