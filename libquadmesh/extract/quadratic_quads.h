// Quadratic quads from linear ones: a node on every edge (8-node serendipity
// quads) and, when asked, one inside every quad (9-node Lagrange quads), each
// placed on the surface the quads were meshed from rather than at the straight
// midpoint, so that the curved elements follow a curved surface and its
// boundary (docs/outputs.md "Quadratic quads").
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <array>
#include <vector>

namespace qm {

struct QuadraticQuadsOptions {
  bool complete = false;  ///< 9 nodes (a node inside each quad) instead of 8
};

/// The quadratic mesh. points: the linear points first (same indices), then one
/// node per edge, then (complete) one per quad. elements[k] has 8 or 9 indices in
/// the Gmsh / Abaqus order: corners 0-3 as in quad k, then the nodes of the edges
/// 0-1, 1-2, 2-3, 3-0, then the inside node.
struct QuadraticQuads {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> elements;
  /// per edge node (points index - first_edge_node): its two corners
  std::vector<std::array<int, 2>> edge_of_node;
  int first_edge_node = 0;
  /// the nodes of the quads' boundary edges (points indices), placed on S's
  /// boundary: a caller with the exact boundary (CAD curves) may move them onto it
  std::vector<int> boundary_nodes;
  double max_move = 0;  ///< largest distance from a straight midpoint to its node (S or its polyline)
  std::size_t cad_nodes = 0;  ///< boundary corners and edge nodes a caller moved onto CAD curves (0 here)
};

/// The node of each edge is the point of S closest to the edge's straight midpoint
/// (CGAL AABB tree on `surface`'s triangles); for an edge of the quads' boundary,
/// the closest point of S's boundary edges (the polyline of the input). The
/// inside node is the closest point of S to the bilinear centre of the curved edges
/// (the serendipity centre: sum of edge nodes / 2 - sum of corners / 4).
/// Preconditions: quads counter-clockwise with corners indexing `points`; S is
/// the surface the quads were meshed from (open: it has a boundary).
QuadraticQuads quadratic_quads(const std::vector<Vec3>& points, const std::vector<std::array<int, 4>>& quads,
                               const TriangleSoup& surface, const QuadraticQuadsOptions& options = {});

}  // namespace qm
