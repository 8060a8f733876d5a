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

}  // namespace qm
