#include "libquadmesh/cones/internal/boundary_ligaments.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <utility>

namespace qm {

namespace {

/// Two vertices of one loop closer than this many boundary edges along it are
/// neighbours on a side or round a corner, not two sides of a slot.
constexpr std::size_t min_loop_separation = 6;

/// A line's value this close to an integer is taken as made integer (the seam
/// rows tie a line's wedges by a penalty: ~1e-8 apart after a solve).
constexpr double integer_tolerance = 1e-4;

/// A boundary vertex's line: its wedge and the coordinate constant along the line.
struct VertexLine {
  int wedge = -1;
  int across = 0;
};

/// Per straight boundary vertex (2 quads), the lines of its two boundary edges
/// (two when a cut ends there and parts their wedges, else the same one twice).
std::vector<std::vector<VertexLine>> vertex_lines(const SurfaceAdjacency& adjacency, const CrossField& field,
                                                  const CutGraph& cut, const std::vector<int>& quads) {
  std::vector<std::vector<VertexLine>> lines(adjacency.boundary_vertex.size());
  for (const std::vector<int>& loop : adjacency.boundary_loops)
    for (std::size_t s = 0; s < loop.size(); ++s) {
      const int a = loop[s], b = loop[(s + 1) % loop.size()];
      const EdgeCorner e = adjacency.find(a, b);
      if (e.face < 0) continue;
      const auto f = static_cast<std::size_t>(e.face);
      const int axis = field.boundary_axis[f][static_cast<std::size_t>(e.i)];
      if (axis < 0) continue;
      const int across = axis == 0 ? 1 : 0;
      for (const auto& [v, corner] : {std::pair(a, e.i), std::pair(b, e.j)})
        if (quads[static_cast<std::size_t>(v)] == 2)
          lines[static_cast<std::size_t>(v)].push_back({cut.wedge[f][static_cast<std::size_t>(corner)], across});
    }
  return lines;
}

/// The coordinate across vertex v's line in `wedge`, or -1 when that wedge is not
/// one of its lines'.
int across_in(const std::vector<VertexLine>& lines, int wedge) {
  for (const VertexLine& l : lines)
    if (l.wedge == wedge) return l.across;
  return -1;
}

}  // namespace

std::vector<Ligament> facing_boundary_lines(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                            const CrossField& field, const CutGraph& cut,
                                            const std::vector<int>& quads) {
  const std::vector<std::vector<VertexLine>> lines = vertex_lines(adjacency, field, cut, quads);
  std::vector<std::size_t> place(lines.size(), 0);
  for (const std::vector<int>& loop : adjacency.boundary_loops)
    for (std::size_t s = 0; s < loop.size(); ++s) place[static_cast<std::size_t>(loop[s])] = s;
  const auto far_apart = [&](int a, int b) {
    const auto sa = static_cast<std::size_t>(a), sb = static_cast<std::size_t>(b);
    const int loop = adjacency.loop_of_vertex[sa];
    if (loop != adjacency.loop_of_vertex[sb]) return true;
    const std::size_t n = adjacency.boundary_loops[static_cast<std::size_t>(loop)].size();
    const std::size_t d = place[sa] > place[sb] ? place[sa] - place[sb] : place[sb] - place[sa];
    return std::min(d, n - d) >= min_loop_separation;
  };
  std::vector<Ligament> out;
  // each pair once (an edge is met from both ends, a path through every vertex and
  // triangle on it)
  std::set<std::pair<int, int>> seen;
  // a pair facing in one chart: a's corner wedge and b's, each one of its lines'
  const auto add = [&](int a, int wedge_a, int b, int wedge_b) {
    if (a == b || !far_apart(a, b)) return;
    const int across = across_in(lines[static_cast<std::size_t>(a)], wedge_a);
    if (across < 0 || across != across_in(lines[static_cast<std::size_t>(b)], wedge_b)) return;
    const Ligament l{2 * wedge_a + across, 2 * wedge_b + across, 1.0};
    if (seen.insert(std::minmax(l.line_from, l.line_to)).second) out.push_back(l);
  };
  const auto straight = [&](int v) { return !lines[static_cast<std::size_t>(v)].empty(); };
  // through a vertex m: the far corners of m's triangles, paired where m's wedge is
  // one (no cut between them round m); an edge (a, b) is the case m = a
  for (std::size_t m = 0; m < adjacency.vertex_faces.size(); ++m) {
    struct Far {
      int vertex, wedge, wedge_at_m;
    };
    std::vector<Far> far;
    for (int f : adjacency.vertex_faces[m]) {
      const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
      const auto sf = static_cast<std::size_t>(f);
      for (std::size_t k = 0; k < 3; ++k) {
        if (static_cast<std::size_t>(t[k]) != m) continue;
        for (std::size_t o : {(k + 1) % 3, (k + 2) % 3}) {
          const int v = t[o];
          if (!straight(v)) continue;
          far.push_back({v, cut.wedge[sf][o], cut.wedge[sf][k]});
          if (straight(static_cast<int>(m))) add(static_cast<int>(m), cut.wedge[sf][k], v, cut.wedge[sf][o]);
        }
      }
    }
    for (std::size_t i = 0; i < far.size(); ++i)
      for (std::size_t j = i + 1; j < far.size(); ++j)
        if (far[i].wedge_at_m == far[j].wedge_at_m) add(far[i].vertex, far[i].wedge, far[j].vertex, far[j].wedge);
  }
  return out;
}

std::vector<Ligament> narrow_ligaments(const std::vector<Ligament>& facing, const Eigen::VectorXd& z,
                                       double min_width, double max_width) {
  std::vector<Ligament> out;
  for (Ligament l : facing) {
    const double width = z[l.line_to] - z[l.line_from];
    if (std::abs(width) < min_width || std::abs(width) > max_width) continue;
    l.sign = width > 0 ? 1 : -1;
    out.push_back(l);
  }
  return out;
}

std::size_t collapsed_ligaments(const std::vector<Ligament>& ligaments, const Eigen::VectorXd& z) {
  const auto integer = [&](int v) { return std::abs(z[v] - std::round(z[v])) < integer_tolerance; };
  std::size_t collapsed = 0;
  for (const Ligament& l : ligaments)
    collapsed += integer(l.line_from) && integer(l.line_to) && l.sign * (z[l.line_to] - z[l.line_from]) < 0.5;
  return collapsed;
}

}  // namespace qm
