// The entry point of include/quadmesh/quadmesh.h: the checks a tool makes before
// meshing, then the pipeline.
#include "quadmesh/quadmesh.h"

#include <fmt/format.h>

#include <limits>
#include <utility>

namespace qm {

namespace {

/// Triangles must index the points (the readers check this for files; arrays
/// from a caller are checked here, before anything indexes with them).
void require_indices_in_range(const std::vector<Vec3>& points, const std::vector<Triangle>& triangles) {
  if (points.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(ErrorCode::bad_input, fmt::format("{} points: more than the {} a triangle can index",
                                                  points.size(), std::numeric_limits<int>::max()));
  const auto n = static_cast<long long>(points.size());
  for (std::size_t f = 0; f < triangles.size(); ++f)
    for (const int v : triangles[f])
      if (v < 0 || v >= n)
        throw Error(ErrorCode::bad_input,
                    fmt::format("triangle {} (vertices {}, {}, {}): vertex {} is not one of the {} points (0 to {})",
                                f, triangles[f][0], triangles[f][1], triangles[f][2], v, n, n - 1));
}

}  // namespace

QuadMeshResult mesh_quads(std::vector<Vec3> points, std::vector<Triangle> triangles,
                          const QuadMeshOptions& options, const ProgressCallback& progress) {
  require_indices_in_range(points, triangles);
  TriangleSoup soup;
  soup.points = std::move(points);
  soup.triangles = std::move(triangles);
  AnalyzedSurface surface = analyze_topology(std::move(soup));
  require_supported(surface);
  return mesh_quads(std::move(surface.soup), options, progress);
}

}  // namespace qm
