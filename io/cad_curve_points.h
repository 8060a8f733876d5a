// Points on the exact CAD curves of a model: where `quadmesh mesh --order 2` puts
// the nodes of boundary edges of CAD input (docs/outputs.md "Quadratic quads").
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <string>
#include <vector>

namespace qm::io {

struct CurvePointQuery {
  int curve = -1;  ///< the CAD curve's tag (Gmsh entity of dimension 1), as CurveEdge::curve
  Vec3 near = Vec3::Zero();
};

/// For each query, the point of its curve closest to `near` (Gmsh's
/// getClosestPoint on the model `path` (.geo .step .brep .iges) opens in this
/// process). Throws qm::Error(bad_input) when Gmsh cannot open the model or a
/// curve is not in it.
std::vector<Vec3> closest_points_on_cad_curves(const std::string& path, const std::vector<CurvePointQuery>& queries);

}  // namespace qm::io
