#include "tools/render/irregular_vertices.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace qm::tools {

namespace {

constexpr double kRightAngleDeg = 90.0;  // the regular grid's corner

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

}  // namespace

std::vector<IrregularVertex> irregular_vertices(const PolygonMesh& mesh) {
  const std::size_t n = mesh.points.size();
  std::unordered_map<std::uint64_t, int> uses;  // faces per distinct edge
  std::vector<int> faces_at(n, 0);
  std::vector<double> angle_sum(n, 0.0);
  for (const std::vector<int>& face : mesh.faces) {
    const std::size_t k = face.size();
    for (std::size_t i = 0; i < k; ++i) {
      const int v = face[i], next = face[(i + 1) % k], prev = face[(i + k - 1) % k];
      ++faces_at[static_cast<std::size_t>(v)];
      angle_sum[static_cast<std::size_t>(v)] +=
          corner_angle_deg(mesh.points[static_cast<std::size_t>(prev)], mesh.points[static_cast<std::size_t>(v)],
                           mesh.points[static_cast<std::size_t>(next)]);
      if (v != next) ++uses[edge_key(v, next)];
    }
  }
  std::vector<int> edges_at(n, 0);
  std::vector<char> on_boundary(n, 0);
  for (const auto& [key, count] : uses) {
    const auto a = static_cast<std::size_t>(key >> 32), b = static_cast<std::size_t>(key & 0xffffffffu);
    ++edges_at[a];
    ++edges_at[b];
    if (count == 1) on_boundary[a] = on_boundary[b] = 1;
  }
  std::vector<IrregularVertex> out;
  for (std::size_t v = 0; v < n; ++v) {
    if (faces_at[v] == 0) continue;
    IrregularVertex x;
    x.vertex = static_cast<int>(v);
    x.boundary = on_boundary[v] != 0;
    x.valence = x.boundary ? faces_at[v] : edges_at[v];
    x.regular = x.boundary ? std::max(1, static_cast<int>(std::lround(angle_sum[v] / kRightAngleDeg))) : 4;
    if (x.valence != x.regular) out.push_back(x);
  }
  return out;
}

}  // namespace qm::tools
