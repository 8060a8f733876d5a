// The boundary-aligned cross field of a cone metric (method.md section 11): the
// frame that the seamless map sends to the axes of the plane.
//
// The field is parallel for the Levi-Civita connection of e^(2u) g: crossing the
// edge a->b from the triangle f that holds a->b into its twin g, a direction keeps
// its angle to the edge and turns further by the discrete *du,
//   w_ab (u_b - u_a)   (w_ab the cotan weight; cone_metric.h),
// whose sum around a vertex is (L u)_v = K_target - K: the holonomy around every
// vertex is its cone's, a multiple of pi/2 [Crane, Desbrun, Schroeder 2010].
// Angles are propagated along a breadth-first tree of the triangles from a
// boundary triangle, whose frame is put along its boundary edge; across the other
// edges the frames differ by whole quarter turns, which are the rotations of the
// map's transitions (seamless_map.h). On a surface with handles the field meets
// itself around each handle turned by some angle, and on a surface with several
// boundary loops it meets the other loops turned: trivial connections
// (handle_alignment.h, then loop_alignment.h) turn it back, keeping every cone.
#pragma once

#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace qm {

struct CrossField {
  /// per triangle, the frame's angle in the triangle's local frame (face_geometry.h)
  std::vector<double> angle;
  /// per triangle and side k (the edge from corner k to corner k + 1): the quarter
  /// turns q such that the twin triangle's chart is i^q times this one's (plus a
  /// translation); 0 across tree edges and boundary edges
  std::vector<std::array<int, 3>> quarter_turns;
  /// per triangle and side: the edge crosses the breadth-first tree
  std::vector<std::array<char, 3>> tree_side;
  /// per triangle and side on the boundary: 0 if the edge runs along the frame's
  /// first axis (the map's real axis), 1 along the second; -1 for inner sides
  std::vector<std::array<int, 3>> boundary_axis;
  /// the largest deviation (radians) from a whole quarter turn met across a
  /// non-tree edge or along a boundary edge: ~0 when the cones' holonomy is sound
  double max_misalignment = 0;
  /// the first boundary loop that the field could not align (-1: all aligned)
  int misaligned_loop = -1;
  /// per boundary loop, the rotation (radians, |.| <= pi/4) that the trivial
  /// connection of loop_alignment.h adds to align it; 0 for the reference loop
  std::vector<double> loop_rotation;
  /// per handle form of handle_alignment.h, the rotation (radians) it adds
  std::vector<double> handle_rotation;
  /// the largest deviation (radians) from a whole quarter turn across an inner
  /// edge the tree does not cross: ~0 when the field closes around every cone and
  /// handle
  double max_seam_misalignment = 0;
};

class ConeMetricSolver;

/// How the field meets each boundary loop, as a function of the cone set: the
/// field propagated from the reference loop arrives at loop B turned by
///   turn_B = remainder(offset_B - gradient_B . (K_target - K))
/// (radians, remainder to (-pi/4, pi/4]), linear in the cone metric's right side
/// because the turn across every edge is linear in u and u = L^-1 (K_target - K).
/// Moving a cone of curvature kappa from v to w changes the inner product by
/// kappa (gradient_B[w] - gradient_B[v]): cone placement tries thousands of moves
/// at the price of one solve per loop.
/// After the boundary loops' rows come, on a surface with handles, one row per
/// independent loop round a handle (the tree's loops that handle_alignment.h's
/// forms close, fewest crossings first), in the same form: the remainder of the
/// field's jump across the loop, which the handles' trivial connection turns back
/// and the seamless map can only take as shear (fertility: handles turned by up
/// to 69 degrees). Its offset is the jump with u = 0, its gradient -L^-1 c, c the
/// coefficients of u in the turns along the loop.
struct LoopTurns {
  int reference = -1;
  std::vector<double> offset;                 ///< per row (0 for the reference)
  std::vector<Eigen::VectorXd> gradient;      ///< per row, per vertex (empty for the reference)
  /// turn_B for the metric's right side `rhs` = K_target - K (per vertex).
  double turn(int loop, const Eigen::VectorXd& rhs) const;
  std::size_t rows() const { return offset.size(); }
  /// whether a row other than the reference's is there to steer
  bool steers() const { return rows() > (reference >= 0 ? 1u : 0u); }
};

/// Precondition: `solver` factored on this soup; the soup is connected.
LoopTurns loop_turns(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const ConeMetricSolver& solver,
                     bool with_handles = true);

class LoopPotentials;

/// Precondition: `u` from cone_metric on this soup; the soup is connected. With
/// `potentials` (on this soup), the loops' potentials are taken from there.
CrossField cone_cross_field(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                            LoopPotentials* potentials = nullptr);

/// The angle in (-pi/4, pi/4] that differs from `angle` by whole quarter turns.
double quarter_turn_remainder(double angle);

}  // namespace qm
