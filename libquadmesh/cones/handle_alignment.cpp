#include "libquadmesh/cones/handle_alignment.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/core/internal/union_find.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <queue>

namespace qm {

namespace {

/// Per vertex, the inner edges' other ends.
std::vector<std::vector<int>> inner_neighbours(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  std::vector<std::vector<int>> next(soup.points.size());
  for (const Triangle& t : soup.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (adjacency.find(b, a).face >= 0) next[static_cast<std::size_t>(a)].push_back(b);
    }
  return next;
}

/// A breadth-first tree of the vertices along inner edges: parent per vertex (-1
/// at the root and at vertices with no inner edge) and depth (-1: not reached).
struct VertexTree {
  std::vector<int> parent;
  std::vector<int> depth;
  bool holds(int a, int b) const {
    return parent[static_cast<std::size_t>(a)] == b || parent[static_cast<std::size_t>(b)] == a;
  }
};

VertexTree inner_vertex_tree(const SurfaceAdjacency& adjacency, const std::vector<std::vector<int>>& next) {
  const std::size_t nV = next.size();
  VertexTree tree{std::vector<int>(nV, -1), std::vector<int>(nV, -1)};
  // the root: an interior vertex if there is one
  int root = -1;
  for (std::size_t v = 0; v < nV && root < 0; ++v)
    if (!next[v].empty() && !adjacency.boundary_vertex[v]) root = static_cast<int>(v);
  for (std::size_t v = 0; v < nV && root < 0; ++v)
    if (!next[v].empty()) root = static_cast<int>(v);
  if (root < 0) return tree;
  std::queue<int> queue;
  tree.depth[static_cast<std::size_t>(root)] = 0;
  queue.push(root);
  while (!queue.empty()) {
    const int v = queue.front();
    queue.pop();
    for (int w : next[static_cast<std::size_t>(v)]) {
      if (tree.depth[static_cast<std::size_t>(w)] >= 0) continue;
      tree.depth[static_cast<std::size_t>(w)] = tree.depth[static_cast<std::size_t>(v)] + 1;
      tree.parent[static_cast<std::size_t>(w)] = v;
      queue.push(w);
    }
  }
  return tree;
}

/// The inner edges (a, b), a < b, in neither the vertex tree nor the cotree of the
/// capped surface: one per handle generator.
std::vector<std::pair<int, int>> generator_edges(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                                 const VertexTree& tree) {
  const std::size_t nF = soup.triangles.size();
  UnionFind cotree(nF + adjacency.boundary_loops.size());  // the triangles and one cap per boundary loop
  // the caps first, so that the cotree takes the boundary edges it can
  for (std::size_t f = 0; f < nF; ++f)
    for (int k = 0; k < 3; ++k) {
      const Triangle& t = soup.triangles[f];
      if (adjacency.find(t[(k + 1) % 3], t[k]).face >= 0) continue;
      cotree.unite(static_cast<int>(f),
                  static_cast<int>(nF) + adjacency.loop_of_vertex[static_cast<std::size_t>(t[k])]);
    }
  std::vector<std::pair<int, int>> generators;
  for (std::size_t f = 0; f < nF; ++f)
    for (int k = 0; k < 3; ++k) {
      const Triangle& t = soup.triangles[f];
      const int a = t[k], b = t[(k + 1) % 3];
      const EdgeCorner g = adjacency.find(b, a);
      if (g.face < static_cast<int>(f)) continue;  // boundary side, or the twin's turn
      if (tree.holds(a, b)) continue;
      if (tree.depth[static_cast<std::size_t>(a)] < 0 || tree.depth[static_cast<std::size_t>(b)] < 0) continue;
      if (!cotree.unite(static_cast<int>(f), g.face)) generators.emplace_back(std::min(a, b), std::max(a, b));
    }
  return generators;
}

/// The cycle closed by the edge (a, b): up the tree from b and down to a, as vertices.
std::vector<int> generator_cycle(const VertexTree& tree, int a, int b) {
  std::vector<int> from_b{b}, from_a{a};
  auto up = [&](std::vector<int>& path) {
    path.push_back(tree.parent[static_cast<std::size_t>(path.back())]);
  };
  while (tree.depth[static_cast<std::size_t>(from_b.back())] > tree.depth[static_cast<std::size_t>(from_a.back())]) up(from_b);
  while (tree.depth[static_cast<std::size_t>(from_a.back())] > tree.depth[static_cast<std::size_t>(from_b.back())]) up(from_a);
  while (from_a.back() != from_b.back()) {
    up(from_a);
    up(from_b);
  }
  // b, ..., lca, then down to a; the edge a -> b closes it
  std::vector<int> cycle = from_b;
  for (auto it = from_a.rbegin() + 1; it != from_a.rend(); ++it) cycle.push_back(*it);
  return cycle;
}

/// The Poincare dual of a closed vertex cycle along inner edges.
SideForm dual_form(const SurfaceAdjacency& adjacency, std::size_t triangles, const std::vector<int>& cycle) {
  SideForm form(triangles, {0.0, 0.0, 0.0});
  for (std::size_t s = 0; s < cycle.size(); ++s) {
    const int x = cycle[s], y = cycle[(s + 1) % cycle.size()];
    const EdgeCorner left = adjacency.find(x, y), right = adjacency.find(y, x);
    QM_ASSERT(left.face >= 0 && right.face >= 0);
    // crossing from the right of x -> y to its left adds 1
    form[static_cast<std::size_t>(right.face)][static_cast<std::size_t>(right.i)] += 1.0;
    form[static_cast<std::size_t>(left.face)][static_cast<std::size_t>(left.i)] -= 1.0;
  }
  return form;
}

/// Adds d(phi) to each form, phi minimizing the form's squared norm on the
/// triangle graph with phi = 0 on the triangles with a boundary side.
void harmonize(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, std::vector<SideForm>& forms) {
  const auto nF = static_cast<Eigen::Index>(soup.triangles.size());
  // per triangle side, the triangle across it (-1: a boundary side); held: a boundary side
  std::vector<std::array<int, 3>> twin(static_cast<std::size_t>(nF), {-1, -1, -1});
  std::vector<char> held(static_cast<std::size_t>(nF), 0);
  for (Eigen::Index f = 0; f < nF; ++f) {
    const Triangle& t = soup.triangles[static_cast<std::size_t>(f)];
    for (int k = 0; k < 3; ++k) {
      const int g = adjacency.find(t[(k + 1) % 3], t[k]).face;
      twin[static_cast<std::size_t>(f)][static_cast<std::size_t>(k)] = g;
      held[static_cast<std::size_t>(f)] |= g < 0;
    }
  }
  if (std::find(held.begin(), held.end(), 1) == held.end()) held[0] = 1;
  std::vector<Eigen::Triplet<double>> entries;
  for (Eigen::Index f = 0; f < nF; ++f) {
    if (held[static_cast<std::size_t>(f)]) {
      entries.emplace_back(f, f, 1.0);
      continue;
    }
    for (int g : twin[static_cast<std::size_t>(f)]) {
      entries.emplace_back(f, f, 1.0);
      if (!held[static_cast<std::size_t>(g)]) entries.emplace_back(f, g, -1.0);
    }
  }
  Eigen::SparseMatrix<double> A(nF, nF);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> solver;
  solver.compute(A);
  if (solver.info() != Eigen::Success) throw Error(ErrorCode::solver, "the handle forms could not be factored");
  for (SideForm& form : forms) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(nF);
    for (Eigen::Index f = 0; f < nF; ++f)
      if (!held[static_cast<std::size_t>(f)])
        for (double w : form[static_cast<std::size_t>(f)]) rhs[f] += w;
    const Eigen::VectorXd phi = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !phi.allFinite()) throw Error(ErrorCode::solver, "the handle forms' solve failed");
    // crossing out of f into g adds phi_g - phi_f
    for (Eigen::Index f = 0; f < nF; ++f)
      for (std::size_t k = 0; k < 3; ++k) {
        const int g = twin[static_cast<std::size_t>(f)][k];
        if (g >= 0) form[static_cast<std::size_t>(f)][k] += phi[g] - phi[f];
      }
  }
}

}  // namespace

