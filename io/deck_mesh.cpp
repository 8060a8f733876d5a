#include "io/deck_mesh.h"

#include "libquadmesh/core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace qm::io {

namespace {

std::size_t corner_count(const std::vector<int>& face) { return face.size() == 3 ? 3 : 4; }

/// Signed area in the xy plane of the polygon of the corners.
double xy_area(const std::vector<Vec3>& points, const std::vector<int>& face) {
  double a = 0;
  const std::size_t n = corner_count(face);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = points[static_cast<std::size_t>(face[i])];
    const Vec3& q = points[static_cast<std::size_t>(face[(i + 1) % n])];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return a / 2;
}

/// The same quad the other way round: corners 0 3 2 1, edge nodes of 3-0 2-3 1-2 0-1.
std::vector<int> reversed(const std::vector<int>& f) {
  if (f.size() == 3) return {f[0], f[2], f[1]};
  std::vector<int> r{f[0], f[3], f[2], f[1]};
  if (f.size() == 8) r.insert(r.end(), {f[7], f[6], f[5], f[4]});
  return r;
}

}  // namespace

std::string deck_name(const std::string& name) {
  std::string out;
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) || c == '_' ? c : '_';
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) out = "G" + out;
  return out.substr(0, 80);
}

DeckMesh deck_mesh(const OutputMesh& mesh, Format format, const std::string& element_type) {
  if (mesh.faces.empty()) throw Error(ErrorCode::bad_input, "a solver deck needs elements: the mesh has no faces");
  std::size_t n = 4;  // the quads' node count
  for (const auto& f : mesh.faces)
    if (f.size() == 8 || f.size() == 9) n = f.size();
  for (const auto& f : mesh.faces)
    if (f.size() != 3 && f.size() != 4 && f.size() != 8)
      throw Error(ErrorCode::bad_input, fmt::format("a solver deck takes triangles and quads of 4 or 8 nodes, not {}",
                                                    f.size()));
    else if (n == 8 && f.size() != 8)
      throw Error(ErrorCode::bad_input, "a solver deck of 8-node quads takes no other elements");
  DeckMesh deck;
  // compact numbering: the points the faces use, in their order
  std::vector<int> id(mesh.points.size(), 0);
  for (const auto& f : mesh.faces)
    for (int v : f) id[static_cast<std::size_t>(v)] = 1;
  std::vector<Vec3> used;
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    if (id[v]) {
      used.push_back(mesh.points[v]);
      id[v] = static_cast<int>(used.size());
    }
  deck.nodes = used;
  deck.element = deck_element(format, static_cast<int>(n), element_type, lies_in_xy_plane(used));
  deck.triangle = triangle_element(format, deck.element.kind);
  const bool plane = deck.element.kind != ElementKind::shell;

  std::map<std::pair<int, int>, std::pair<int, int>> side_of_edge;  // (a, b) point indices -> (element, side)
  for (const auto& face : mesh.faces) {
    const std::vector<int> f = plane && xy_area(mesh.points, face) < 0 ? reversed(face) : face;
    const int element = static_cast<int>(deck.elements.size()) + 1;
    std::vector<int> nodes;
    for (int v : f) nodes.push_back(id[static_cast<std::size_t>(v)]);
    deck.elements.push_back(std::move(nodes));
    const int corners = static_cast<int>(corner_count(f));
    for (int s = 0; s < corners; ++s) {
      const int a = f[static_cast<std::size_t>(s)], b = f[static_cast<std::size_t>((s + 1) % corners)];
      side_of_edge[{std::min(a, b), std::max(a, b)}] = {element, s};
    }
  }
  for (const LineGroup& g : mesh.line_groups) {
    DeckSet set{deck_name(g.name), {}, {}};
    for (std::size_t i = 0; i < g.edges.size(); ++i) {
      const auto [a, b] = g.edges[i];
      for (int v : {a, b}) set.nodes.push_back(id[static_cast<std::size_t>(v)]);
      if (!g.mids.empty()) set.nodes.push_back(id[static_cast<std::size_t>(g.mids[i])]);
      const auto it = side_of_edge.find({std::min(a, b), std::max(a, b)});
      if (it != side_of_edge.end()) set.sides.push_back(it->second);
    }
    deck.sets.push_back(std::move(set));
  }
  for (const PointGroup& g : mesh.point_groups) {
    DeckSet set{deck_name(g.name), {}, {}};
    for (int v : g.points) set.nodes.push_back(id[static_cast<std::size_t>(v)]);
    deck.sets.push_back(std::move(set));
  }
  for (DeckSet& s : deck.sets) {
    s.nodes.erase(std::remove(s.nodes.begin(), s.nodes.end(), 0), s.nodes.end());
    std::sort(s.nodes.begin(), s.nodes.end());
    s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
    std::sort(s.sides.begin(), s.sides.end());
  }
  deck.element_set = deck_name(mesh.surface_group);
  return deck;
}

}  // namespace qm::io
