#include "libquadmesh/forms/zeros.h"

#include "libquadmesh/core/internal/union_find.h"
#include "libquadmesh/forms/edge_forms.h"

#include <cmath>
#include <complex>

namespace qm {

FormZeros form_zeros(const DoubledSurface& d, const Eigen::VectorXd& re, const Eigen::VectorXd& im) {
  using C = std::complex<double>;
  const Mesh& m = d.mesh;
  auto along = [&](Mesh::Halfedge_index h) {
    return C(value_along(m, re, h), value_along(m, im, h));
  };
  const std::size_t nV = m.number_of_vertices(), nF = m.number_of_faces();
  FormZeros z;
  z.flipped.assign(nF, 0);
  std::vector<double> angle(nV, 0.0), size_sum(nV, 0.0);
  std::vector<int> valence(nV, 0);
  for (Mesh::Face_index f : m.faces()) {
    const Mesh::Halfedge_index h0 = m.halfedge(f), h1 = m.next(h0), h2 = m.next(h1);
    const C a = along(h0), b = along(h1), c = along(h2);  // sides i->j, j->k, k->i
    const double area2 = std::imag(std::conj(a) * (-c));  // (z_j - z_i) x (z_k - z_i)
    if (area2 < 0) {
      z.flipped[f] = 1;
      ++z.flipped_count;
    }
    // angle at the source of each side: from that side to the reverse of the previous
    const Mesh::Halfedge_index hs[3] = {h0, h1, h2};
    const C sides[3] = {a, b, c};
    const double magnitude = (std::abs(a) + std::abs(b) + std::abs(c)) / 3;
    for (int s = 0; s < 3; ++s) {
      const C out = sides[s], in_reversed = -sides[(s + 2) % 3];
      const auto v = m.source(hs[s]);
      angle[v] += std::arg(in_reversed / out);
      size_sum[v] += magnitude;
      ++valence[v];
    }
  }
  z.vertex_order.resize(nV);
  for (std::size_t v = 0; v < nV; ++v)
    z.vertex_order[v] = static_cast<int>(std::lround(angle[v] / (2 * M_PI))) - 1;

  UnionFind sets(nV);
  for (Mesh::Face_index f : m.faces()) {
    if (!z.flipped[f]) continue;
    const Mesh::Halfedge_index h = m.halfedge(f);
    sets.unite(m.source(h), m.target(h));
    sets.unite(m.target(h), m.target(m.next(h)));
  }
  std::vector<int> cluster_of(nV, -1);
  auto cluster_for = [&](std::size_t v) {
    const int root = sets.find(static_cast<int>(v));
    if (cluster_of[root] < 0) {
      cluster_of[root] = static_cast<int>(z.clusters.size());
      z.clusters.emplace_back();
    }
    return cluster_of[root];
  };
  std::vector<char> in_fold(nV, 0);
  for (Mesh::Face_index f : m.faces())
    if (z.flipped[f]) {
      const Mesh::Halfedge_index h = m.halfedge(f);
      in_fold[m.source(h)] = in_fold[m.target(h)] = in_fold[m.target(m.next(h))] = 1;
    }
  for (std::size_t v = 0; v < nV; ++v) {
    if (z.vertex_order[v] == 0 && !in_fold[v]) continue;
    ZeroCluster& c = z.clusters[cluster_for(v)];
    c.vertices.push_back(static_cast<int>(v));
    c.order += z.vertex_order[v];
    if (d.vertex_mirror[v] == static_cast<int>(v) && d.input_vertices < nV) c.on_boundary = true;
  }
  for (Mesh::Face_index f : m.faces())
    if (z.flipped[f]) {
      ZeroCluster& c = z.clusters[cluster_for(m.source(m.halfedge(f)))];
      ++c.flipped_triangles;
      ++c.order;
    }
  for (ZeroCluster& c : z.clusters) {
    double best = std::numeric_limits<double>::infinity();
    for (int v : c.vertices) {
      const double mean = size_sum[v] / std::max(1, valence[v]);
      const bool plus = static_cast<std::size_t>(v) < d.input_vertices;
      // prefer vertices of S (the + copy), then the smallest |h|
      const double key = mean + (plus ? 0.0 : 1e300);
      if (key < best) {
        best = key;
        c.representative = v;
      }
    }
    z.order_sum += c.order;
  }
  return z;
}

}  // namespace qm
