// The raw input surface: points and triangles as read from a file, before any
// topological check. Everything the topology module inspects lives here, because a
// non-manifold or non-orientable input cannot be stored in a halfedge mesh.
#pragma once

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace qm {

using Vec3 = Eigen::Vector3d;
using Triangle = std::array<int, 3>;

/// One boundary-candidate edge of the triangulation that lies on a CAD curve.
struct CurveEdge {
  int a = -1, b = -1;  ///< soup point indices (unordered)
  int curve = -1;      ///< CAD curve tag (Gmsh entity of dimension 1)
};

/// A physical group of CAD curves (Gmsh physical group of dimension 1).
struct PhysicalCurveGroup {
  int tag = -1;
  std::string name;  ///< may be empty: the group is then known by its tag
  std::vector<int> curves;
};

/// A physical group of CAD surfaces (Gmsh physical group of dimension 2): the
/// element tags of its triangles, which are the soup's triangle labels.
struct PhysicalSurfaceGroup {
  int tag = -1;
  std::string name;  ///< may be empty: the group is then known by its tag
  std::vector<std::int64_t> elements;
};

/// What a CAD input tells about its boundary and its parts: for every mesh edge
/// on a CAD curve, the curve's tag, the physical groups of curves, and the
/// physical groups of surfaces (`quadmesh mesh --each-component` names its parts
/// after them). Empty for discrete inputs (OBJ, OFF, PLY, STL, MSH without
/// geometry).
struct CadCurves {
  std::vector<CurveEdge> edges;
  std::vector<PhysicalCurveGroup> groups;
  std::vector<PhysicalSurfaceGroup> surface_groups;
};

/// A triangle soup with the file's own numbering kept for messages.
///  - points[i]: coordinates; point_labels[i]: the id the file uses for it
///    (1-based line order in OBJ, 0-based in OFF/PLY, node tag in MSH);
///  - triangles[f]: indices into points, in the file's orientation;
///    triangle_labels[f]: the file's id for that element.
/// The label vectors are either empty (labels are then the indices) or sized
/// like points / triangles.
struct TriangleSoup {
  std::vector<Vec3> points;
  std::vector<Triangle> triangles;
  std::vector<std::int64_t> point_labels;
  std::vector<std::int64_t> triangle_labels;
  CadCurves cad;

  std::int64_t point_label(int i) const {
    return point_labels.empty() ? i : point_labels[static_cast<std::size_t>(i)];
  }
  std::int64_t triangle_label(int f) const {
    return triangle_labels.empty() ? f : triangle_labels[static_cast<std::size_t>(f)];
  }
};

/// "vertex 12 at (0.1, 2, 3)": how messages name a point of the soup.
std::string describe_vertex(const TriangleSoup& soup, int i);
/// "triangle 7 (vertices 1, 2, 3)": how messages name a triangle of the soup.
std::string describe_triangle(const TriangleSoup& soup, int f);

/// The angle between a and b (radians, in [0, pi]): atan2 of |a x b| and a . b,
/// which keeps full precision near 0 and pi, where acos does not.
double angle_between(const Vec3& a, const Vec3& b);

/// The angle of triangle f at its corner k (radians).
double corner_angle(const TriangleSoup& soup, std::size_t f, int k);

/// Mean edge length of a soup (each edge counted once per triangle side; 0 without
/// triangles).
double mean_edge_length(const TriangleSoup& soup);

}  // namespace qm
