#include "libquadmesh/cones/cone_winding.h"

#include "libquadmesh/core/error.h"

#include <cmath>

namespace qm {

std::vector<int> misturned_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const FaceMap& map, const std::vector<int>& quads) {
  QM_ASSERT(quads.size() == soup.points.size() && map.corners.size() == soup.triangles.size());
  std::vector<double> angle(quads.size(), 0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const CornerValues& z = map.corners[f];
    // the corner's angle from the edge to the next corner to the edge to the one
    // after, negative where the image triangle is turned over
    for (std::size_t k = 0; k < 3; ++k)
      angle[static_cast<std::size_t>(soup.triangles[f][k])] +=
          std::arg((z[(k + 2) % 3] - z[k]) / (z[(k + 1) % 3] - z[k]));
  }
  std::vector<int> out;
  for (std::size_t v = 0; v < quads.size(); ++v)
    if (!adjacency.boundary_vertex[v] && !adjacency.vertex_faces[v].empty() && quads[v] != 4 &&
        std::abs(angle[v] - quads[v] * M_PI / 2) > M_PI / 4)
      out.push_back(static_cast<int>(v));
  return out;
}

}  // namespace qm
