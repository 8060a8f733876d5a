// The seamless map's stiffening (seamless_map.cpp) raises the fitting energy's
// weight on a few triangles at a time: the folded ones and those at their
// corners. Each triangle's term is, per axis of the map, the cotan form of its
// three corner values, positive semidefinite. So raising triangles' stiffness adds
// a positive semidefinite matrix on the wedges at their corners, the same on both
// axes, and the system's factorization can be updated by it (OrderedCholesky::
// update, C C^T) rather than computed again (bunny-open's system: 0.18 s a
// factorization). The update costs about its rank times the paths from C's rows
// to the elimination tree's root, so C comes from a Cholesky factorization of the
// change on its wedges, in the elimination order: rank at most the wedges less
// one per connected patch, about a quarter of the two columns per triangle and
// axis C would have a triangle at a time (a patch has about twice as many
// triangles as wedges).
#pragma once

#include "libquadmesh/cones/cut_graph.h"
#include "libquadmesh/core/triangle_soup.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <optional>
#include <vector>

namespace qm {

struct StiffnessChange {
  /// The change of the energy's matrix, as add_fitting_energy writes it (both
  /// triangles of the symmetric matrix, both axes).
  std::vector<Eigen::Triplet<double>> matrix;
  /// The wedges at the changed triangles' corners, ascending, and the change on
  /// them for one axis (the map's values 2 w and 2 w + 1 take the same).
  std::vector<int> wedges;
  Eigen::MatrixXd block;
};

/// The change of the fitting energy when triangle f's stiffness goes from
/// before[f] to after[f] (after[f] >= before[f]).
StiffnessChange stiffness_change(const TriangleSoup& soup, const CutGraph& cut, const std::vector<double>& before,
                                 const std::vector<double>& after);

/// C (variables x k) with C C^T the change on both axes: the block's Cholesky
/// factorization with its wedges taken in the order of `position` (of each
/// variable, in the system's elimination order), a pivot that vanishes (the
/// constants, one per patch) left out. Nothing where the block is not positive
/// semidefinite to round-off (a corner so degenerate that its cotangent is
/// clamped) or has more than `max_wedges` wedges (its dense factorization would
/// cost more than the system's).
std::optional<Eigen::SparseMatrix<double>> change_columns(const StiffnessChange& change,
                                                          const std::vector<int>& position, int variables,
                                                          std::size_t max_wedges);

}  // namespace qm
