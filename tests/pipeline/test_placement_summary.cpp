// What the progress line says of each cone placement (pipeline/internal/
// placement_summary.h): every placement the route may try on one part, greedy or
// the cross field's, has its own line. No meshing.
#include "libquadmesh/pipeline/internal/cone_route.h"
#include "libquadmesh/pipeline/internal/placement_summary.h"

#include <doctest/doctest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

using namespace qm;

namespace {

/// Every placement the route may try on a part with handles and convex fillets, in
/// the order it adds them (first_acceptable_placement, then the cross field's).
std::vector<ConePlacementOptions> every_placement(bool fillets) {
  std::vector<ConePlacementOptions> out = cone_placements(InteriorCones::greedy, true);
  for (const auto& more : {fallback_placements(false), fallback_placements(true), capped_placements(),
                           fillet_placements(), squared_hole_placements(fillets)})
    out.insert(out.end(), more.begin(), more.end());
  out.push_back(cross_field_placement());
  return out;
}

}  // namespace

TEST_CASE("placement summaries: the plain placement names its distances and nothing else") {
  CHECK(placement_summary(ConePlacementOptions{}) ==
        "corners, then the interior, 2 quads from the boundary and 2.5 apart");
  CHECK(placement_summary(cross_field_placement()) == "corners, then the smoothest cross field's singularities");
  CHECK(placement_summary(nearer_placement()) ==
        "corners, then the interior, 1.2 quads from the boundary and 1.7 apart");
}

TEST_CASE("placement summaries: what sets a placement apart, in the order the route adds it") {
  ConePlacementOptions p;
  p.pair_band_goal = 0;
  p.steer_handles = false;
  CHECK(placement_summary(p) ==
        "corners, then the interior, 2 quads from the boundary and 2.5 apart; no cone pairs, handles not steered");
  ConePlacementOptions squared = squared_hole_placements(true).back();
  CHECK(std::isinf(squared.square_hole_max_length));
  CHECK(placement_summary(squared) ==
        "corners, then the interior, 2 quads from the boundary and 2.5 apart; a cone beside each fillet, every hole "
        "made a square however long, squares turned to the frame");
  CHECK(placement_summary(squared_hole_placements(false).front()) ==
        "corners, then the interior, 2 quads from the boundary and 2.5 apart; holes up to 16 quads round made "
        "squares");
  ConePlacementOptions again = capped_placements().front();
  again.avoided_points = {Vec3(0, 0, 0), Vec3(1, 0, 0)};
  CHECK(placement_summary(again) ==
        "corners, then the interior, 1.5 quads from the boundary and 2 apart; protrusions capped, away from 2 cones "
        "a map folded round");
}

TEST_CASE("placement summaries: no two placements the route may try share a progress line") {
  for (bool fillets : {false, true}) {
    const std::vector<ConePlacementOptions> placements = every_placement(fillets);
    REQUIRE(placements.size() == 23);  // 8 + 2 + 1 + 4 + 3 + 4 + 1
    std::map<std::string, std::size_t> first_with;
    for (std::size_t i = 0; i < placements.size(); ++i) {
      const std::string summary = placement_summary(placements[i]);
      const auto [at, inserted] = first_with.emplace(summary, i);
      INFO("placement ", i, " says what placement ", at->second, " says: ", summary);
      CHECK(inserted);
    }
  }
}
