#include "libquadmesh/forms/boundary_chords.h"

#include "libquadmesh/topology/internal/edge_incidence.h"

#include <vector>

namespace qm {

std::size_t split_boundary_chords(TriangleSoup& soup) {
  if (soup.point_labels.size() != soup.points.size()) {
    soup.point_labels.resize(soup.points.size());
    for (std::size_t i = 0; i < soup.points.size(); ++i) soup.point_labels[i] = static_cast<std::int64_t>(i);
  }
  if (soup.triangle_labels.size() != soup.triangles.size()) {
    soup.triangle_labels.resize(soup.triangles.size());
    for (std::size_t f = 0; f < soup.triangles.size(); ++f) soup.triangle_labels[f] = static_cast<std::int64_t>(f);
  }
  std::size_t splits = 0;
  for (;;) {
    const EdgeIncidence inc = edge_incidence(soup);
    std::vector<char> on_boundary(soup.points.size(), 0);
    for (std::size_t e = 0; e < inc.edge_count(); ++e)
      if (inc.is_boundary(static_cast<int>(e))) on_boundary[inc.edges[e][0]] = on_boundary[inc.edges[e][1]] = 1;
    CurveEdgeIndex curves = curve_edge_index(soup);
    std::vector<char> touched(soup.triangles.size(), 0);
    std::size_t pass = 0;
    for (std::size_t e = 0; e < inc.edge_count(); ++e) {
      const auto [a, b] = inc.edges[e];
      if (inc.valence(static_cast<int>(e)) != 2 || !on_boundary[a] || !on_boundary[b]) continue;
      if (split_edge_at_midpoint(soup, inc, static_cast<int>(e), touched, curves) < 0) continue;  // next pass
      ++pass;
    }
    splits += pass;
    if (pass == 0) return splits;
  }
}

}  // namespace qm
