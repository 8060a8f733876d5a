#include "libquadmesh/extract/quad_chords.h"

#include "libquadmesh/core/error.h"

#include <algorithm>
#include <map>
#include <utility>

namespace qm {

namespace {

using EdgeKey = std::pair<int, int>;

EdgeKey edge_key(const Quad& q, int i) {
  const int a = q[static_cast<std::size_t>(i)], b = q[static_cast<std::size_t>((i + 1) % 4)];
  return {std::min(a, b), std::max(a, b)};
}

/// per undirected edge, the (quad, local edge) pairs using it
std::map<EdgeKey, std::vector<std::pair<int, int>>> edge_uses(const std::vector<Quad>& quads) {
  std::map<EdgeKey, std::vector<std::pair<int, int>>> uses;
  for (std::size_t q = 0; q < quads.size(); ++q)
    for (int i = 0; i < 4; ++i) uses[edge_key(quads[q], i)].push_back({static_cast<int>(q), i});
  return uses;
}

}  // namespace

QuadChords quad_chords(const std::vector<Quad>& quads) {
  const auto uses = edge_uses(quads);
  QuadChords c;
  c.chord_of.assign(quads.size(), {-1, -1});
  for (std::size_t q0 = 0; q0 < quads.size(); ++q0)
    for (int d0 = 0; d0 < 2; ++d0) {
      if (c.chord_of[q0][static_cast<std::size_t>(d0)] >= 0) continue;
      const int chord = static_cast<int>(c.length.size());
      c.length.push_back(0);
      c.open.push_back(0);
      std::vector<std::pair<int, int>> stack{{static_cast<int>(q0), d0}};
      c.chord_of[q0][static_cast<std::size_t>(d0)] = chord;
      while (!stack.empty()) {
        const auto [q, d] = stack.back();
        stack.pop_back();
        ++c.length[static_cast<std::size_t>(chord)];
        for (int e : {d, d + 2}) {
          const auto& users = uses.at(edge_key(quads[static_cast<std::size_t>(q)], e));
          QM_ASSERT_MSG(users.size() <= 2, "quad_chords: an edge is shared by more than two quads");
          if (users.size() == 1) {
            c.open[static_cast<std::size_t>(chord)] = 1;
            continue;
          }
          const auto [q2, e2] = users[0].first == q && users[0].second == e ? users[1] : users[0];
          int& slot = c.chord_of[static_cast<std::size_t>(q2)][static_cast<std::size_t>(e2 % 2)];
          if (slot >= 0) continue;
          slot = chord;
          stack.push_back({q2, e2 % 2});
        }
      }
    }
  return c;
}

SplitQuads split_chords(const std::vector<Quad>& quads, int point_count, const QuadChords& chords,
                        const std::vector<char>& split) {
  QM_ASSERT(chords.chord_of.size() == quads.size() && split.size() == chords.length.size());
  const auto uses = edge_uses(quads);
  SplitQuads out;
  std::map<EdgeKey, int> midpoint;
  auto mid = [&](const Quad& q, int i) {
    const EdgeKey key = edge_key(q, i);
    const auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    const int id = point_count + static_cast<int>(out.new_points.size());
    out.new_points.push_back({key.first, key.second, -1, uses.at(key).size() == 1});
    midpoint.emplace(key, id);
    return id;
  };
  for (std::size_t k = 0; k < quads.size(); ++k) {
    const Quad& q = quads[k];
    const bool s0 = split[static_cast<std::size_t>(chords.chord_of[k][0])] != 0;
    const bool s1 = split[static_cast<std::size_t>(chords.chord_of[k][1])] != 0;
    const int v0 = q[0], v1 = q[1], v2 = q[2], v3 = q[3];
    if (s0 && s1) {
      const int m0 = mid(q, 0), m1 = mid(q, 1), m2 = mid(q, 2), m3 = mid(q, 3);
      const int c = point_count + static_cast<int>(out.new_points.size());
      out.new_points.push_back({-1, -1, static_cast<int>(k), false});
      out.quads.push_back({v0, m0, c, m3});
      out.quads.push_back({m0, v1, m1, c});
      out.quads.push_back({c, m1, v2, m2});
      out.quads.push_back({m3, c, m2, v3});
    } else if (s0) {
      const int m0 = mid(q, 0), m2 = mid(q, 2);
      out.quads.push_back({v0, m0, m2, v3});
      out.quads.push_back({m0, v1, v2, m2});
    } else if (s1) {
      const int m1 = mid(q, 1), m3 = mid(q, 3);
      out.quads.push_back({v0, v1, m1, m3});
      out.quads.push_back({m3, m1, v2, v3});
    } else {
      out.quads.push_back(q);
    }
  }
  return out;
}

}  // namespace qm
