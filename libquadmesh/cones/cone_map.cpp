#include "libquadmesh/cones/cone_map.h"

#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/core/error.h"

#include <cmath>
#include <string>

namespace qm {

int euler_characteristic(const SurfaceAdjacency& adjacency) {
  const TriangleSoup& soup = *adjacency.soup;
  std::size_t boundary_edges = 0;
  for (const auto& loop : adjacency.boundary_loops) boundary_edges += loop.size();
  const std::size_t edges = (3 * soup.triangles.size() + boundary_edges) / 2;
  std::size_t vertices = 0;
  for (const auto& faces : adjacency.vertex_faces) vertices += faces.empty() ? 0 : 1;
  return static_cast<int>(vertices) - static_cast<int>(edges) + static_cast<int>(soup.triangles.size());
}

ConeMap cone_map(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<Cone>& cones,
                 double size) {
  QM_ASSERT(size > 0 && adjacency.soup == &soup);
  ConeMap out;
  out.quads = quads_per_vertex(adjacency, cones);
  require_gauss_bonnet(adjacency, out.quads, euler_characteristic(adjacency));
  out.u = cone_metric(soup, adjacency, target_curvature(adjacency, out.quads), vertex_curvature(soup, adjacency));
  out.field = cone_cross_field(soup, adjacency, out.u);
  if (out.field.misaligned_loop >= 0)
    throw Error(ErrorCode::unsupported,
                "boundary loop " + std::to_string(out.field.misaligned_loop) + " is turned by " +
                    std::to_string(out.field.max_misalignment * 180 / M_PI) +
                    " degrees against the cones' cross field: these cones give no quad mesh");
  out.cut = cut_graph(soup, adjacency, out.field, out.quads);
  out.map = seamless_map(soup, adjacency, out.u, out.field, out.cut, out.quads, size, out.report);
  return out;
}

}  // namespace qm
