// The symmetric holomorphic forms restricted to S (the + copy of the double), as
// face maps: each triangle of S with the local integral of h_k at its corners.
// Symmetric forms are determined by their values on S (method.md section 6).
#pragma once

#include "libquadmesh/forms/symmetric_forms.h"
#include "libquadmesh/param/face_map.h"

namespace qm {

/// One FaceMap per symmetric basis form h_k = omega_k + i *omega_k, over the
/// triangles of `soup` (the soup S the forms were computed on; triangle f of S is
/// face f of the double). Each triangle's first corner maps to 0.
std::vector<FaceMap> symmetric_face_maps(const SymmetricForms& forms, const TriangleSoup& soup);

}  // namespace qm
