#include "io/read_surface.h"

#include "io/cgal_polygon_soup.h"
#include "io/child_process.h"
#include "io/geo_check.h"
#include "io/gmsh_nodes.h"
#include "io/gmsh_session.h"
#include "io/surface_transfer.h"
#include "io/text_diagnostics.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/mesh.h"

#include <fmt/format.h>
#include <gmsh.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <new>
#include <sstream>
#include <unordered_map>

namespace qm::io {

namespace {

[[noreturn]] void fail(const std::string& message, const std::string& option = {}) {
  throw Error(ErrorCode::bad_input, message, option);
}

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

/// The automatic CAD triangulation: triangles of this fraction of the quad size.
/// The map is linear on each triangle, so a triangle must not be wider than a
/// quad (long_edges.h splits those that are); Gmsh's Frontal-Delaunay edges reach
/// about 1.3 x the size asked, so 0.75 keeps them under the quad size. A third
/// (the size before issue 21) gave the same quads from 5 x the triangles.
constexpr double cad_triangle_fraction = 0.75;
/// ...and at most 2 pi / this many radians of a curve or surface's curvature per
/// triangle (Gmsh's Mesh.MeshSizeFromCurvature): a fillet or a bend finer than the
/// quads stays close to the CAD surface (chord height under 1% of its radius).
constexpr double cad_curvature_elements = 24;

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
  const bool automatic = !(options.cad_mesh_size > 0) && !(options.cad_size_divisor > 0);
  const double size = options.cad_mesh_size > 0      ? options.cad_mesh_size
                      : options.cad_size_divisor > 0 ? quad_size / options.cad_size_divisor
                                                     : cad_triangle_fraction * quad_size;
  if (has_surface_elements()) return 0.0;  // the script meshed itself
  gmsh::option::setNumber("Mesh.MeshSizeMax", size);
  if (automatic) gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", cad_curvature_elements);
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

/// The physical surface groups of the model loaded in Gmsh, with the element tags
/// of their faces (the soup's triangle labels).
void collect_surface_groups(CadCurves& cad) {
  std::vector<std::pair<int, int>> groups;
  gmsh::model::getPhysicalGroups(groups, 2);
  for (const auto& [dim, tag] : groups) {
    PhysicalSurfaceGroup group;
    group.tag = tag;
    gmsh::model::getPhysicalName(dim, tag, group.name);
    std::vector<int> surfaces;
    gmsh::model::getEntitiesForPhysicalGroup(dim, tag, surfaces);
    for (int surface : surfaces) {
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> element_tags, element_nodes;
      gmsh::model::mesh::getElements(types, element_tags, element_nodes, dim, surface);
      for (const auto& tags : element_tags)
        for (std::size_t e : tags) group.elements.push_back(static_cast<std::int64_t>(e));
    }
    cad.surface_groups.push_back(std::move(group));
  }
}

/// The surface elements (and CAD curves) of the model loaded in Gmsh.
SurfaceFile collect_surface(const std::string& path, Format format) {
  SurfaceFile file;
  file.format = format;
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
  collect_surface_groups(file.soup.cad);
  return file;
}

/// The session of the read in progress, for a child whose script calls Exit.
const GmshSession* current_session = nullptr;

/// Reads with Gmsh in this process, without limits.
SurfaceFile read_with_gmsh_here(const std::string& path, Format format, const ReadOptions& options) {
  GmshSession session;
  struct Current {
    explicit Current(const GmshSession& s) { current_session = &s; }
    ~Current() { current_session = nullptr; }
  } current(session);
  try {
    gmsh::open(path);
  } catch (...) {
  }
  std::string error = session.first_error();
  if (!error.empty()) fail(fmt::format("{}: Gmsh could not read it: {}", path, error));

  const double size = is_cad(format) ? triangulate_cad(path, options, session) : 0.0;
  SurfaceFile file = collect_surface(path, format);
  file.cad_mesh_size = size;
  return file;
}

// ---- Gmsh in a child process -------------------------------------------------

/// Exit statuses of the Gmsh child besides 0 (result written).
constexpr int exit_out_of_memory = 97;  ///< operator new failed under the memory limit
constexpr int exit_gmsh_exited = 98;    ///< Gmsh (or the script's Exit) called exit()

struct ChildState {
  int fd = -1;
  std::string path;
  Format format = Format::unknown;
};
ChildState child_state;

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) _exit(1);
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void out_of_memory() { _exit(exit_out_of_memory); }

/// Runs when Gmsh calls exit() in the child (a script's `Exit;`, or a fatal
/// error): hands back the surface mesh the script made, or Gmsh's first error,
/// or nothing; then ends the child at once (no destructors of the parent's state).
void on_exit_in_child() {
  try {
    if (has_surface_elements()) {
      SurfaceFile file = collect_surface(child_state.path, child_state.format);
      write_all(child_state.fd, encode_surface(file));
    } else if (current_session != nullptr) {
      const std::string error = current_session->first_error();
      if (!error.empty())
        write_all(child_state.fd,
                  encode_error(Error(ErrorCode::bad_input,
                                     fmt::format("{}: Gmsh could not read it: {}",
                                                 child_state.path, error))));
    }
  } catch (const Error& e) {
    write_all(child_state.fd, encode_error(e));
  } catch (...) {
  }
  _exit(exit_gmsh_exited);
}

/// The child's work: read, then hand back the surface or the error.
int gmsh_child_main(const std::string& path, Format format, const ReadOptions& options, int fd) {
  std::set_new_handler(out_of_memory);
  child_state = {fd, path, format};
  { GmshSession warm_up; }  // Gmsh's own exit-time cleanup is registered before ours
  std::atexit(on_exit_in_child);
  try {
    write_all(fd, encode_surface(read_with_gmsh_here(path, format, options)));
  } catch (const Error& e) {
    write_all(fd, encode_error(e));
  }
  return 0;
}

std::uint64_t current_address_space_limit() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_max == RLIM_INFINITY)
    return std::numeric_limits<std::uint64_t>::max();
  return static_cast<std::uint64_t>(limit.rlim_max);
}

