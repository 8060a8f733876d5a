// Quad meshes on the grid of test::grid(n), for the tests of what moves quad
// corners (smoothing, fitting).
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/extract/lattice_quads.h"

#include <vector>

namespace qm::test {

/// The n x n quads on the points of `grid` (test::grid(n), possibly moved), with
/// default locations.
LatticeQuads grid_quads(const TriangleSoup& grid, int n);

/// Per point, 0 on the unit square's boundary (x or y equal to 0 or 1), else -1.
std::vector<int> unit_square_boundary(const LatticeQuads& quads);

/// The smallest scaled Jacobian of the quads (the quality module's).
double min_scaled_jacobian(const LatticeQuads& quads);

}  // namespace qm::test
