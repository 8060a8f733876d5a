#include "io/cad_curve_points.h"

#include "io/gmsh_session.h"
#include "libquadmesh/core/error.h"

#include <fmt/format.h>
#include <gmsh.h>

namespace qm::io {

std::vector<Vec3> closest_points_on_cad_curves(const std::string& path, const std::vector<CurvePointQuery>& queries) {
  GmshSession session;
  try {
    gmsh::open(path);
  } catch (...) {
  }
  if (const std::string error = session.first_error(); !error.empty())
    throw Error(ErrorCode::bad_input, fmt::format("{}: Gmsh could not read it again for the CAD curves: {}", path, error));
  std::vector<Vec3> out;
  out.reserve(queries.size());
  for (const CurvePointQuery& q : queries) {
    std::vector<double> closest, parameter;
    try {
      gmsh::model::getClosestPoint(1, q.curve, {q.near.x(), q.near.y(), q.near.z()}, closest, parameter);
    } catch (...) {
    }
    if (closest.size() != 3)
      throw Error(ErrorCode::bad_input, fmt::format("{}: no CAD curve {} to put a node on", path, q.curve));
    out.emplace_back(closest[0], closest[1], closest[2]);
  }
  return out;
}

}  // namespace qm::io
