// Writing a triangle or quad mesh with its physical groups, in the format the
// output path's extension names (README "Formats").
#pragma once

#include "io/file_format.h"
#include "libquadmesh/core/triangle_soup.h"

#include <array>
#include <string>
#include <vector>

namespace qm::io {

/// A named set of line elements (a boundary loop, a CAD physical curve).
struct LineGroup {
  std::string name;
  std::vector<std::array<int, 2>> edges;  ///< point indices
  std::vector<int> mids;  ///< quadratic meshes: the node of each edge (same order); else empty
};

/// A named set of points written as point elements (zeros, singular vertices).
struct PointGroup {
  std::string name;
  std::vector<int> points;
};

/// A named set of faces written as a physical surface of its own (one part of an
/// assembly).
struct SurfaceGroup {
  std::string name;
  std::vector<int> faces;  ///< face indices
};

/// What gets written: points, faces of 3 or 4 corners (counter-clockwise seen from
/// the surface's front) or quadratic quads of 8 or 9 nodes (corners, then the nodes
/// of the edges 0-1, 1-2, 2-3, 3-0, then the inside node), line and point groups,
/// and the name of the surface's group; or, when surface_groups is not empty, one
/// physical surface per surface group (every face in exactly one of them; Gmsh
/// formats only: the solver decks put every face in one element set).
struct OutputMesh {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;
  std::vector<LineGroup> line_groups;
  std::vector<PointGroup> point_groups;
  std::string surface_group = "surface";
  std::vector<SurfaceGroup> surface_groups;
};

struct WriteOptions {
  double msh_version = 4.1;  ///< 4.1 or 2.2 for .msh
  bool binary = false;       ///< binary .msh (Gmsh formats only)
  /// Solver decks (.inp .bdf .unv): the element type (io/deck_element.h); empty:
  /// from the geometry (plane stress in the z = 0 plane, else shell).
  std::string element_type;
};

/// Writes atomically: to a temporary file beside `path`, renamed at the end, so a
/// failure never leaves a partial file. Gmsh formats get the line groups as
/// physical curves and the faces as one physical surface; OBJ/OFF/PLY get the faces
/// only; solver decks (.inp .bdf .unv) are written by io/write_deck.h: the faces
/// as elements, each group as a node set (and, in .inp, an element-edge surface). Throws qm::Error(bad_input) for an unknown extension or an unwritable
/// destination.
void write_mesh(const std::string& path, const OutputMesh& mesh, const WriteOptions& options = {});

/// Throws qm::Error(bad_input) unless `path` has a writable extension and its
/// folder exists: tools call it before any long computation.
void check_output_path(const std::string& path);

/// The soup's triangles as an OutputMesh (no line groups).
OutputMesh output_mesh_of(const TriangleSoup& soup);

}  // namespace qm::io
