// The Jacobian determinant ratio of curved (quadratic) quads: how far the map
// from the reference square is from folding. A solver rejects an element whose
// determinant is <= 0 somewhere; the ratio min J / max J is the usual check of
// higher-order meshes (Gmsh's "SICN"-like Jacobian ratio, Abaqus' "distorted
// element" warning), 1 for a parallelogram with straight edges.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <vector>

namespace qm {

/// Samples of the reference square [-1, 1]^2 at which J is measured: a 5 x 5 grid,
/// which holds every node of the 4-, 8- and 9-node quads.
inline constexpr int jacobian_samples_per_side = 5;

/// min J / max J over the samples of one quad with 4, 8 (serendipity) or 9
/// (Lagrange) nodes in the Gmsh / Abaqus order (corners, then the nodes of edges
/// 0-1, 1-2, 2-3, 3-0, then the inside node). J = (x_xi x x_eta) . n, with n the
/// unit normal at the centre, (x_xi x x_eta)(0, 0) normalized: the determinant
/// of the map in the element's own plane, for surfaces in 3D. Returns <= 0 when J
/// changes sign or vanishes (or the element is degenerate at its centre: -1).
/// Precondition: element.size() is 4, 8 or 9.
double jacobian_ratio(const std::vector<Vec3>& points, const std::vector<int>& element);

struct CurvedJacobians {
  double min_ratio = 1.0;  ///< over all elements (1 for none)
  int worst = -1;          ///< the element where it is reached
  std::size_t non_positive = 0;  ///< elements with a ratio <= 0
};

CurvedJacobians curved_jacobians(const std::vector<Vec3>& points, const std::vector<std::vector<int>>& elements);

}  // namespace qm
