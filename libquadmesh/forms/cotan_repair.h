// Curing negative cotangent weights (method.md section 6: negative weights cause
// folds with no zero). An interior edge whose two opposite angles sum past 180
// degrees is flipped where the surface is nearly flat across it, and split at its
// midpoint elsewhere; a boundary edge opposite an obtuse angle cannot be cured by a
// flip (on the double both opposite angles are the same angle) and is split.
#pragma once

#include "libquadmesh/core/mesh.h"

namespace qm {

struct CotanRepairOptions {
  double flat_dihedral_deg = 10.0;  ///< flip only when the faces bend less than this
  int max_rounds = 8;
};

struct CotanRepairReport {
  std::size_t negative_before = 0, negative_after = 0;  ///< edges with w < 0
  std::size_t flips = 0, interior_splits = 0, boundary_splits = 0;
};

/// Flips and splits in place; vertices are only added (indices of existing
/// vertices are kept), every new vertex lies on an old edge.
CotanRepairReport repair_cotan_weights(Mesh& mesh, const CotanRepairOptions& options = {});

}  // namespace qm
