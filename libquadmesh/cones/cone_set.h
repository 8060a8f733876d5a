// Cone singularities of a quad mesh, prescribed per vertex (method.md section 11).
//
// A quad mesh's singular vertices are cones of angle k pi/2 of its flat metric:
// an interior vertex in n quads has cone angle n pi/2 (n = 4 is regular; 3 and 5
// are the valence-3/5 cones), a boundary vertex in q quads has image angle q pi/2
// (q = 2 is a straight boundary; q = 1 a convex CAD corner, q = 3 a concave one).
// In curvature terms (method.md section 11): kappa = 2 pi - n pi/2 inside,
// tau = pi - q pi/2 on the boundary, and Gauss-Bonnet demands
//   sum kappa + sum tau = 2 pi chi,   i.e.   sum (4 - n) + sum (2 - q) = 4 chi.
#pragma once

#include "libquadmesh/param/internal/surface_adjacency.h"

#include <cmath>
#include <vector>

namespace qm {

/// The angle of a quad's corner, the unit of every cone (radians).
constexpr double quarter_turn = M_PI / 2;

/// One prescribed cone: `quads` is the number of quads the vertex will be in.
struct Cone {
  int vertex = -1;
  int quads = 4;
};

/// Per vertex, the quads it will be in: 4 inside and 2 on the boundary unless a
/// cone says otherwise. Throws qm::Error (bad_input) naming the cone when its
/// vertex is out of range, listed twice, or its quad count is below 1 (or above 8).
std::vector<int> quads_per_vertex(const SurfaceAdjacency& adjacency, const std::vector<Cone>& cones);

/// The curvature the flat cone metric is to have at each vertex (radians):
/// kappa = 2 pi - n pi/2 inside, tau = pi - q pi/2 on the boundary.
std::vector<double> target_curvature(const SurfaceAdjacency& adjacency, const std::vector<int>& quads);

/// The surface's own discrete curvature at each vertex: the angle defect
/// 2 pi - (sum of angles) inside, the geodesic curvature pi - (sum of angles) on
/// the boundary. Sums to 2 pi chi (discrete Gauss-Bonnet).
std::vector<double> vertex_curvature(const TriangleSoup& soup, const SurfaceAdjacency& adjacency);

/// Throws qm::Error (bad_input) when sum (4 - n) + sum (2 - q) != 4 chi, saying
/// by how many quarter turns the cone set misses it.
void require_gauss_bonnet(const SurfaceAdjacency& adjacency, const std::vector<int>& quads, int euler_characteristic);

}  // namespace qm
