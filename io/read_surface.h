// Reading an input surface from any supported file (README "Formats").
#pragma once

#include "io/file_format.h"
#include "libquadmesh/core/triangle_soup.h"

#include <cstdint>
#include <string>

namespace qm::io {

/// The limits Gmsh runs under when it reads a file (README "Limits"). Gmsh runs in
/// a child process: a .geo script that loops, asks for billions of triangles or
/// crashes Gmsh ends that child, not the reader.
struct CadSandbox {
  /// Wall-clock seconds Gmsh may take (reading and triangulating); then the child
  /// and everything it started are killed. Must be > 0.
  double timeout_seconds = 300.0;
  /// Address space the child may use, in GiB; 0: automatic (the smaller of 8 GiB
  /// and 3/4 of the physical memory).
  double memory_gib = 0.0;
  /// Let .geo scripts run shell commands, write files, exit, and read files
  /// outside their folder (io/geo_check.h). Include cycles stay refused.
  bool allow_geo_commands = false;
  /// Run Gmsh in this process, without limits (tests compare both ways).
  bool in_process = false;
  /// Test hook: the child raises SIGSEGV before reading, as a crashing Gmsh would.
  bool crash_on_purpose = false;
};

/// The sandbox a default-constructed ReadOptions starts with. The quadmesh
/// program sets it once from its command line (--cad-timeout, --cad-memory,
/// --allow-geo-commands) so that every command's reads get it.
CadSandbox& default_cad_sandbox();

/// The child's address-space limit for `sandbox`, in bytes (memory_gib, or
/// automatic), before the limit this process already has is applied.
std::uint64_t cad_memory_limit_bytes(const CadSandbox& sandbox);

struct ReadOptions {
  /// CAD inputs (.geo .step .brep .iges): Gmsh's maximum triangle size. 0 means
  /// automatic: 0.75 x quad_size, and at most 15 degrees of a curve's or surface's
  /// bend per triangle (read_surface.cpp says why).
  double cad_mesh_size = 0.0;
  /// With cad_mesh_size 0: triangles of quad_size / this instead, without the
  /// curvature sizing (3: the triangulation of before issue 21, which the tests of
  /// the paths it took pin). 0: automatic.
  double cad_size_divisor = 0.0;
  /// The quad size the triangulation is for; 0 means 1/60 of the bounding-box
  /// diagonal (the mesher's default).
  double quad_size = 0.0;
  /// The quad size as a fraction of the bounding-box diagonal (used when > 0 and
  /// quad_size is 0).
  double quad_size_relative = 0.0;
  /// Files read through Gmsh (CAD, MSH, STL, ...): its time and memory limits and
  /// what a .geo script may do.
  CadSandbox sandbox = default_cad_sandbox();
};

struct SurfaceFile {
  TriangleSoup soup;
  Format format = Format::unknown;
  std::size_t polygons_split = 0;   ///< quads/polygons fan-split into triangles
  double cad_mesh_size = 0.0;       ///< the triangle size Gmsh used (CAD inputs), else 0
};

/// Reads triangles (quads and polygons are fan-split), with the file's own ids kept
/// as labels and, for Gmsh inputs, the CAD curve of every edge on a curve.
/// Throws qm::Error(bad_input) with a one-line message that starts with the path
/// (and the line, for text formats) on a missing, empty, truncated or unparsable
/// file, or one without triangles, and for a refused .geo command, Gmsh running
/// out of time or memory, or crashing.
SurfaceFile read_surface(const std::string& path, const ReadOptions& options = {});

}  // namespace qm::io
