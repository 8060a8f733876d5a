// Connected components of a triangle soup: triangles that share a point are in
// one component (so a bow-tie is one component with a non-manifold point).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <vector>

namespace qm {

struct Components {
  int count = 0;
  std::vector<int> triangle_component;  ///< component of each triangle
  std::vector<int> point_component;     ///< component of each point (-1: unreferenced)
  std::vector<std::size_t> triangle_counts;

  /// The component with the most triangles (the first of equals).
  int largest() const;
  /// Triangles of component c, in input order.
  std::vector<int> triangles_of(int c) const;
};

Components connected_components(const TriangleSoup& soup);

}  // namespace qm
