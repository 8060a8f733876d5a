// Element shape by the Verdict library's definitions (Stimpson, Ernst, Knupp,
// Pebay, Thompson, "The Verdict Geometric Quality Library", SAND2007-1751), as
// VTK 9's vtkMeshQuality, ParaView and Cubit compute them (method.md section 10).
// A value that differs from theirs on the same element is a bug.
//
// Conventions: a quad is (x0, x1, x2, x3) in order round its boundary; its normal
// is that of its diagonals, (x2 - x0) x (x3 - x1), so a quad listed clockwise in
// a plane measures like the same quad listed counterclockwise (a quad turned over
// against its neighbours is quad_quality.h's normal consistency, not a Verdict
// figure). A quad whose last two points coincide is "collapsed" and measured as
// the triangle (x0, x1, x2), as Verdict does. Angles are in degrees. Where
// Verdict answers a degenerate element with its sentinels, so do these:
// kVerdictTiny (1e-30) and kVerdictHuge (1e30); results are clamped to
// [-kVerdictHuge, kVerdictHuge].
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <array>

namespace qm {

/// Verdict's VERDICT_DBL_MIN: lengths and areas below it count as zero.
inline constexpr double kVerdictTiny = 1e-30;
/// Verdict's VERDICT_DBL_MAX: the answer for an unbounded ratio.
inline constexpr double kVerdictHuge = 1e30;

using QuadPoints = std::array<Vec3, 4>;
using TrianglePoints = std::array<Vec3, 3>;

/// Every Verdict figure this project reports for one quad.
struct QuadVerdict {
  double scaled_jacobian = 1;  ///< min over corners of the corner Jacobian (against the
                               ///< diagonals' normal) over its two edge lengths; [-1, 1], 1 = rectangle
  double minimum_angle = 90;   ///< smallest corner angle, degrees (360 with a zero edge)
  double maximum_angle = 90;   ///< largest corner angle, degrees; 360 - it when a corner is re-entrant
  double warpage = 1;          ///< min(n0 . n2, n1 . n3)^3 of the unit corner normals: 1 planar, <= 0 folded
  double aspect_ratio = 1;     ///< max edge * perimeter / (2 (|e0 x e1| + |e2 x e3|)); 1 = square
  double skew = 0;             ///< |cos| of the angle between the principal axes; 0 = orthogonal
  double taper = 0;            ///< |x0 - x1 + x2 - x3| / the shorter principal axis; 0 = parallelogram
};

/// Every Verdict figure this project reports for one triangle.
struct TriangleVerdict {
  double scaled_jacobian = 1;  ///< 2/sqrt(3) |e0 x e1| / the largest product of two edge
                               ///< lengths; [0, 1] (no orientation in 3D), 1 = equilateral
  double minimum_angle = 60;   ///< degrees (0 with a zero edge)
  double maximum_angle = 60;   ///< degrees (0 with a zero edge)
  double aspect_ratio = 1;     ///< max edge * perimeter / (4 sqrt(3) area); 1 = equilateral
};

/// Verdict quad_scaled_jacobian: the signed corner areas (each corner's edge
/// cross product dotted with the unit diagonal normal) over the products of the
/// corner's edge lengths, smallest over the four corners; 0 with a zero edge.
double quad_scaled_jacobian(const QuadPoints& x);

/// Verdict quad_minimum_angle and quad_maximum_angle (see QuadVerdict).
double quad_minimum_angle(const QuadPoints& x);
double quad_maximum_angle(const QuadPoints& x);

/// Verdict quad_warpage (see QuadVerdict); kVerdictTiny when a corner normal vanishes.
double quad_warpage(const QuadPoints& x);

/// Verdict quad_aspect_ratio (see QuadVerdict); kVerdictHuge for a zero area.
double quad_aspect_ratio(const QuadPoints& x);

/// Verdict quad_skew (see QuadVerdict); 0 when a principal axis vanishes.
double quad_skew(const QuadPoints& x);

/// Verdict quad_taper (see QuadVerdict); kVerdictHuge when a principal axis vanishes.
double quad_taper(const QuadPoints& x);

/// All of the above for one quad.
QuadVerdict quad_verdict(const QuadPoints& x);

/// Verdict tri_scaled_jacobian, tri_minimum_angle, tri_maximum_angle and
/// tri_aspect_ratio (see TriangleVerdict).
double triangle_scaled_jacobian(const TrianglePoints& x);
double triangle_minimum_angle(const TrianglePoints& x);
double triangle_maximum_angle(const TrianglePoints& x);
double triangle_aspect_ratio(const TrianglePoints& x);

/// All of the above for one triangle.
TriangleVerdict triangle_verdict(const TrianglePoints& x);

}  // namespace qm
