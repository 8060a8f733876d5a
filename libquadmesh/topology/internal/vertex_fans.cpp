#include "libquadmesh/topology/internal/vertex_fans.h"

#include "libquadmesh/core/internal/union_find.h"

namespace qm {

namespace {
/// The corner of triangle f at point p, or -1.
int corner_at(const TriangleSoup& soup, int f, int p) {
  for (int k = 0; k < 3; ++k)
    if (soup.triangles[f][k] == p) return 3 * f + k;
  return -1;
}
}  // namespace

VertexFans vertex_fans(const TriangleSoup& soup, const EdgeIncidence& inc) {
  const int corner_count = static_cast<int>(3 * soup.triangles.size());
  UnionFind sets(static_cast<std::size_t>(corner_count));
  for (std::size_t e = 0; e < inc.edge_count(); ++e) {
    if (inc.valence(static_cast<int>(e)) != 2) continue;
    const int h0 = inc.halfedges[inc.offsets[e]];
    const int h1 = inc.halfedges[inc.offsets[e] + 1];
    for (int p : inc.edges[e]) {
      const int c0 = corner_at(soup, h0 / 3, p);
      const int c1 = corner_at(soup, h1 / 3, p);
      if (c0 >= 0 && c1 >= 0) sets.unite(c0, c1);
    }
  }
  VertexFans fans;
  sets.labels(fans.corner_fan);
  // Corners of one set share their point, so the labels are fans; count per point.
  int count = 0;
  for (int label : fans.corner_fan) count = std::max(count, label + 1);
  fans.fan_point.assign(static_cast<std::size_t>(count), -1);
  fans.fans_per_point.assign(soup.points.size(), 0);
  for (int c = 0; c < corner_count; ++c) {
    const int fan = fans.corner_fan[c];
    if (fans.fan_point[fan] >= 0) continue;
    const int p = soup.triangles[c / 3][c % 3];
    fans.fan_point[fan] = p;
    ++fans.fans_per_point[p];
  }
  return fans;
}

}  // namespace qm
