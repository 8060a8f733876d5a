#include "libquadmesh/param/surface_forms.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/edge_forms.h"

namespace qm {

std::vector<FaceMap> symmetric_face_maps(const SymmetricForms& forms, const TriangleSoup& soup) {
  const Mesh& D = forms.doubled.mesh;
  QM_ASSERT(forms.doubled.input_faces == soup.triangles.size());
  const int count = forms.symmetric.dimension();
  std::vector<FaceMap> maps(static_cast<std::size_t>(count));
  for (FaceMap& m : maps) m.corners.assign(soup.triangles.size(), CornerValues{});
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    const Mesh::Face_index face(static_cast<Mesh::size_type>(f));
    // walk the face from the halfedge leaving corner 0
    Mesh::Halfedge_index h = D.halfedge(face);
    while (static_cast<int>(D.source(h)) != t[0]) h = D.next(h);
    for (int step = 0; step < 2; ++step) {
      QM_ASSERT(static_cast<int>(D.target(h)) == t[step + 1]);
      for (int k = 0; k < count; ++k) {
        const Complex along(value_along(D, forms.symmetric.real_part.col(k), h),
                            value_along(D, forms.symmetric.imaginary_part.col(k), h));
        maps[static_cast<std::size_t>(k)].corners[f][step + 1] =
            maps[static_cast<std::size_t>(k)].corners[f][step] + along;
      }
      h = D.next(h);
    }
  }
  return maps;
}

}  // namespace qm
