#include "libquadmesh/topology/internal/orientation.h"

#include <queue>

namespace qm {

OrientationResult orient_consistently(const TriangleSoup& soup, const EdgeIncidence& inc) {
  const int face_count = static_cast<int>(soup.triangles.size());
  OrientationResult result;
  result.flip.assign(static_cast<std::size_t>(face_count), 0);
  std::vector<char> seen(static_cast<std::size_t>(face_count), 0);
  std::vector<int> patch;
  for (int seed = 0; seed < face_count; ++seed) {
    if (seen[seed]) continue;
    patch.clear();
    std::queue<int> queue;
    queue.push(seed);
    seen[seed] = 1;
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      patch.push_back(f);
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * f + k;
        const int e = inc.halfedge_edge[h];
        if (e < 0 || inc.valence(e) != 2) continue;
        const int h0 = inc.halfedges[inc.offsets[e]];
        const int g_h = (h0 == h) ? inc.halfedges[inc.offsets[e] + 1] : h0;
        const int g = g_h / 3;
        if (g == f) continue;
        const bool same_direction = halfedge_source(soup, h) == halfedge_source(soup, g_h);
        const char wanted = static_cast<char>(result.flip[f] ^ (same_direction ? 1 : 0));
        if (!seen[g]) {
          seen[g] = 1;
          result.flip[g] = wanted;
          queue.push(g);
        } else if (result.flip[g] != wanted && result.orientable) {
          result.orientable = false;
          result.contradicting_edge = e;
        }
      }
    }
    std::size_t flipped = 0;
    for (int f : patch) flipped += result.flip[f];
    if (2 * flipped > patch.size()) {
      for (int f : patch) result.flip[f] ^= 1;
      flipped = patch.size() - flipped;
    }
    result.flip_count += flipped;
  }
  result.consistent = result.orientable && result.flip_count == 0;
  return result;
}

void apply_orientation(TriangleSoup& soup, const std::vector<char>& flip) {
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (flip[f]) std::swap(soup.triangles[f][1], soup.triangles[f][2]);
}

}  // namespace qm
