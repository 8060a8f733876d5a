// The cone metric's solver keeps the metrics it solved for (cone_metric.h): a
// target asked for again gets, bit for bit, the metric a solve would give, and a
// placement on a solver shared with another places the cones it places alone.
#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cone_placement.h"
#include "libquadmesh/cones/cone_set.h"
#include "io/read_surface.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

#include <cstring>

using namespace qm;

namespace {

/// Whether a and b are the same vectors bit for bit.
bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * static_cast<std::size_t>(a.size())) == 0;
}

bool same_cones(const std::vector<Cone>& a, const std::vector<Cone>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                    [](const Cone& x, const Cone& y) { return x.vertex == y.vertex && x.quads == y.quads; });
}

}  // namespace

TEST_CASE("a cone metric asked for again is the one solved, bit for bit; another target gets its own") {
  io::ReadOptions read;
  read.quad_size = 1.75;
  const TriangleSoup soup = io::read_surface(test::example("plate-two-holes.geo"), read).soup;
  const SurfaceAdjacency adjacency = surface_adjacency(soup);
  const std::vector<double> curvature = vertex_curvature(soup, adjacency);
  const std::vector<Cone> cones = place_cones(soup, adjacency, 1.75);
  REQUIRE(cones.size() > 8);
  // the last cone (an interior one: the corners come first) one vertex over
  REQUIRE(!adjacency.boundary_vertex[static_cast<std::size_t>(cones.back().vertex)]);
  std::vector<Cone> moved = cones;
  moved.back().vertex = vertex_ring(soup, adjacency, cones.back().vertex).neighbours.front();
  REQUIRE(!adjacency.boundary_vertex[static_cast<std::size_t>(moved.back().vertex)]);
  const std::vector<double> first = target_curvature(adjacency, quads_per_vertex(adjacency, cones));
  const std::vector<double> second = target_curvature(adjacency, quads_per_vertex(adjacency, moved));

  const ConeMetricSolver kept(soup, adjacency);
  const Eigen::VectorXd u1 = kept.solve(first, curvature);
  const Eigen::VectorXd u2 = kept.solve(second, curvature);
  CHECK(!same_bits(u1, u2));
  CHECK((u1 - u2).cwiseAbs().maxCoeff() > 1e-3);  // a cone moved changes the metric
  // asked again, in another order: what fresh solvers give
  CHECK(same_bits(kept.solve(second, curvature), ConeMetricSolver(soup, adjacency).solve(second, curvature)));
  CHECK(same_bits(kept.solve(first, curvature), ConeMetricSolver(soup, adjacency).solve(first, curvature)));
  CHECK(same_bits(kept.solve(first, curvature), u1));

  // a placement on the solver the first placement used, made again: the same cones
  CHECK(same_cones(place_cones(kept, 1.75), cones));
  CHECK(same_cones(place_cones(kept, 1.75), cones));
}
