#include "libquadmesh/core/mesh.h"

#include "libquadmesh/core/error.h"

namespace qm {

Mesh to_surface_mesh(const TriangleSoup& soup) {
  Mesh mesh;
  mesh.reserve(static_cast<Mesh::size_type>(soup.points.size()),
               static_cast<Mesh::size_type>(3 * soup.triangles.size() / 2 + soup.points.size()),
               static_cast<Mesh::size_type>(soup.triangles.size()));
  for (const Vec3& p : soup.points) mesh.add_vertex(Point3(p.x(), p.y(), p.z()));
  for (const Triangle& t : soup.triangles) {
    const Mesh::Face_index f =
        mesh.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2]));
    QM_ASSERT_MSG(f != Mesh::null_face(), "soup must be oriented and manifold");
  }
  return mesh;
}

std::array<int, 3> face_corners(const Mesh& m, Mesh::Face_index f) {
  std::array<int, 3> out{};
  int k = 0;
  for (Mesh::Halfedge_index h : m.halfedges_around_face(m.halfedge(f)))
    if (k < 3) out[k++] = static_cast<int>(m.target(h));
  return out;
}

TriangleSoup soup_of(const Mesh& mesh, const TriangleSoup& before) {
  QM_ASSERT(mesh.number_of_removed_vertices() == 0 && mesh.number_of_removed_faces() == 0);
  QM_ASSERT(mesh.number_of_vertices() >= before.points.size());
  TriangleSoup out;
  out.cad = before.cad;
  for (Mesh::Vertex_index v : mesh.vertices()) {
    out.points.emplace_back(mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z());
    const std::size_t i = static_cast<std::size_t>(v);
    out.point_labels.push_back(i < before.points.size() ? before.point_label(static_cast<int>(i)) : -1);
  }
  for (Mesh::Face_index f : mesh.faces()) out.triangles.push_back(face_corners(mesh, f));
  return out;
}

}  // namespace qm
