// Edge 1-forms: a value per edge of the mesh, stored along halfedge(e, 0) (the
// convention of every function in forms/). Reading one along any halfedge.
#pragma once

#include "libquadmesh/core/mesh.h"

namespace qm {

/// +1 when h is halfedge(edge(h), 0), -1 when it is the opposite one.
inline double along_sign(const Mesh& m, Mesh::Halfedge_index h) {
  return m.halfedge(m.edge(h), 0) == h ? 1.0 : -1.0;
}

/// The value of the form (any Eigen vector expression indexed by edge) along h.
template <class Form>
auto value_along(const Mesh& m, const Form& form, Mesh::Halfedge_index h) {
  return along_sign(m, h) * form[static_cast<Eigen::Index>(m.edge(h))];
}

}  // namespace qm
