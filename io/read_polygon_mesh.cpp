#include "io/read_polygon_mesh.h"

#include "io/cgal_polygon_soup.h"
#include "io/file_format.h"
#include "io/gmsh_nodes.h"
#include "io/gmsh_session.h"
#include "io/text_diagnostics.h"
#include "libquadmesh/core/error.h"

#include <fmt/format.h>
#include <gmsh.h>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <unordered_map>

namespace qm::io {

namespace {


[[noreturn]] void fail(const std::string& message) {
  throw Error(ErrorCode::bad_input, message);
}

/// Keeps only the points that a face uses (in their order) and renumbers the faces.
void drop_unreferenced(PolygonMesh& mesh) {
  std::vector<int> index(mesh.points.size(), -1);
  for (const std::vector<int>& face : mesh.faces)
    for (int v : face)
      index[static_cast<std::size_t>(v)] = 0;
  std::vector<Vec3> kept;
  for (std::size_t i = 0; i < mesh.points.size(); ++i)
    if (index[i] == 0) {
      index[i] = static_cast<int>(kept.size());
      kept.push_back(mesh.points[i]);
    }
  for (std::vector<int>& face : mesh.faces)
    for (int& v : face)
      v = index[static_cast<std::size_t>(v)];
  mesh.points = std::move(kept);
}

PolygonMesh read_with_cgal(const std::string& path, Format format) {
  PolygonSoup read;
  if (!read_cgal_polygon_soup(path, read)) fail(fmt::format("{}: could not parse the file", path));
  const auto& points = read.points;
  const auto& polygons = read.polygons;
  const std::size_t base = format == Format::obj ? 1 : 0;  // OBJ counts from 1
  PolygonMesh mesh;
  mesh.points = points;
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    if (polygons[f].size() < 3)
      fail(fmt::format("{}: face {} has {} vertices", path, f + base, polygons[f].size()));
    std::vector<int> face;
    for (std::size_t v : polygons[f]) {
      if (v >= points.size())
        fail(fmt::format("{}: face {} refers to vertex {}, but the file has {} vertices", path,
                         f + base, v + base, points.size()));
      face.push_back(static_cast<int>(v));
    }
    mesh.faces.push_back(std::move(face));
  }
  return mesh;
}

PolygonMesh read_with_gmsh(const std::string& path) {
  GmshSession session;
  try {
    gmsh::open(path);
  } catch (...) {
  }
  const std::string error = session.first_error();
  if (!error.empty()) fail(fmt::format("{}: Gmsh could not read it: {}", path, error));

  PolygonMesh mesh;
  GmshNodes nodes(path);  // only nodes used by a face become points
  auto point_of = [&](std::size_t tag) { return nodes.use(tag, mesh.points); };
  // Gmsh element types: 2 is the 3-node triangle, 3 the 4-node quadrangle
  for (const auto& [type, corners] : {std::pair<int, std::size_t>{2, 3}, {3, 4}}) {
    std::vector<std::size_t> element_tags, element_nodes;
    gmsh::model::mesh::getElementsByType(type, element_tags, element_nodes, -1);
    for (std::size_t e = 0; e < element_tags.size(); ++e) {
      std::vector<int> face;
      for (std::size_t c = 0; c < corners; ++c)
        face.push_back(point_of(element_nodes[e * corners + c]));
      mesh.faces.push_back(std::move(face));
    }
  }
  return mesh;
}

}  // namespace

PolygonMesh read_polygon_mesh(const std::string& path) {
  const Format format = check_input_file(path);

  PolygonMesh mesh = (format == Format::obj || format == Format::off || format == Format::ply)
                         ? read_with_cgal(path, format)
                         : read_with_gmsh(path);
  if (mesh.faces.empty()) fail(fmt::format("{}: no triangles or quads found", path));
  drop_unreferenced(mesh);
  return mesh;
}

}  // namespace qm::io
