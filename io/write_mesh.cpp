#include "io/write_mesh.h"

#include "io/atomic_file.h"
#include "io/write_deck.h"
#include "io/gmsh_model.h"
#include "io/gmsh_session.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/mesh.h"

#include <CGAL/IO/polygon_soup_io.h>
#include <fmt/format.h>
#include <gmsh.h>

#include <filesystem>
#include <numeric>

namespace qm::io {

namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::bad_input, message); }

std::string fs_extension(const std::string& path) { return std::filesystem::path(path).extension().string(); }

void write_with_cgal(const std::string& path, const OutputMesh& mesh) {
  std::vector<Point3> points;
  points.reserve(mesh.points.size());
  for (const Vec3& p : mesh.points) points.emplace_back(p.x(), p.y(), p.z());
  std::vector<std::vector<std::size_t>> polygons;
  polygons.reserve(mesh.faces.size());
  for (const auto& f : mesh.faces) polygons.emplace_back(f.begin(), f.end());
  if (!CGAL::IO::write_polygon_soup(path, points, polygons,
                                    CGAL::parameters::stream_precision(17)))
    fail(fmt::format("{}: CGAL could not write the file", path));
}

/// Gmsh element type of a face with n corners.
int gmsh_face_type(std::size_t n) {
  if (n == 3) return 2;
  if (n == 4) return 3;
  if (n == 8) return 16;  // 8-node (serendipity) quadrangle
  if (n == 9) return 10;  // 9-node quadrangle
  throw AssertionError(fmt::format("faces must have 3, 4, 8 or 9 nodes, found {}", n));
}

void write_with_gmsh(const std::string& path, const OutputMesh& mesh, const WriteOptions& options) {
  GmshSession session;
  add_to_gmsh_model(mesh);
  write_gmsh_model(path, options, session);
}

}  // namespace

namespace {

/// Adds the points used by `faces` that no entity holds yet (`added`) as nodes of
/// `entity` (node tag = point index + 1); every point when `faces` is null.
void add_nodes(int entity, const OutputMesh& mesh, const std::vector<int>* faces, std::vector<char>& added) {
  std::vector<std::size_t> tags;
  std::vector<double> coords;
  const auto add = [&](int v) {
    if (added[static_cast<std::size_t>(v)]) return;
    added[static_cast<std::size_t>(v)] = 1;
    const Vec3& p = mesh.points[static_cast<std::size_t>(v)];
    tags.push_back(static_cast<std::size_t>(v) + 1);
    coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  };
  if (faces == nullptr)
    for (std::size_t v = 0; v < mesh.points.size(); ++v) add(static_cast<int>(v));
  else
    for (int f : *faces)
      for (int v : mesh.faces[static_cast<std::size_t>(f)]) add(v);
  if (!tags.empty()) gmsh::model::mesh::addNodes(2, entity, tags, coords);
}

/// Adds `faces` (all when null) as elements of `entity`, triangles first, numbering
/// them from next_element (then quads, then 8- and 9-node quads); records each face's
/// element tag in face_tags.
void add_faces(int entity, const OutputMesh& mesh, const std::vector<int>* faces, std::size_t& next_element,
               std::vector<std::size_t>& face_tags) {
  std::vector<int> all;
  if (faces == nullptr) {
    all.resize(mesh.faces.size());
    std::iota(all.begin(), all.end(), 0);
    faces = &all;
  }
  for (std::size_t corners : {std::size_t{3}, std::size_t{4}, std::size_t{8}, std::size_t{9}}) {
    std::vector<std::size_t> tags, nodes;
    for (int i : *faces) {
      const auto& f = mesh.faces[static_cast<std::size_t>(i)];
      gmsh_face_type(f.size());
      if (f.size() != corners) continue;
      face_tags[static_cast<std::size_t>(i)] = next_element;
      tags.push_back(next_element++);
      for (int v : f) nodes.push_back(static_cast<std::size_t>(v) + 1);
    }
    if (!tags.empty()) gmsh::model::mesh::addElementsByType(entity, gmsh_face_type(corners), tags, nodes);
  }
}

}  // namespace

