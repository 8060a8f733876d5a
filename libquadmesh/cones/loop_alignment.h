// Aligning the cross field with every boundary loop at once (method.md section 11:
// "fix it by the choice of cones, or by a trivial connection" [Crane, Desbrun,
// Schroeder 2010]).
//
// The cone metric's field, propagated from a reference loop, meets another loop B
// turned by some angle delta_B that no cone set chosen independently of it makes a
// multiple of pi/2. A rotation added to the connection across every inner edge,
//   x(f -> g) = c_B (phi_B(g) - phi_B(f)),
// with phi_B a function on the triangles that is 1 on the triangles with a side on
// B and 0 on those with a side on any other loop, turns the field at B by c_B and
// nowhere else on a boundary: around an inner vertex its sum is 0 (a closed
// cycle), and around a boundary vertex it runs from a triangle of one loop to
// another triangle of the same loop, where phi_B has one value. So every cone
// keeps its angle and every boundary vertex its turning. phi_B is harmonic on the
// graph of triangles (uniform weights) between those values, which spreads the
// rotation smoothly over the part between B and the other loops.
#pragma once

#include "libquadmesh/param/internal/surface_adjacency.h"

#include <Eigen/Core>

#include <map>
#include <vector>

namespace qm {

/// phi_B per triangle for every loop B != reference (rows: triangles; column k for
/// the k-th loop other than `reference`, in loop order). Throws qm::Error
/// (unsupported) naming the triangle when one triangle has sides on two loops.
Eigen::MatrixXd loop_potentials(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, int reference);

/// loop_potentials of one surface, each reference loop's computed at its first
/// call and kept: the cross fields of every cone set on the surface share them
/// (they do not depend on the cones; bunny-open: 0.23 s per cone set, the graph
/// Laplacian of its 69,000 triangles factored). Not to be used by two threads at
/// once.
class LoopPotentials {
 public:
  LoopPotentials(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) : soup_(soup), adjacency_(adjacency) {}
  LoopPotentials(const LoopPotentials&) = delete;
  LoopPotentials& operator=(const LoopPotentials&) = delete;
  /// loop_potentials(soup, adjacency, reference), the same bits.
  const Eigen::MatrixXd& operator()(int reference);
  /// The surface they are for.
  const TriangleSoup& soup() const { return soup_; }

 private:
  const TriangleSoup& soup_;
  const SurfaceAdjacency& adjacency_;
  std::map<int, Eigen::MatrixXd> kept_;
};

}  // namespace qm