std::string read_all(int fd) {
  struct stat info {};
  if (fstat(fd, &info) != 0 || info.st_size <= 0) return {};
  std::string bytes(static_cast<std::size_t>(info.st_size), '\0');
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = pread(fd, bytes.data() + done, bytes.size() - done, static_cast<off_t>(done));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  bytes.resize(done);
  return bytes;
}

/// Reads with Gmsh in a child process under the sandbox's time and memory limits.
SurfaceFile read_with_gmsh_child(const std::string& path, Format format, const ReadOptions& options) {
  const CadSandbox& sandbox = options.sandbox;
  // The result travels in an unlinked temporary file: nothing is left behind,
  // whatever happens to either process.
  std::string name = (std::filesystem::temp_directory_path() / "quadmesh-gmsh-XXXXXX").string();
  const int fd = mkstemp(name.data());
  if (fd < 0)
    throw Error(ErrorCode::bad_input,
                fmt::format("{}: cannot create a temporary file for Gmsh's result: {}", path,
                            std::strerror(errno)));
  unlink(name.c_str());
  struct Closer {
    int fd;
    ~Closer() { close(fd); }
  } closer{fd};

  ChildOptions child;
  child.timeout_seconds = sandbox.timeout_seconds;
  child.memory_limit_bytes = cad_memory_limit_bytes(sandbox);
  child.crash_on_purpose = sandbox.crash_on_purpose;
  const ChildResult result =
      run_in_child([&] { return gmsh_child_main(path, format, options, fd); }, child);

  if (result.status == ChildStatus::timeout)
    fail(fmt::format("{}: Gmsh did not finish within {:g} s (CadSandbox::timeout_seconds): stopped; a "
                     "script that loops or a mesh size far too small for the model does this",
                     path, sandbox.timeout_seconds),
         "CadSandbox::timeout_seconds");
  if (result.status == ChildStatus::crashed)
    fail(fmt::format("{}: Gmsh crashed (signal {})", path, result.signal));
  if (result.exit_code == exit_out_of_memory) {
    const double limit = static_cast<double>(
        std::min(child.memory_limit_bytes, current_address_space_limit()));
    fail(fmt::format("{}: Gmsh needed more than {:.3g} GiB (CadSandbox::memory_gib)", path,
                     limit / (1024.0 * 1024.0 * 1024.0)),
         "CadSandbox::memory_gib");
  }
  auto decoded = decode_result(read_all(fd), format);
  if (decoded) {
    if (auto* error = std::get_if<Error>(&*decoded)) throw *error;
    return std::get<SurfaceFile>(std::move(*decoded));
  }
  if (result.exit_code == exit_gmsh_exited && format == Format::geo)
    fail(fmt::format("{}: the script exited before any surface was meshed", path));
  if (result.exit_code == exit_gmsh_exited)
    fail(fmt::format("{}: Gmsh exited before it read a surface", path));
  fail(fmt::format("{}: Gmsh ended without a result ({})", path,
                   result.detail.empty() ? "exit status 0" : result.detail));
}

SurfaceFile read_with_gmsh(const std::string& path, Format format, const ReadOptions& options) {
  const double timeout = options.sandbox.timeout_seconds;
  if (!(std::isfinite(timeout) && timeout > 0))
    throw Error(ErrorCode::bad_input, "CadSandbox::timeout_seconds must be a positive number of seconds",
                "CadSandbox::timeout_seconds");
  const double memory = options.sandbox.memory_gib;
  if (!(std::isfinite(memory) && memory >= 0))
    throw Error(ErrorCode::bad_input, "CadSandbox::memory_gib must be a positive number of GiB",
                "CadSandbox::memory_gib");
  if (format == Format::geo) check_geo_script(path, options.sandbox.allow_geo_commands);
  return options.sandbox.in_process ? read_with_gmsh_here(path, format, options)
                                    : read_with_gmsh_child(path, format, options);
}

}  // namespace

CadSandbox& default_cad_sandbox() {
  static CadSandbox sandbox;
  return sandbox;
}

std::uint64_t cad_memory_limit_bytes(const CadSandbox& sandbox) {
  constexpr double gib = 1024.0 * 1024.0 * 1024.0;
  if (sandbox.memory_gib > 0) return static_cast<std::uint64_t>(sandbox.memory_gib * gib);
  const std::uint64_t eight = std::uint64_t{8} << 30;
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || page_size <= 0) return eight;
  const std::uint64_t physical = static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page_size);
  return std::min(eight, physical / 4 * 3);
}

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
