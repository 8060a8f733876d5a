#include "libquadmesh/forms/cut_integration.h"

#include "libquadmesh/forms/edge_forms.h"

#include <queue>
#include <vector>

namespace qm {

Eigen::MatrixX3d integrate_on_cut_surface(const Mesh& m, const Eigen::VectorXd& form,
                                          std::size_t face_count) {
  auto along = [&](Mesh::Halfedge_index h) { return value_along(m, form, h); };
  Eigen::MatrixX3d values = Eigen::MatrixX3d::Zero(static_cast<Eigen::Index>(face_count), 3);
  std::vector<char> done(face_count, 0);
  // Fills face f from a known value at the target of halfedge `from` (a halfedge of f).
  auto fill = [&](Mesh::Face_index f, Mesh::Halfedge_index from, double value) {
    const std::array<int, 3> corners = face_corners(m, f);
    Mesh::Halfedge_index h = from;
    for (int step = 0; step < 3; ++step) {
      const int v = static_cast<int>(m.target(h));
      for (int k = 0; k < 3; ++k)
        if (corners[k] == v) values(static_cast<Eigen::Index>(f), k) = value;
      h = m.next(h);
      value += along(h);
    }
  };
  for (std::size_t seed = 0; seed < face_count; ++seed) {
    if (done[seed]) continue;
    const Mesh::Face_index s(static_cast<Mesh::size_type>(seed));
    fill(s, m.halfedge(s), 0.0);
    done[seed] = 1;
    std::queue<Mesh::Face_index> queue;
    queue.push(s);
    while (!queue.empty()) {
      const Mesh::Face_index f = queue.front();
      queue.pop();
      const std::array<int, 3> corners = face_corners(m, f);
      for (Mesh::Halfedge_index h : m.halfedges_around_face(m.halfedge(f))) {
        const Mesh::Face_index g = m.face(m.opposite(h));
        if (g == Mesh::null_face() || static_cast<std::size_t>(g) >= face_count || done[g]) continue;
        // the opposite halfedge ends at source(h), whose value in f is known
        const int v = static_cast<int>(m.source(h));
        double value = 0;
        for (int k = 0; k < 3; ++k)
          if (corners[k] == v) value = values(static_cast<Eigen::Index>(f), k);
        fill(g, m.opposite(h), value);
        done[g] = 1;
        queue.push(g);
      }
    }
  }
  return values;
}

}  // namespace qm
