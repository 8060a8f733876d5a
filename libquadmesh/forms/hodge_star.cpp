#include "libquadmesh/forms/hodge_star.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/edge_forms.h"

#include <Eigen/Dense>

namespace qm {

namespace {
Eigen::Vector3d vec(const Point3& p) { return {p.x(), p.y(), p.z()}; }
}  // namespace

std::vector<Eigen::MatrixX3d> face_covectors(const Mesh& m, const Eigen::MatrixXd& forms) {
  const Eigen::Index nF = static_cast<Eigen::Index>(m.number_of_faces());
  std::vector<Eigen::MatrixX3d> out(static_cast<std::size_t>(forms.cols()),
                                    Eigen::MatrixX3d::Zero(nF, 3));
  for (Mesh::Face_index f : m.faces()) {
    const Mesh::Halfedge_index h0 = m.halfedge(f);
    const Mesh::Halfedge_index h1 = m.next(h0);
    const Eigen::Vector3d p0 = vec(m.point(m.source(h0)));
    const Eigen::Vector3d e0 = vec(m.point(m.target(h0))) - p0;  // i -> j
    const Eigen::Vector3d e1 = vec(m.point(m.target(h1))) - p0;  // i -> k
    // u = a e0 + b e1 with u.e0 = w0, u.e1 = w1 (Gram system)
    Eigen::Matrix2d G;
    G << e0.dot(e0), e0.dot(e1), e0.dot(e1), e1.dot(e1);
    const Eigen::Matrix2d Ginv = G.inverse();
    for (Eigen::Index k = 0; k < forms.cols(); ++k) {
      const double w0 = value_along(m, forms.col(k), h0);
      const double w1 = w0 + value_along(m, forms.col(k), h1);  // i -> j -> k
      const Eigen::Vector2d ab = Ginv * Eigen::Vector2d(w0, w1);
      out[static_cast<std::size_t>(k)].row(static_cast<Eigen::Index>(f)) = ab[0] * e0 + ab[1] * e1;
    }
  }
  return out;
}

HodgeStar galerkin_hodge_star(const Mesh& m, const Eigen::MatrixXd& forms) {
  const Eigen::Index k = forms.cols();
  const auto cov = face_covectors(m, forms);
  HodgeStar star;
  star.wedge = Eigen::MatrixXd::Zero(k, k);
  star.inner = Eigen::MatrixXd::Zero(k, k);
  for (Mesh::Face_index f : m.faces()) {
    const Mesh::Halfedge_index h = m.halfedge(f);
    const Eigen::Vector3d p0 = vec(m.point(m.source(h)));
    const Eigen::Vector3d normal =
        (vec(m.point(m.target(h))) - p0).cross(vec(m.point(m.target(m.next(h)))) - p0);
    const double area = normal.norm() / 2;
    const Eigen::Vector3d n = normal.normalized();
    const Eigen::Index fi = static_cast<Eigen::Index>(f);
    for (Eigen::Index i = 0; i < k; ++i) {
      const Eigen::Vector3d ui = cov[i].row(fi);
      for (Eigen::Index j = 0; j < k; ++j) {
        const Eigen::Vector3d uj = cov[j].row(fi);
        star.wedge(i, j) += area * ui.cross(uj).dot(n);
        star.inner(i, j) += area * ui.dot(uj);
      }
    }
  }
  star.lambda = star.wedge.fullPivLu().solve(star.inner);
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(k, k);
  star.squared_residual = (star.lambda * star.lambda + I).norm() / I.norm();
  return star;
}

}  // namespace qm
