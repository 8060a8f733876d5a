// Cutting the surface open through its cones (method.md section 11): the edges
// that the cross field's tree does not cross, pruned of every branch that ends at
// a regular interior vertex, leave paths from each cone to the boundary (and,
// on a surface with several boundaries or handles, the paths that open those).
// Each vertex's triangles fall into wedges, separated by cut edges: the seamless
// map has one value per wedge (seamless_map.h).
#pragma once

#include "libquadmesh/cones/cross_field.h"

#include <array>
#include <vector>

namespace qm {

struct CutGraph {
  /// per triangle and side k (corner k to k + 1): the side lies on the cut
  std::vector<std::array<char, 3>> cut_side;
  /// per triangle and corner: the wedge of that corner's vertex
  std::vector<std::array<int, 3>> wedge;
  int wedge_count = 0;
  std::size_t cut_edges = 0;
};

/// Precondition: `quads` from quads_per_vertex (a regular interior vertex has 4).
CutGraph cut_graph(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const CrossField& field,
                   const std::vector<int>& quads);

}  // namespace qm
