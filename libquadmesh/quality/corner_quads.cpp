#include "libquadmesh/quality/corner_quads.h"

#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace qm {

namespace {

/// Per point of `mesh`: the faces around it, and the length of its shortest
/// boundary edge (infinity for a point not on the boundary).
struct BoundaryPoints {
  std::vector<int> faces;
  std::vector<double> shortest_boundary_edge;
};

BoundaryPoints boundary_points(const PolygonMesh& mesh) {
  BoundaryPoints b;
  b.faces.assign(mesh.points.size(), 0);
  b.shortest_boundary_edge.assign(mesh.points.size(), std::numeric_limits<double>::infinity());
  std::map<std::pair<int, int>, int> uses;
  for (const std::vector<int>& face : mesh.faces)
    for (std::size_t k = 0; k < face.size(); ++k) {
      ++b.faces[static_cast<std::size_t>(face[k])];
      const int a = face[k], c = face[(k + 1) % face.size()];
      ++uses[{std::min(a, c), std::max(a, c)}];
    }
  for (const auto& [edge, count] : uses) {
    if (count != 1) continue;
    const double length = (mesh.points[static_cast<std::size_t>(edge.first)] -
                           mesh.points[static_cast<std::size_t>(edge.second)]).norm();
    for (int v : {edge.first, edge.second}) {
      double& shortest = b.shortest_boundary_edge[static_cast<std::size_t>(v)];
      shortest = std::min(shortest, length);
    }
  }
  return b;
}

bool within(double x, double low, double high) { return x >= low && x <= high; }

}  // namespace

CornerQuads corner_quads(const PolygonMesh& mesh, const TriangleSoup& reference, double quad_size) {
  const BoundaryPoints boundary = boundary_points(mesh);
  std::vector<std::size_t> on_boundary;
  for (std::size_t p = 0; p < mesh.points.size(); ++p)
    if (std::isfinite(boundary.shortest_boundary_edge[p])) on_boundary.push_back(p);
  // the window: half a quad (corner_window_quads), the requested size's or,
  // without one, the mesh's mean edge
  double edges = 0, total = 0;
  for (const std::vector<int>& face : mesh.faces)
    for (std::size_t k = 0; k < face.size(); ++k, ++edges)
      total += (mesh.points[static_cast<std::size_t>(face[(k + 1) % face.size()])] -
                mesh.points[static_cast<std::size_t>(face[k])]).norm();
  CornerQuads result;
  if (edges == 0 || !(total > 0)) return result;
  const double quad = quad_size > 0 ? quad_size : total / edges;
  for (const BoundaryCorner& corner : boundary_corners(reference, corner_window_quads * quad)) {
    const double angle = corner.angle_deg;
    CornerCount c;
    c.position = reference.points[static_cast<std::size_t>(corner.vertex)];
    c.angle_deg = angle;
    c.quads_wanted = corner_quads_wanted(angle);
    double nearest = std::numeric_limits<double>::infinity();
    int at = -1;
    for (std::size_t p : on_boundary) {
      const double d = (mesh.points[p] - c.position).norm();
      if (d < nearest) nearest = d, at = static_cast<int>(p);
    }
    if (at >= 0 && nearest <= corner_match_share * boundary.shortest_boundary_edge[static_cast<std::size_t>(at)])
      c.quads = boundary.faces[static_cast<std::size_t>(at)];
    const bool wrong = c.quads != c.quads_wanted;
    if (within(angle, convex_corner_low_deg, convex_corner_high_deg)) {
      ++result.convex;
      result.convex_wrong += wrong;
    } else if (within(angle, concave_corner_low_deg, concave_corner_high_deg)) {
      ++result.concave;
      result.concave_wrong += wrong;
    } else {
      ++result.other;
      result.other_wrong += wrong;
    }
    result.corners.push_back(c);
  }
  return result;
}

}  // namespace qm
