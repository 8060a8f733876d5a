#include "libquadmesh/topology/internal/components.h"

#include "libquadmesh/core/internal/union_find.h"

#include <algorithm>

namespace qm {

int Components::largest() const {
  return static_cast<int>(std::max_element(triangle_counts.begin(), triangle_counts.end()) -
                          triangle_counts.begin());
}

std::vector<int> Components::triangles_of(int c) const {
  std::vector<int> out;
  for (std::size_t f = 0; f < triangle_component.size(); ++f)
    if (triangle_component[f] == c) out.push_back(static_cast<int>(f));
  return out;
}

Components connected_components(const TriangleSoup& soup) {
  UnionFind sets(soup.points.size());
  for (const Triangle& t : soup.triangles) {
    sets.unite(t[0], t[1]);
    sets.unite(t[1], t[2]);
  }
  std::vector<char> referenced(soup.points.size(), 0);
  for (const Triangle& t : soup.triangles)
    for (int p : t) referenced[p] = 1;
  Components comps;
  comps.point_component.assign(soup.points.size(), -1);
  std::vector<int> root_label(soup.points.size(), -1);
  for (std::size_t p = 0; p < soup.points.size(); ++p) {
    if (!referenced[p]) continue;
    const int r = sets.find(static_cast<int>(p));
    if (root_label[r] < 0) root_label[r] = comps.count++;
    comps.point_component[p] = root_label[r];
  }
  comps.triangle_counts.assign(static_cast<std::size_t>(comps.count), 0);
  comps.triangle_component.reserve(soup.triangles.size());
  for (const Triangle& t : soup.triangles) {
    const int c = comps.point_component[t[0]];
    comps.triangle_component.push_back(c);
    ++comps.triangle_counts[c];
  }
  return comps;
}

}  // namespace qm
