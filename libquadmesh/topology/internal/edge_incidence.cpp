#include "libquadmesh/topology/internal/edge_incidence.h"

#include <algorithm>
#include <cstdint>

namespace qm {

EdgeIncidence edge_incidence(const TriangleSoup& soup) {
  const std::size_t halfedge_count = 3 * soup.triangles.size();
  struct Key {
    std::int64_t a, b;
    int h;
  };
  std::vector<Key> keys;
  keys.reserve(halfedge_count);
  for (std::size_t h = 0; h < halfedge_count; ++h) {
    const int s = halfedge_source(soup, static_cast<int>(h));
    const int t = halfedge_target(soup, static_cast<int>(h));
    if (s == t) continue;
    keys.push_back({std::min(s, t), std::max(s, t), static_cast<int>(h)});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& x, const Key& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.h < y.h);
  });

  EdgeIncidence inc;
  inc.halfedge_edge.assign(halfedge_count, -1);
  inc.halfedges.reserve(keys.size());
  inc.offsets.push_back(0);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (i == 0 || keys[i].a != keys[i - 1].a || keys[i].b != keys[i - 1].b) {
      if (i > 0) inc.offsets.push_back(static_cast<int>(i));
      inc.edges.push_back({static_cast<int>(keys[i].a), static_cast<int>(keys[i].b)});
    }
    inc.halfedges.push_back(keys[i].h);
    inc.halfedge_edge[keys[i].h] = static_cast<int>(inc.edges.size()) - 1;
  }
  if (!keys.empty()) inc.offsets.push_back(static_cast<int>(keys.size()));
  return inc;
}

CurveEdgeIndex curve_edge_index(const TriangleSoup& soup) {
  CurveEdgeIndex index;
  for (std::size_t i = 0; i < soup.cad.edges.size(); ++i) {
    const CurveEdge& c = soup.cad.edges[i];
    index[{std::min(c.a, c.b), std::max(c.a, c.b)}] = i;
  }
  return index;
}

namespace {

/// The CAD curve edge a-b, if there is one, replaced by a-m and m-b.
void split_curve_edge(TriangleSoup& soup, CurveEdgeIndex& curves, int a, int b, int m) {
  const auto it = curves.find({std::min(a, b), std::max(a, b)});
  if (it == curves.end()) return;
  const std::size_t i = it->second;
  curves.erase(it);
  const CurveEdge whole = soup.cad.edges[i];
  soup.cad.edges[i] = CurveEdge{whole.a, m, whole.curve};
  soup.cad.edges.push_back(CurveEdge{m, whole.b, whole.curve});
  curves[{std::min(whole.a, m), std::max(whole.a, m)}] = i;
  curves[{std::min(m, whole.b), std::max(m, whole.b)}] = soup.cad.edges.size() - 1;
}

}  // namespace

int split_edge_at_midpoint(TriangleSoup& soup, const EdgeIncidence& inc, int e, std::vector<char>& touched,
                           CurveEdgeIndex& curves) {
  return split_edge_at(soup, inc, e, 0.5, touched, curves);
}

int split_edge_at(TriangleSoup& soup, const EdgeIncidence& inc, int e, double t, std::vector<char>& touched,
                  CurveEdgeIndex& curves) {
  const auto first = static_cast<std::size_t>(inc.offsets[static_cast<std::size_t>(e)]);
  const auto last = static_cast<std::size_t>(inc.offsets[static_cast<std::size_t>(e) + 1]);
  for (std::size_t i = first; i < last; ++i)
    if (touched[static_cast<std::size_t>(inc.halfedges[i] / 3)]) return -1;
  const auto [a, b] = inc.edges[static_cast<std::size_t>(e)];
  const int m = static_cast<int>(soup.points.size());
  soup.points.push_back((1 - t) * soup.points[static_cast<std::size_t>(a)] + t * soup.points[static_cast<std::size_t>(b)]);
  if (!soup.point_labels.empty()) soup.point_labels.push_back(-1);
  for (std::size_t i = first; i < last; ++i) {
    const int h = inc.halfedges[i];
    const auto f = static_cast<std::size_t>(h / 3);
    const auto k = static_cast<std::size_t>(h % 3);
    const Triangle tri = soup.triangles[f];
    const int x = tri[k], y = tri[(k + 1) % 3], c = tri[(k + 2) % 3];
    soup.triangles[f] = {x, m, c};
    soup.triangles.push_back({m, y, c});
    if (!soup.triangle_labels.empty()) soup.triangle_labels.push_back(soup.triangle_labels[f]);
    touched[f] = 1;
    touched.push_back(1);
  }
  split_curve_edge(soup, curves, a, b, m);
  return m;
}

}  // namespace qm
