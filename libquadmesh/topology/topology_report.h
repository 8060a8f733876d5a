// Everything the method needs to know about an input surface before it starts
// (method.md section 0): counts, manifoldness, orientability, boundary loops,
// components, Euler characteristic and genus, and element-level defects.
#pragma once

#include "libquadmesh/topology/internal/boundary_loops.h"
#include "libquadmesh/topology/internal/components.h"
#include "libquadmesh/topology/internal/coordinate_range.h"
#include "libquadmesh/topology/internal/orientation.h"

#include <vector>

namespace qm {

struct ComponentTopology {
  std::size_t vertices = 0, edges = 0, faces = 0;
  int boundary_loops = 0;
  long euler_characteristic = 0;  ///< V - E + F
  int genus = -1;  ///< (2 - chi - b) / 2 when orientable and edge-manifold, else -1
};

struct TopologyReport {
  std::size_t points_read = 0;          ///< points in the file, used or not
  std::size_t unreferenced_points = 0;  ///< dropped: no triangle uses them
  std::size_t vertices = 0, edges = 0, faces = 0;

  std::vector<int> nonfinite_vertices;    ///< NaN or infinite coordinates
  CoordinateRange range;                  ///< the finite coordinates' extent (coordinate_range.h)
  std::vector<int> repeated_corner_faces; ///< a vertex used twice
  std::vector<int> zero_area_faces;       ///< three collinear vertices (exact test)
  std::vector<int> duplicate_faces;       ///< same vertex set as an earlier triangle

  struct NonManifoldEdge {
    int a = -1, b = -1;  ///< its two vertices
    int triangles = 0;   ///< how many triangles share it (three or more)
  };
  std::vector<NonManifoldEdge> nonmanifold_edges;
  std::vector<int> nonmanifold_vertices;  ///< vertices whose triangles form several fans
  OrientationResult orientation;
  std::array<int, 2> nonorientable_edge{-1, -1};  ///< vertices of the edge where orientation contradicts
  BoundaryLoops boundary;
  Components components;
  std::vector<ComponentTopology> per_component;

  long euler_characteristic = 0;  ///< V - E + F of the whole soup
  int genus = -1;                 ///< sum over components, -1 when undefined

  bool edge_manifold() const { return nonmanifold_edges.empty(); }
  bool vertex_manifold() const { return nonmanifold_vertices.empty(); }
  bool manifold() const { return edge_manifold() && vertex_manifold(); }
  /// Connected components of the boundary: the boundary loops of a manifold
  /// surface; loops touching at a pinched point count once.
  int boundary_loop_count() const { return boundary.component_count; }
};

/// A surface after analysis: the soup with unreferenced points dropped and, when
/// orientable, its triangles consistently oriented (the input's majority
/// orientation kept); the report speaks of this soup's indices.
struct AnalyzedSurface {
  TriangleSoup soup;
  TopologyReport report;
};

/// Runs every check of method.md section 0. Never throws on bad data: every
/// defect is recorded in the report (see assess_applicability for the verdict).
AnalyzedSurface analyze_topology(TriangleSoup soup);

}  // namespace qm
