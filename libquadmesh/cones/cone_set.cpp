#include "libquadmesh/cones/cone_set.h"

#include "libquadmesh/core/error.h"

#include <Eigen/Geometry>

#include <cmath>
#include <string>

namespace qm {

namespace {
/// More quads than this at one vertex is no cone a quad mesher wants.
constexpr int max_cone_quads = 8;
}  // namespace

std::vector<int> quads_per_vertex(const SurfaceAdjacency& adjacency, const std::vector<Cone>& cones) {
  const std::size_t nV = adjacency.vertex_faces.size();
  std::vector<int> quads(nV, 4);
  std::vector<char> given(nV, 0);
  for (std::size_t v = 0; v < nV; ++v)
    if (adjacency.boundary_vertex[v]) quads[v] = 2;
  for (std::size_t k = 0; k < cones.size(); ++k) {
    const Cone& c = cones[k];
    const std::string where = "cone " + std::to_string(k) + " (vertex " + std::to_string(c.vertex) + ")";
    if (c.vertex < 0 || static_cast<std::size_t>(c.vertex) >= nV)
      throw Error(ErrorCode::bad_input, where + ": no such vertex (the surface has " + std::to_string(nV) + ")");
    if (given[static_cast<std::size_t>(c.vertex)]++)
      throw Error(ErrorCode::bad_input, where + ": the vertex already has a cone");
    if (c.quads < 1 || c.quads > max_cone_quads)
      throw Error(ErrorCode::bad_input, where + ": " + std::to_string(c.quads) + " quads (1 to " +
                                            std::to_string(max_cone_quads) + " allowed)");
    quads[static_cast<std::size_t>(c.vertex)] = c.quads;
  }
  return quads;
}

std::vector<double> target_curvature(const SurfaceAdjacency& adjacency, const std::vector<int>& quads) {
  std::vector<double> k(quads.size());
  for (std::size_t v = 0; v < quads.size(); ++v)
    k[v] = (adjacency.boundary_vertex[v] ? 2 - quads[v] : 4 - quads[v]) * quarter_turn;
  return k;
}

std::vector<double> vertex_curvature(const TriangleSoup& soup, const SurfaceAdjacency& adjacency) {
  const std::size_t nV = soup.points.size();
  std::vector<double> k(nV);
  for (std::size_t v = 0; v < nV; ++v) k[v] = adjacency.boundary_vertex[v] ? M_PI : 2 * M_PI;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int i = 0; i < 3; ++i)
      k[static_cast<std::size_t>(soup.triangles[f][static_cast<std::size_t>(i)])] -= corner_angle(soup, f, i);
  return k;
}

void require_gauss_bonnet(const SurfaceAdjacency& adjacency, const std::vector<int>& quads, int euler_characteristic) {
  int turns = 0;
  for (std::size_t v = 0; v < quads.size(); ++v) turns += (adjacency.boundary_vertex[v] ? 2 : 4) - quads[v];
  if (turns != 4 * euler_characteristic)
    throw Error(ErrorCode::bad_input,
                "the cones turn by " + std::to_string(turns) + " quarter turns in all where Gauss-Bonnet needs " +
                    std::to_string(4 * euler_characteristic) + " (4 chi, chi = " +
                    std::to_string(euler_characteristic) + ")");
}

}  // namespace qm
