// Undirected edges of a triangle soup and the halfedges (triangle sides) on each.
//
// Halfedge h = 3 f + k of triangle f runs from triangles[f][k] to
// triangles[f][(k + 1) % 3]. Sides whose two ends are the same point (a
// combinatorially degenerate triangle) belong to no edge (halfedge_edge = -1).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <array>
#include <cstddef>
#include <map>
#include <vector>

namespace qm {

struct EdgeIncidence {
  std::vector<std::array<int, 2>> edges;  ///< edge e joins points edges[e][0] < edges[e][1]
  std::vector<int> offsets;               ///< halfedges of e: halfedges[offsets[e] .. offsets[e+1])
  std::vector<int> halfedges;             ///< halfedge ids grouped by edge
  std::vector<int> halfedge_edge;         ///< edge of halfedge h, or -1 (size 3 F)

  std::size_t edge_count() const { return edges.size(); }
  int valence(int e) const { return offsets[e + 1] - offsets[e]; }
  bool is_boundary(int e) const { return valence(e) == 1; }
  bool is_manifold(int e) const { return valence(e) <= 2; }
};

inline int halfedge_source(const TriangleSoup& soup, int h) { return soup.triangles[h / 3][h % 3]; }
inline int halfedge_target(const TriangleSoup& soup, int h) {
  return soup.triangles[h / 3][(h % 3 + 1) % 3];
}

/// Builds the edge incidence in O(F log F).
EdgeIncidence edge_incidence(const TriangleSoup& soup);

/// The soup's CAD curve edges (TriangleSoup::cad.edges) by their ends, the smaller
/// first: the splits below keep them whole.
using CurveEdgeIndex = std::map<std::array<int, 2>, std::size_t>;
CurveEdgeIndex curve_edge_index(const TriangleSoup& soup);

/// Splits edge e of `inc` (built on `soup`) at its midpoint, each of its triangles
/// into two, unless one of them is already `touched` (split in this pass: `inc` no
/// longer describes it); returns the new point, or -1. The new point gets label -1
/// and new triangles their parent's label (when the soup has labels); the split
/// triangles and the new ones are marked in `touched` (sized like the triangles).
/// A CAD curve edge on e (found in `curves`, built on `soup`) becomes two, a-m and
/// m-b, on the same curve; `curves` is kept up to date.
int split_edge_at_midpoint(TriangleSoup& soup, const EdgeIncidence& inc, int e, std::vector<char>& touched,
                           CurveEdgeIndex& curves);

/// The same at the point (1 - t) edges[e][0] + t edges[e][1], 0 < t < 1.
int split_edge_at(TriangleSoup& soup, const EdgeIncidence& inc, int e, double t, std::vector<char>& touched,
                  CurveEdgeIndex& curves);

}  // namespace qm
