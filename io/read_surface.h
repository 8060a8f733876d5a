// Reading an input surface from any supported file (README "Formats").
#pragma once

#include "io/file_format.h"
#include "libquadmesh/core/triangle_soup.h"

#include <string>

namespace qm::io {

struct ReadOptions {
  /// CAD inputs (.geo .step .brep .iges): Gmsh's maximum triangle size. 0 means
  /// automatic: a third of quad_size.
  double cad_mesh_size = 0.0;
  /// The quad size the triangulation is for; 0 means 1/60 of the bounding-box
  /// diagonal (the mesher's default).
  double quad_size = 0.0;
  /// The quad size as a fraction of the bounding-box diagonal (used when > 0 and
  /// quad_size is 0).
  double quad_size_relative = 0.0;
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
/// file, or one without triangles.
SurfaceFile read_surface(const std::string& path, const ReadOptions& options = {});

}  // namespace qm::io
