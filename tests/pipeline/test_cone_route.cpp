// The cone route's attempts (pipeline/internal/cone_route.h) on a shared scan: a
// candidate is judged as its quads would be written.
#include "io/read_surface.h"
#include "libquadmesh/forms/long_edges.h"
#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/cone_route.h"
#include "libquadmesh/pipeline/internal/form_setup.h"
#include "libquadmesh/topology/topology_report.h"
#include "tests/support/test_meshes.h"

#include <doctest/doctest.h>

using namespace qm;

TEST_CASE("a cone candidate whose only fault is quads the smoothing turns back is judged after that smoothing" *
          doctest::test_suite("slow")) {
  // fertility at 1.5% of the diagonal, its long edges split as mesh_quads splits
  // them, the widest placement (cone_placements' last): the extraction leaves 4
  // inverted or flipped quads beside cones and no dropped cell or stray point; the
  // smoothing of the worst quads (what the written quads get) turns every one back
  TriangleSoup soup = analyze_topology(io::read_surface(test::shared_mesh("fertility-3holes.obj")).soup).soup;
  QuadMeshOptions options;
  options.size_relative = 0.015;
  const double size = requested_size(soup, options).edge;
  REQUIRE(split_long_edges(soup, size) > 0);
  std::vector<std::pair<std::string, double>> timings;
  Stages stages(timings, {});
  const FormSetup setup = prepare_forms(std::move(soup), options, stages);
  const SurfaceTopology input = topology_of(setup.soup);
  const ConePlacementOptions widest = cone_placements().back();
  std::vector<std::vector<Cone>> placed;
  const Candidate raw = cone_attempt(setup, widest, stages, placed, 1.0, false);
  placed.clear();
  const Candidate smoothed = cone_attempt(setup, widest, stages, placed, 1.0, true);
  CHECK(raw.quality.inverted + raw.quality.flipped > 0);
  CHECK(raw.quality.dropped_cells == 0);
  CHECK(raw.result.stray_boundary_points == 0);
  CHECK(!sound(raw.quality, input, options.acceptance));
  CHECK(smoothed.quality.inverted + smoothed.quality.flipped == 0);
  CHECK(smoothed.result.smoothing.moved_points > 0);
  CHECK(sound(smoothed.quality, input, options.acceptance));
  // the same lattice: only interior regular points moved
  CHECK(smoothed.result.quads.quads == raw.result.quads.quads);
}
