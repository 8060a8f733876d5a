// The ranking of candidate results (pipeline/internal/candidate_ranking.h) on
// made-up measurements, and the measurement itself on small quad meshes.
#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/cone_route.h"

#include "libquadmesh/quality/quad_quality.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace qm;

namespace {

const SurfaceTopology annulus{0, 2};

/// A sound candidate of the annulus's topology whose worst quad is `jacobian` and
/// whose corners deviate `angles` degrees from right on average.
CandidateQuality sound(double jacobian = 0.8, double angles = 2.0) {
  CandidateQuality c;
  c.has_quads = true;
  c.topology = annulus;
  c.min_sound_scaled_jacobian = jacobian;
  c.angle_dev_mean = angles;
  return c;
}

}  // namespace

TEST_CASE("ranking: worst shortcoming first: topology, then inversions, then dropped cells, then criteria") {
  const AcceptanceCriteria criteria;
  CandidateQuality wrong_topology = sound(0.9);
  wrong_topology.topology = {-1, 2};
  CandidateQuality inverted = sound(0.9);
  inverted.inverted = 1;
  CandidateQuality dropped = sound(0.9);
  dropped.dropped_cells = 3;
  CandidateQuality strays = sound(0.9);
  strays.stray_boundary_points = 3;
  const CandidateQuality misshapen = sound(0.2);
  const CandidateQuality good = sound(0.5);
  const CandidateQuality better = sound(0.7);
  auto rank = [&](const CandidateQuality& c) { return shortcomings(c, annulus, criteria); };
  CHECK(rank(inverted) < rank(wrong_topology));
  CHECK(rank(dropped) < rank(inverted));
  CHECK_FALSE(rank(strays) < rank(dropped));  // dropped cells and stray points weigh alike
  CHECK_FALSE(rank(dropped) < rank(strays));
  CHECK(rank(misshapen) < rank(dropped));
  CHECK(rank(good) < rank(misshapen));
  CHECK(rank(better) < rank(good));
  CHECK(rank(better) <= rank(better));
}

TEST_CASE("ranking: the criteria come from AcceptanceCriteria, and each unmet one counts") {
  AcceptanceCriteria criteria;
  CHECK(shortcomings(sound(criteria.min_scaled_jacobian, criteria.max_mean_angle_deviation_deg), annulus, criteria)
            .unmet_criteria == 0);
  CHECK(shortcomings(sound(0.29, 2.0), annulus, criteria).unmet_criteria == 1);
  CHECK(shortcomings(sound(0.8, 5.1), annulus, criteria).unmet_criteria == 1);
  CHECK(shortcomings(sound(0.29, 5.1), annulus, criteria).unmet_criteria == 2);
  criteria.min_scaled_jacobian = 0.2;
  CHECK(shortcomings(sound(0.29, 2.0), annulus, criteria).unmet_criteria == 0);
  CHECK(acceptable(shortcomings(sound(0.29, 2.0), annulus, criteria)));
  CHECK_FALSE(acceptable(shortcomings(sound(0.19, 2.0), annulus, criteria)));
}

TEST_CASE("ranking: broken and faulty") {
  CHECK_FALSE(broken(sound(), annulus));
  CHECK_FALSE(faulty(sound(), annulus));
  CandidateQuality empty;
  CHECK(broken(empty, annulus));
  CandidateQuality folds = sound();
  folds.folds_left = 1;
  CHECK(broken(folds, annulus));
  CandidateQuality other = sound();
  other.topology = {1, 1};
  CHECK(broken(other, annulus));
  CandidateQuality strays = sound();
  strays.stray_boundary_points = 1;
  CHECK_FALSE(broken(strays, annulus));
  CHECK(faulty(strays, annulus));
}

TEST_CASE("ranking: a challenger replaces the best only with quads and strictly fewer shortcomings") {
  const AcceptanceCriteria criteria;
  CHECK(replaces(sound(0.7), sound(0.5), annulus, criteria));
  CHECK_FALSE(replaces(sound(0.5), sound(0.5), annulus, criteria));  // ties keep the earlier attempt
  CandidateQuality empty;  // no quads: never kept, whatever the figures say
  empty.topology = annulus;
  CHECK_FALSE(replaces(empty, sound(0.1), annulus, criteria));
  // the long-edge split: ties go to the split input
  CHECK(at_least_as_good(sound(0.5), sound(0.5), annulus, criteria));
  CHECK_FALSE(at_least_as_good(sound(0.4), sound(0.5), annulus, criteria));
}

