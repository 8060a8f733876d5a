// Quad extraction: the integer grid of the parameterization pulled back to S
// (method.md section 9; seed paper "pull back the grid"; here robust), for maps
// whose charts differ across cuts by a quarter turn and an integer translation,
// z_g = i^r z_f + t (method.md section 11: quarter-turn cones; cf. QEx [Ebke et
// al. 2013]); a translation surface is the case r = 0 everywhere.
//
// Every unit cell [k, k+1] x [l, l+1] of the plane that the map covers once is one
// quad. Cells are found triangle by triangle: a "piece" is a triangle whose open
// image meets the open cell; pieces of two triangles sharing an edge belong to the
// same quad when the open edge crosses the open cell, mapped by the transition
// between the two charts (a quarter turn turns the cell too: r = 1 takes (k, l) to
// (-l-1, k) before the translation). The turns are not given: they are read from
// the map, the ratio of an edge's images in two charts being i^r up to round-off.
// A quad's corners are the cell's lattice points, counter-clockwise from (k, l) in
// its first piece's chart (corner c there is corner c + r of a piece turned by r),
// located in one of its pieces' closed triangles: at a triangle vertex, on an edge
// or inside, with a key that does not depend on the chart, so neighbouring quads
// share them. All predicates are exact: coordinates are fixed-point integers
// (2^-30 units of the lattice), each corner is its vertex's reference point turned
// exactly plus an integer translation, and orientations use 128-bit products;
// lattice points on vertices, edges, cuts and the boundary are therefore decided
// exactly. A cell is kept only if its pieces' image areas add up to 1 (it is
// complete); the others, and any triangle whose image is not positively oriented,
// are counted in the report.
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/quality/quad_quality.h"

#include <array>

namespace qm {

/// Where a quad vertex lies on S.
struct SurfaceLocation {
  enum class Kind { vertex, edge, face };
  Kind kind = Kind::face;
  int a = -1;     ///< vertex: the vertex; edge: its smaller end
  int b = -1;     ///< edge: its larger end
  int face = -1;  ///< a triangle holding the point
  std::array<double, 3> barycentric{};  ///< in `face`, by the soup's corner order
};

struct LatticeQuads {
  std::vector<Vec3> points;
  std::vector<std::array<int, 4>> quads;      ///< counter-clockwise (the image's orientation)
  std::vector<SurfaceLocation> locations;     ///< per point
};

struct ExtractionReport {
  std::size_t cells = 0;               ///< complete cells, i.e. quads
  std::size_t incomplete_cells = 0;    ///< covered area not 1: dropped
  std::size_t degenerate_cells = 0;    ///< two corners at one point, or a corner not found: dropped
  std::size_t bad_triangles = 0;       ///< image area <= 0 or too large (max_cells_per_triangle): not used
  /// corners whose chart differs from their vertex's reference chart by more than a
  /// quarter turn and an integer translation, and edges whose two charts do
  std::size_t seam_mismatches = 0;
  int first_problem_triangle = -1;     ///< a triangle at the first problem met (bad or in a dropped cell)
};

/// The quads as a PolygonMesh (for the quality module).
PolygonMesh polygon_mesh(const LatticeQuads& quads);

/// The corner points of quad k, in order.
std::array<Vec3, 4> quad_corners(const LatticeQuads& quads, std::size_t k);

/// The same with point v at p instead (a trial move of v).
std::array<Vec3, 4> quad_corners(const LatticeQuads& quads, std::size_t k, int v, const Vec3& p);

/// The points on the quads' own boundary (an edge of one quad only) that do not lie
/// on a boundary of S (`boundary_loop_of_point[v] < 0`): a boundary-aligned mesh has
/// none; one that has some leaves part of S uncovered or covers part twice, even
/// when its Euler characteristic and loop count come out as the input's.
std::vector<int> stray_boundary_points(const LatticeQuads& quads, const std::vector<int>& boundary_loop_of_point);

/// fixed-point units per lattice unit
constexpr std::int64_t lattice_scale = std::int64_t(1) << 30;

/// A triangle whose image's bounding box spans more lattice cells than this is
/// counted as bad (not used): no sound map has one, and enumerating it would take
/// the memory of the machine.
constexpr double max_cells_per_triangle = 65536;

/// The quads of the integer grid pulled back by `param` (method.md sections 9, 11).
/// Precondition: `param` is seamless: at every vertex and across every edge the
/// charts differ by i^r z + t (r quarter turns, t a Gaussian integer); a cone vertex
/// (the turns around it do not add up to 0) lies on a lattice point. The seams that
/// are not are counted in `report.seam_mismatches`. Quads are counter-clockwise in
/// the image.
LatticeQuads extract_lattice_quads(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                   const FaceMap& param, ExtractionReport& report);

}  // namespace qm
