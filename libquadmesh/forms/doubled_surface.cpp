#include "libquadmesh/forms/doubled_surface.h"

#include "libquadmesh/core/error.h"

#include <algorithm>

namespace qm {

namespace {

/// Fills edge_mirror / edge_mirror_sign from vertex_mirror.
void mirror_edges(DoubledSurface& d) {
  const Mesh& m = d.mesh;
  d.edge_mirror.assign(m.number_of_edges(), -1);
  d.edge_mirror_sign.assign(m.number_of_edges(), 0);
  for (Mesh::Edge_index e : m.edges()) {
    const Mesh::Halfedge_index h = m.halfedge(e, 0);
    const auto a = Mesh::Vertex_index(d.vertex_mirror[m.source(h)]);
    const auto b = Mesh::Vertex_index(d.vertex_mirror[m.target(h)]);
    Mesh::Halfedge_index g = m.halfedge(a, b);
    QM_ASSERT_MSG(g != Mesh::null_halfedge(), "the mirror of an edge must be an edge");
    const Mesh::Edge_index ge = m.edge(g);
    d.edge_mirror[e] = static_cast<int>(ge);
    d.edge_mirror_sign[e] = m.halfedge(ge, 0) == g ? 1 : -1;
  }
}

}  // namespace

DoubledSurface double_surface(const Mesh& s) {
  QM_ASSERT(s.number_of_removed_vertices() == 0 && s.number_of_removed_faces() == 0);
  DoubledSurface d;
  d.input_vertices = s.number_of_vertices();
  d.input_faces = s.number_of_faces();
  std::vector<int> minus(s.number_of_vertices(), -1);
  for (Mesh::Vertex_index v : s.vertices()) d.mesh.add_vertex(s.point(v));
  for (Mesh::Vertex_index v : s.vertices()) {
    if (s.is_border(v)) {
      minus[v] = static_cast<int>(v);
    } else {
      minus[v] = static_cast<int>(d.mesh.add_vertex(s.point(v)));
    }
  }
  QM_ASSERT_MSG(d.mesh.number_of_vertices() < 2 * s.number_of_vertices(), "needs a boundary");
  d.vertex_mirror.assign(d.mesh.number_of_vertices(), -1);
  for (Mesh::Vertex_index v : s.vertices()) {
    d.vertex_mirror[v] = minus[v];
    d.vertex_mirror[minus[v]] = static_cast<int>(v);
  }
  std::vector<Mesh::Vertex_index> corners;
  for (Mesh::Face_index f : s.faces()) {
    corners.clear();
    for (Mesh::Vertex_index v : s.vertices_around_face(s.halfedge(f))) corners.push_back(v);
    d.mesh.add_face(corners);
  }
  for (Mesh::Face_index f : s.faces()) {
    corners.clear();
    for (Mesh::Vertex_index v : s.vertices_around_face(s.halfedge(f)))
      corners.push_back(Mesh::Vertex_index(minus[v]));
    std::reverse(corners.begin(), corners.end());
    const Mesh::Face_index g = d.mesh.add_face(corners);
    QM_ASSERT_MSG(g != Mesh::null_face(), "mirror face must be addable");
  }
  QM_ASSERT_MSG(d.mesh.is_valid(false), "the doubled surface must be a valid mesh");
  d.face_mirror.resize(d.mesh.number_of_faces());
  for (std::size_t f = 0; f < d.input_faces; ++f) {
    d.face_mirror[f] = static_cast<int>(f + d.input_faces);
    d.face_mirror[f + d.input_faces] = static_cast<int>(f);
  }
  mirror_edges(d);
  d.is_input_boundary_edge.assign(d.mesh.number_of_edges(), 0);
  for (Mesh::Edge_index e : s.edges())
    if (s.is_border(e)) {
      const Mesh::Halfedge_index h = s.halfedge(e, 0);
      const Mesh::Halfedge_index g = d.mesh.halfedge(s.source(h), s.target(h));
      d.is_input_boundary_edge[d.mesh.edge(g)] = 1;
    }
  return d;
}

DoubledSurface identity_double(const Mesh& closed) {
  DoubledSurface d;
  d.mesh = closed;
  d.input_vertices = closed.number_of_vertices();
  d.input_faces = closed.number_of_faces();
  d.vertex_mirror.resize(closed.number_of_vertices());
  for (std::size_t i = 0; i < d.vertex_mirror.size(); ++i) d.vertex_mirror[i] = static_cast<int>(i);
  d.face_mirror.resize(closed.number_of_faces());
  for (std::size_t i = 0; i < d.face_mirror.size(); ++i) d.face_mirror[i] = static_cast<int>(i);
  mirror_edges(d);
  d.is_input_boundary_edge.assign(closed.number_of_edges(), 0);
  return d;
}

}  // namespace qm
