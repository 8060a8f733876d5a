// Isotropic remeshing before the forms are computed (method.md section 6:
// slivers ruin the Galerkin Hodge star; coarse obtuse meshes give poor forms).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

namespace qm {

struct RemeshOptions {
  /// Target edge length; 0 means 0.4 times the mean edge length of the input
  /// (measured to bring ||Lambda^2 + I|| under 0.1 on the shared coarse meshes).
  double target_edge_length = 0.0;
  int iterations = 5;
};

/// The edge length remesh_isotropic aims at: the option, or its default.
double remesh_target(const TriangleSoup& soup, const RemeshOptions& options);

/// CGAL isotropic remeshing [Botsch & Kobbelt 2004] of an oriented manifold soup.
/// Boundary edges are split to the target length and then protected: the boundary
/// polyline is kept exactly. New vertices are projected onto the input surface.
/// Every point gets label -1 (the file's numbering no longer applies), and the CAD
/// curve information is dropped. The topology (chi, boundary loops) is unchanged.
TriangleSoup remesh_isotropic(const TriangleSoup& soup, const RemeshOptions& options = {});

}  // namespace qm
