// Distances along the surface's edges (Dijkstra), as the cone stages measure
// nearness: to the boundary, to a corner.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <functional>
#include <utility>
#include <vector>

namespace qm {

/// Per vertex, the length of the shortest edge path to a vertex marked in
/// `sources` (infinity when none is reachable).
std::vector<double> distance_from(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                  const std::vector<char>& sources);

/// The vertices nearer than `radius` to `source` along the edges, nearest first,
/// with their distances (the source first, at 0). The search stops at the first
/// other vertex reached for which `stop` holds: `radius` becomes its distance, and
/// it and any vertex as far are left out.
std::vector<std::pair<int, double>> vertices_within(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                                    int source, double& radius,
                                                    const std::function<bool(int)>& stop);

}  // namespace qm
