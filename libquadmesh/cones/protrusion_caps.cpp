#include "libquadmesh/cones/protrusion_caps.h"

#include <cmath>

namespace qm {

std::vector<int> sublevel_region(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                                 int seed, double level) {
  std::vector<char> in(soup.points.size(), 0);
  std::vector<int> region{seed};
  in[static_cast<std::size_t>(seed)] = 1;
  for (std::size_t next = 0; next < region.size(); ++next)
    for (int f : adjacency.vertex_faces[static_cast<std::size_t>(region[next])])
      for (int w : soup.triangles[static_cast<std::size_t>(f)])
        if (!in[static_cast<std::size_t>(w)] && u[w] < level) {
          in[static_cast<std::size_t>(w)] = 1;
          region.push_back(w);
        }
  return region;
}

int cap_quarter_turns(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<double>& curvature,
                      const Eigen::VectorXd& u, double level, int seed, const std::vector<Cone>& cones) {
  const std::vector<double> target = target_curvature(adjacency, quads_per_vertex(adjacency, cones));
  double lacking = 0;
  for (int v : sublevel_region(soup, adjacency, u, seed, level)) {
    const auto sv = static_cast<std::size_t>(v);
    if (adjacency.boundary_vertex[sv]) return 0;
    lacking += curvature[sv] - target[sv];
  }
  return static_cast<int>(std::lround(lacking / quarter_turn));
}

}  // namespace qm