std::vector<SideForm> handle_forms(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  const VertexTree tree = inner_vertex_tree(adjacency, inner_neighbours(soup, adjacency));
  std::vector<SideForm> forms;
  for (const auto& [a, b] : generator_edges(soup, adjacency, tree))
    forms.push_back(dual_form(adjacency, soup.triangles.size(), generator_cycle(tree, a, b)));
  if (!forms.empty()) harmonize(soup, adjacency, forms);
  return forms;
}

SideForm combined_form(const std::vector<SideForm>& forms, const std::vector<double>& coefficient) {
  QM_ASSERT(forms.size() == coefficient.size());
  SideForm sum(forms.empty() ? 0 : forms.front().size(), {0.0, 0.0, 0.0});
  for (std::size_t k = 0; k < forms.size(); ++k)
    for (std::size_t f = 0; f < sum.size(); ++f)
      for (std::size_t s = 0; s < 3; ++s) sum[f][s] += coefficient[k] * forms[k][f][s];
  return sum;
}

double max_vertex_curl(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const SideForm& form) {
  std::vector<double> curl(soup.points.size(), 0.0);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int c = 0; c < 3; ++c)
      // turning counter-clockwise about corner c, f is left across side c + 2
      curl[static_cast<std::size_t>(soup.triangles[f][c])] += form[f][static_cast<std::size_t>((c + 2) % 3)];
  double largest = 0;
  for (std::size_t v = 0; v < curl.size(); ++v)
    if (!adjacency.vertex_faces[v].empty()) largest = std::max(largest, std::abs(curl[v]));
  return largest;
}

}  // namespace qm
