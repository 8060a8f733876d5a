#include "tests/support/grid_quads.h"

#include "libquadmesh/quality/quad_quality.h"

#include <algorithm>

namespace qm::test {

LatticeQuads grid_quads(const TriangleSoup& grid, int n) {
  LatticeQuads q;
  q.points = grid.points;
  q.locations.resize(q.points.size());
  auto id = [&](int i, int j) { return i * (n + 1) + j; };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) q.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return q;
}

std::vector<int> unit_square_boundary(const LatticeQuads& quads) {
  std::vector<int> loop(quads.points.size(), -1);
  for (std::size_t v = 0; v < quads.points.size(); ++v) {
    const Vec3& p = quads.points[v];
    if (p.x() == 0 || p.y() == 0 || p.x() == 1 || p.y() == 1) loop[v] = 0;
  }
  return loop;
}

double min_scaled_jacobian(const LatticeQuads& quads) {
  const std::vector<double> j = quad_shape_samples(polygon_mesh(quads)).scaled_jacobian;
  return *std::min_element(j.begin(), j.end());
}

}  // namespace qm::test
