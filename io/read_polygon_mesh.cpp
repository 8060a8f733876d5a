#include "io/read_polygon_mesh.h"

#include "io/file_format.h"
#include "io/gmsh_session.h"
#include "io/text_diagnostics.h"
#include "libquadmesh/core/error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
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

using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;

[[noreturn]] void fail(const std::string& message) {
  throw Error(ErrorCode::bad_input, message);
}

std::optional<std::string> diagnose(const std::string& path, Format format) {
  switch (format) {
    case Format::obj:
      return diagnose_obj(path);
    case Format::off:
      return diagnose_off(path);
    case Format::ply:
      return diagnose_ply(path);
    case Format::stl:
      return diagnose_stl(path);
    default:
      return std::nullopt;
  }
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
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  {
    // CGAL's readers complain on std::cerr; the library never prints.
    std::ostringstream swallowed;
    std::streambuf* previous = std::cerr.rdbuf(swallowed.rdbuf());
    try {
      ok = CGAL::IO::read_polygon_soup(path, points, polygons);
    } catch (const std::exception&) {
      ok = false;
    }
    std::cerr.rdbuf(previous);
  }
  if (!ok) fail(fmt::format("{}: could not parse the file", path));
  const std::size_t base = format == Format::obj ? 1 : 0;  // OBJ counts from 1
  PolygonMesh mesh;
  for (const Point& p : points)
    mesh.points.emplace_back(p.x(), p.y(), p.z());
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

  std::vector<std::size_t> node_tags;
  std::vector<double> coords, params;
  gmsh::model::mesh::getNodes(node_tags, coords, params, -1, -1, false, false);
  std::unordered_map<std::size_t, std::size_t> node_slot;
  node_slot.reserve(node_tags.size());
  for (std::size_t i = 0; i < node_tags.size(); ++i)
    node_slot.emplace(node_tags[i], i);

  PolygonMesh mesh;
  std::unordered_map<std::size_t, int> node_index;  // only nodes used by a face
  auto point_of = [&](std::size_t tag) {
    const auto found = node_index.find(tag);
    if (found != node_index.end()) return found->second;
    const auto slot = node_slot.find(tag);
    if (slot == node_slot.end())
      fail(fmt::format("{}: an element refers to node {}, which the file does not define", path,
                       tag));
    const std::size_t s = slot->second;
    const int index = static_cast<int>(mesh.points.size());
    mesh.points.emplace_back(coords[3 * s], coords[3 * s + 1], coords[3 * s + 2]);
    node_index.emplace(tag, index);
    return index;
  };
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
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) fail(fmt::format("{}: no such file", path));
  if (fs::is_directory(path, ec)) fail(fmt::format("{}: is a directory, not a mesh file", path));
  if (fs::file_size(path, ec) == 0) fail(fmt::format("{}: empty file", path));
  if (!std::ifstream(path).good()) fail(fmt::format("{}: cannot open the file for reading", path));
  const Format format = format_of(path);
  if (!is_readable(format))
    fail(fmt::format("{}: unknown input format '{}' (readable: {})", path,
                     fs::path(path).extension().string(), readable_extensions()));
  if (auto problem = diagnose(path, format)) fail(*problem);

  PolygonMesh mesh = (format == Format::obj || format == Format::off || format == Format::ply)
                         ? read_with_cgal(path, format)
                         : read_with_gmsh(path);
  if (mesh.faces.empty()) fail(fmt::format("{}: no triangles or quads found", path));
  drop_unreferenced(mesh);
  return mesh;
}

}  // namespace qm::io