std::vector<std::size_t> add_to_gmsh_model(const OutputMesh& mesh) {
  gmsh::model::add("quadmesh");
  // faces are numbered in input order (per surface group): element tag of face i is face_tags[i]
  std::vector<std::size_t> face_tags(mesh.faces.size());
  std::size_t next_element = 1;
  std::vector<char> added(mesh.points.size(), 0);
  std::vector<std::pair<int, std::string>> surfaces;  // entity, physical name
  if (mesh.surface_groups.empty()) {
    const int surface = gmsh::model::addDiscreteEntity(2);
    add_nodes(surface, mesh, nullptr, added);
    add_faces(surface, mesh, nullptr, next_element, face_tags);
    surfaces.emplace_back(surface, mesh.surface_group);
  } else {
    for (const SurfaceGroup& group : mesh.surface_groups) {
      const int surface = gmsh::model::addDiscreteEntity(2);
      add_nodes(surface, mesh, &group.faces, added);
      add_faces(surface, mesh, &group.faces, next_element, face_tags);
      surfaces.emplace_back(surface, group.name);
    }
    add_nodes(surfaces.front().first, mesh, nullptr, added);  // points no face uses
  }
  for (const LineGroup& group : mesh.line_groups) {
    const int curve = gmsh::model::addDiscreteEntity(1);
    std::vector<std::size_t> tags, nodes;
    const bool quadratic = !group.mids.empty();
    for (std::size_t i = 0; i < group.edges.size(); ++i) {
      const auto& e = group.edges[i];
      tags.push_back(next_element++);
      nodes.push_back(static_cast<std::size_t>(e[0]) + 1);
      nodes.push_back(static_cast<std::size_t>(e[1]) + 1);
      if (quadratic) nodes.push_back(static_cast<std::size_t>(group.mids[i]) + 1);
    }
    if (!tags.empty()) gmsh::model::mesh::addElementsByType(curve, quadratic ? 8 : 1, tags, nodes);
    const int physical = gmsh::model::addPhysicalGroup(1, {curve});
    gmsh::model::setPhysicalName(1, physical, group.name);
  }
  for (const PointGroup& group : mesh.point_groups) {
    std::vector<int> entities;
    for (int p : group.points) {
      const int entity = gmsh::model::addDiscreteEntity(0);
      gmsh::model::mesh::addElementsByType(entity, 15, {next_element++},
                                           {static_cast<std::size_t>(p) + 1});
      entities.push_back(entity);
    }
    const int physical = gmsh::model::addPhysicalGroup(0, entities);
    gmsh::model::setPhysicalName(0, physical, group.name);
  }
  for (const auto& [surface, name] : surfaces) {
    const int physical = gmsh::model::addPhysicalGroup(2, {surface});
    gmsh::model::setPhysicalName(2, physical, name);
  }
  return face_tags;
}

void write_gmsh_model(const std::string& path, const WriteOptions& options,
                      const GmshSession& session) {
  gmsh::option::setNumber("Mesh.MshFileVersion", options.msh_version);
  gmsh::option::setNumber("Mesh.Binary", options.binary ? 1 : 0);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  try {
    gmsh::write(path);
  } catch (...) {
  }
  const std::string error = session.first_error();
  if (!error.empty()) fail(fmt::format("{}: Gmsh could not write it: {}", path, error));
}

void check_output_path(const std::string& path) {
  namespace fs = std::filesystem;
  const Format format = format_of(path);
  if (!is_writable(format))
    fail(fmt::format("{}: unknown output format '{}' (writable: {})", path,
                     fs::path(path).extension().string(), writable_extensions()));
  const fs::path folder = fs::path(path).parent_path();
  std::error_code ec;
  if (!folder.empty() && !fs::is_directory(folder, ec))
    fail(fmt::format("{}: the folder {} does not exist", path, folder.string()));
}

void write_mesh(const std::string& path, const OutputMesh& mesh, const WriteOptions& options) {
  check_output_path(path);
  if (options.msh_version != 4.1 && options.msh_version != 2.2)
    fail(fmt::format("{}: MSH version {} is not 4.1 or 2.2", path, options.msh_version));
  const Format format = format_of(path);
  for (const auto& f : mesh.faces)
    if (static_cast<int>(f.size()) > max_quad_nodes(format))
      fail(fmt::format("{}: {} cannot hold {}-node quads", path, fs_extension(path), f.size()));
  write_atomically(path, [&](const std::string& temporary) {
    if (format == Format::obj || format == Format::off || format == Format::ply)
      write_with_cgal(temporary, mesh);
    else if (is_deck(format))
      write_deck(temporary, format, mesh, options.element_type);
    else
      write_with_gmsh(temporary, mesh, options);
  });
}

OutputMesh output_mesh_of(const TriangleSoup& soup) {
  OutputMesh mesh;
  mesh.points = soup.points;
  mesh.faces.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) mesh.faces.push_back({t[0], t[1], t[2]});
  return mesh;
}

}  // namespace qm::io
