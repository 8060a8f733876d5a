#include "libquadmesh/forms/cotan_laplacian.h"

#include <vector>

namespace qm {

namespace {
/// cot of the angle at `apex` in the triangle (apex, a, b).
double cot_at(const Point3& apex, const Point3& a, const Point3& b) {
  const Kernel::Vector_3 u = a - apex, v = b - apex;
  const double cross = std::sqrt(CGAL::cross_product(u, v).squared_length());
  return (u * v) / cross;
}
}  // namespace

Eigen::VectorXd cotan_weights(const Mesh& mesh) {
  Eigen::VectorXd w = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh.number_of_edges()));
  for (Mesh::Edge_index e : mesh.edges()) {
    double sum = 0;
    for (int side = 0; side < 2; ++side) {
      const Mesh::Halfedge_index h = mesh.halfedge(e, side);
      if (mesh.is_border(h)) continue;
      const Mesh::Vertex_index apex = mesh.target(mesh.next(h));
      sum += cot_at(mesh.point(apex), mesh.point(mesh.source(h)), mesh.point(mesh.target(h)));
    }
    w[static_cast<Eigen::Index>(e)] = sum / 2;
  }
  return w;
}

SparseMatrix exterior_derivative_0(const Mesh& mesh) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(2 * mesh.number_of_edges());
  for (Mesh::Edge_index e : mesh.edges()) {
    const Mesh::Halfedge_index h = mesh.halfedge(e, 0);
    entries.emplace_back(static_cast<int>(e), static_cast<int>(mesh.target(h)), 1.0);
    entries.emplace_back(static_cast<int>(e), static_cast<int>(mesh.source(h)), -1.0);
  }
  SparseMatrix d0(static_cast<Eigen::Index>(mesh.number_of_edges()),
                  static_cast<Eigen::Index>(mesh.number_of_vertices()));
  d0.setFromTriplets(entries.begin(), entries.end());
  return d0;
}

SparseMatrix cotan_laplacian(const Mesh& mesh, const Eigen::VectorXd& weights) {
  const SparseMatrix d0 = exterior_derivative_0(mesh);
  SparseMatrix L = d0.transpose() * weights.asDiagonal() * d0;
  L.makeCompressed();
  return L;
}

}  // namespace qm
