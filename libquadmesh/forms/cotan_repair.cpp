#include "libquadmesh/forms/cotan_repair.h"

#include "libquadmesh/forms/cotan_laplacian.h"

#include <CGAL/boost/graph/Euler_operations.h>

#include <cmath>

namespace qm {

namespace {

Kernel::Vector_3 face_normal(const Mesh& m, Mesh::Halfedge_index h) {
  const Point3& a = m.point(m.source(h));
  const Point3& b = m.point(m.target(h));
  const Point3& c = m.point(m.target(m.next(h)));
  return CGAL::cross_product(b - a, c - a);
}

double angle_between(const Kernel::Vector_3& u, const Kernel::Vector_3& v) {
  const double nu = std::sqrt(u.squared_length()), nv = std::sqrt(v.squared_length());
  if (nu == 0 || nv == 0) return M_PI;
  return std::acos(std::clamp((u * v) / (nu * nv), -1.0, 1.0));
}

/// Flipping the edge of h keeps both new triangles facing like the old ones.
bool flip_is_safe(const Mesh& m, Mesh::Halfedge_index h, double flat) {
  const Mesh::Halfedge_index o = m.opposite(h);
  const Mesh::Vertex_index c = m.target(m.next(h)), d = m.target(m.next(o));
  if (c == d || m.halfedge(c, d) != Mesh::null_halfedge()) return false;
  const Kernel::Vector_3 n1 = face_normal(m, h), n2 = face_normal(m, o);
  if (angle_between(n1, n2) > flat) return false;
  const Kernel::Vector_3 n = n1 + n2;
  const Point3 &a = m.point(m.source(h)), &b = m.point(m.target(h));
  const Point3 &pc = m.point(c), &pd = m.point(d);
  // new triangles (c, d, b) and (d, c, a), oriented like the old pair
  return CGAL::cross_product(pd - pc, b - pc) * n > 0 && CGAL::cross_product(pc - pd, a - pd) * n > 0;
}

/// Splits the edge of h at its midpoint and joins the new vertex to the opposite
/// vertex of each adjacent triangle.
void split_at_midpoint(Mesh& m, Mesh::Halfedge_index h) {
  const Point3 mid = CGAL::midpoint(m.point(m.source(h)), m.point(m.target(h)));
  // split_edge(h) inserts a vertex on the edge; the returned halfedge ends at it
  const Mesh::Halfedge_index hn = CGAL::Euler::split_edge(h, m);
  m.point(m.target(hn)) = mid;
  for (Mesh::Halfedge_index side : {hn, m.opposite(hn)}) {
    if (m.is_border(side)) continue;
    // the face of `side` is now a quad: connect the new vertex to the opposite corner
    const Mesh::Halfedge_index to_new = m.target(side) == m.target(hn) ? side : m.prev(side);
    CGAL::Euler::split_face(to_new, m.next(m.next(to_new)), m);
  }
}

}  // namespace

CotanRepairReport repair_cotan_weights(Mesh& m, const CotanRepairOptions& options) {
  CotanRepairReport report;
  const double flat = options.flat_dihedral_deg * M_PI / 180.0;
  auto negative_edges = [&]() {
    const Eigen::VectorXd w = cotan_weights(m);
    std::vector<Mesh::Edge_index> out;
    for (Mesh::Edge_index e : m.edges())
      if (w[static_cast<Eigen::Index>(e)] < 0) out.push_back(e);
    return out;
  };
  std::vector<Mesh::Edge_index> bad = negative_edges();
  report.negative_before = bad.size();
  for (int round = 0; round < options.max_rounds && !bad.empty(); ++round) {
    std::vector<char> touched(m.number_of_faces() + 4 * bad.size(), 0);
    for (Mesh::Edge_index e : bad) {
      const Mesh::Halfedge_index h = m.halfedge(e, 0);
      const Mesh::Halfedge_index o = m.opposite(h);
      const bool boundary = m.is_border(h) || m.is_border(o);
      const int f1 = m.is_border(h) ? -1 : static_cast<int>(m.face(h));
      const int f2 = m.is_border(o) ? -1 : static_cast<int>(m.face(o));
      if ((f1 >= 0 && touched[f1]) || (f2 >= 0 && touched[f2])) continue;  // next round
      if (f1 >= 0) touched[f1] = 1;
      if (f2 >= 0) touched[f2] = 1;
      if (!boundary && flip_is_safe(m, h, flat)) {
        CGAL::Euler::flip_edge(h, m);
        ++report.flips;
      } else {
        split_at_midpoint(m, m.is_border(h) ? o : h);
        ++(boundary ? report.boundary_splits : report.interior_splits);
      }
    }
    bad = negative_edges();
  }
  report.negative_after = bad.size();
  return report;
}

}  // namespace qm