TEST_CASE("ranking: the measurement of a result, once, and its sound Jacobian as quad_quality sees it") {
  // a 2 x 1 strip of quads, the second sheared
  QuadMeshResult r;
  r.quads.points = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2.6, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)};
  r.quads.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  r.quads.locations.resize(r.quads.points.size());
  r.extraction.incomplete_cells = 1;
  r.stray_boundary_points = 2;
  const CandidateQuality c = assess_candidate(r);
  CHECK(c.has_quads);
  CHECK((c.topology == SurfaceTopology{1, 1}));
  CHECK(c.dropped_cells == 1);
  CHECK(c.stray_boundary_points == 2);
  // independently: the smallest of sound_scaled_jacobians
  const std::vector<double> j = sound_scaled_jacobians(polygon_mesh(r.quads));
  REQUIRE(j.size() == 2);
  CHECK(c.min_sound_scaled_jacobian == std::min(j[0], j[1]));
  CHECK(c.min_sound_scaled_jacobian < 1.0);
  const QuadQuality q = quad_quality(polygon_mesh(r.quads), nullptr);
  CHECK(q.min_sound_scaled_jacobian <= q.min_scaled_jacobian);
  CHECK(q.min_sound_scaled_jacobian <= q.min_normal_consistency);
  CHECK(c.angle_dev_mean == q.angle_dev_mean);
  // without quads: the Jacobian counts as 1, the angles as not measured
  const CandidateQuality none = assess_candidate(QuadMeshResult{});
  CHECK_FALSE(none.has_quads);
  CHECK(none.min_sound_scaled_jacobian == 1.0);
  CHECK(std::isnan(none.angle_dev_mean));
}

TEST_CASE("singularities auto: the cone result replaces the Abel one only when sound and better in band or corners") {
  const AcceptanceCriteria criteria;
  const CandidateQuality cones = sound();
  auto judged = [](const CandidateQuality& q, double share, std::size_t corners_wrong = 0, double largest = 1.5) {
    return RouteJudgement{q, SizeBand{100, share, largest, 0.6}, corners_wrong};
  };
  auto with = [&](double share, std::size_t corners_wrong = 0, double largest = 1.5) {
    return judged(cones, share, corners_wrong, largest);
  };
  // more quads in the size band, by more than a point
  CHECK(cones_replace(with(0.95), with(0.80), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.805), with(0.80), annulus, criteria));
  // the corners right (one quad per 90 degrees) while the band keeps its goal
  CHECK(cones_replace(with(0.97), with(0.98, 4), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.97, 2), with(0.98, 2), annulus, criteria));
  // the band met where the Abel quads have one above 3 x the size, the corners no worse
  CHECK(cones_replace(with(0.95, 0, 2.4), with(0.96, 0, 3.7), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.95, 0, 3.1), with(0.96, 0, 3.7), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.95, 0, 2.4), with(0.96, 0, 2.9), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.95, 1, 2.4), with(0.96, 0, 3.7), annulus, criteria));
  // fewer criteria missed (the band both, the corners only the Abel quads'), the
  // share at most ten points lower and the largest quad no larger: a gusset
  CHECK(criteria_missed(with(0.75, 0, 4.3), criteria) == 1);
  CHECK(criteria_missed(with(0.81, 3, 6.8), criteria) == 2);
  CHECK(cones_replace(with(0.75, 0, 4.3), with(0.81, 3, 6.8), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.70, 0, 4.3), with(0.81, 3, 6.8), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.75, 0, 7.0), with(0.81, 3, 6.8), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.75, 1, 4.3), with(0.81, 3, 6.8), annulus, criteria));
  // the corners right, both short of the band's share: one criterion against two
  CHECK(cones_replace(with(size_band_goal - 0.05, 0), with(0.86, 4), annulus, criteria));
  // the Abel quads below the Jacobian floor or off right angles miss those too
  CandidateQuality skewed = sound();
  skewed.min_sound_scaled_jacobian = 0.2;
  skewed.angle_dev_mean = 6.0;
  CHECK(criteria_missed(judged(skewed, 0.95), criteria) == 2);
  CHECK(cones_replace(with(0.88, 0, 1.4), judged(skewed, 0.95), annulus, criteria));
  CHECK_FALSE(cones_replace(with(0.88, 0, 2.5), judged(skewed, 0.95), annulus, criteria));
  // never when unsound, however good the band
  CandidateQuality dropped = sound();
  dropped.dropped_cells = 1;
  CHECK_FALSE(cones_replace(judged(dropped, 1.0), with(0.5, 4), annulus, criteria));
  CandidateQuality inverted = sound();
  inverted.inverted = 1;
  CHECK_FALSE(cones_replace(judged(inverted, 1.0), with(0.5, 4), annulus, criteria));
  CandidateQuality torn = sound();
  torn.topology = {-1, 2};
  CHECK_FALSE(cones_replace(judged(torn, 1.0), with(0.5, 4), annulus, criteria));
}
