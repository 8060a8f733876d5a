#include "libquadmesh/forms/cohomology_basis.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/edge_forms.h"
#include "libquadmesh/forms/internal/spanning_tree.h"

#include <cmath>
#include <queue>

namespace qm {

CohomologyBasis cohomology_basis(const Mesh& m) {
  QM_ASSERT(m.number_of_removed_edges() == 0);
  const std::size_t nE = m.number_of_edges();
  const std::vector<char> in_tree = vertex_spanning_tree(m).edge_used;
  std::vector<char> crossed_by_cotree(nE, 0);
  // dual spanning tree avoiding the primal tree; remember each face's parent edge
  const std::size_t nF = m.number_of_faces();
  std::vector<int> parent_halfedge(nF, -1);  // halfedge of f on the edge to its parent
  std::vector<char> face_reached(nF, 0);
  std::vector<Mesh::Face_index> order;
  order.reserve(nF);
  std::queue<Mesh::Face_index> fq;
  fq.push(Mesh::Face_index(0));
  face_reached[0] = 1;
  while (!fq.empty()) {
    const Mesh::Face_index f = fq.front();
    fq.pop();
    order.push_back(f);
    for (Mesh::Halfedge_index h : m.halfedges_around_face(m.halfedge(f))) {
      if (in_tree[m.edge(h)]) continue;
      const Mesh::Face_index g = m.face(m.opposite(h));
      if (g == Mesh::null_face() || face_reached[g]) continue;
      face_reached[g] = 1;
      crossed_by_cotree[m.edge(h)] = 1;
      parent_halfedge[g] = static_cast<int>(m.opposite(h));
      fq.push(g);
    }
  }
  CohomologyBasis basis;
  for (Mesh::Edge_index e : m.edges())
    if (!in_tree[e] && !crossed_by_cotree[e]) basis.generator_edges.push_back(static_cast<int>(e));

  const Eigen::Index k = static_cast<Eigen::Index>(basis.generator_edges.size());
  basis.forms = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(nE), k);
  for (Eigen::Index g = 0; g < k; ++g) basis.forms(basis.generator_edges[g], g) = 1.0;
  // Peel the dual tree from its leaves: the parent edge of f takes the value that
  // closes f. Reverse breadth-first order visits children before parents.
  for (auto it = order.rbegin(); it != order.rend(); ++it) {
    const Mesh::Face_index f = *it;
    if (parent_halfedge[f] < 0) continue;  // the root: closed automatically
    const Mesh::Halfedge_index ph(static_cast<Mesh::size_type>(parent_halfedge[f]));
    Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(k);
    for (Mesh::Halfedge_index h : m.halfedges_around_face(m.halfedge(f)))
      if (h != ph) sum += along_sign(m, h) * basis.forms.row(static_cast<Eigen::Index>(m.edge(h)));
    basis.forms.row(static_cast<Eigen::Index>(m.edge(ph))) = -along_sign(m, ph) * sum;
  }
  return basis;
}

double max_face_curl(const Mesh& m, const Eigen::MatrixXd& forms) {
  double worst = 0;
  for (Mesh::Face_index f : m.faces()) {
    Eigen::RowVectorXd sum = Eigen::RowVectorXd::Zero(forms.cols());
    for (Mesh::Halfedge_index h : m.halfedges_around_face(m.halfedge(f)))
      sum += along_sign(m, h) * forms.row(static_cast<Eigen::Index>(m.edge(h)));
    worst = std::max(worst, sum.cwiseAbs().maxCoeff());
  }
  return worst;
}

}  // namespace qm
