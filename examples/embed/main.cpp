// Embeds quadmesh: a 3 x 1 plate with two square holes, triangulated here on a
// grid, meshed with quads through the one entry header; prints what came out.
// Exit status 0 when the quads meet the library's own acceptance criteria, else 1.
#include <quadmesh/quadmesh.h>

#include <cstdio>
#include <vector>

namespace {

/// A grid of nx x ny square cells of side h, each split into two triangles
/// (counter-clockwise), without the cells inside the two holes.
void plate_with_two_holes(int nx, int ny, double h, std::vector<qm::Vec3>& points,
                          std::vector<qm::Triangle>& triangles) {
  auto in_hole = [&](int i, int j) {
    const bool rows = j >= ny / 3 && j < ny - ny / 3;
    return rows && ((i >= nx / 6 && i < nx / 6 + ny / 3) || (i >= nx - nx / 6 - ny / 3 && i < nx - nx / 6));
  };
  auto id = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) points.emplace_back(i * h, j * h, 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      if (in_hole(i, j)) continue;
      triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  // the points inside the holes are used by no triangle: the library drops them
}

}  // namespace

int main() {
  std::vector<qm::Vec3> points;
  std::vector<qm::Triangle> triangles;
  plate_with_two_holes(60, 20, 0.05, points, triangles);

  qm::QuadMeshOptions options;
  options.size_relative = 0.015;  // quads 1.5% of the bounding-box diagonal
  try {
    const qm::QuadMeshResult result = qm::mesh_quads(points, triangles, options);
    const qm::QuadQuality q = qm::quad_quality(qm::polygon_mesh(result.quads), &result.surface);
    std::printf("%zu quads (%zu points), %d symmetric forms on the double\n", result.quads.quads.size(),
                result.quads.points.size(), result.doubled_genus);
    std::printf("scaled Jacobian: min %.3f, mean %.3f (Verdict)\n", q.min_scaled_jacobian, q.mean_scaled_jacobian);
    std::printf("angles: %.1f to %.1f degrees, mean deviation from 90 %.2f\n", q.min_angle, q.max_angle,
                q.angle_dev_mean);
    std::printf("Hausdorff distance to the plate: %.2g of the diagonal\n", q.hausdorff_rel);
    const qm::AcceptanceCriteria accept;  // the thresholds the library holds its quads to
    return q.min_scaled_jacobian >= accept.min_scaled_jacobian &&
                   q.angle_dev_mean <= accept.max_mean_angle_deviation_deg
               ? 0
               : 1;
  } catch (const qm::Error& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 1;
  }
}
