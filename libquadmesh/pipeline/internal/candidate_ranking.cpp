#include "libquadmesh/pipeline/internal/candidate_ranking.h"

#include "libquadmesh/quality/quad_quality.h"

#include <tuple>

namespace qm {

namespace {

SurfaceTopology topology_of(const QuadQuality& q) { return {q.euler_characteristic, q.boundary_loops}; }

auto key(const Shortcomings& s) {
  return std::make_tuple(s.wrong_topology, s.inverted_or_flipped, s.dropped_or_stray, s.unmet_criteria,
                         s.negated_min_jacobian);
}

}  // namespace

SurfaceTopology topology_of(const TriangleSoup& soup) {
  PolygonMesh mesh;
  mesh.points = soup.points;
  for (const Triangle& t : soup.triangles) mesh.faces.push_back({t[0], t[1], t[2]});
  return topology_of(quad_quality(mesh, nullptr));
}

CandidateQuality assess_candidate(const QuadMeshResult& result) {
  const QuadQuality q = quad_quality(polygon_mesh(result.quads), nullptr);
  CandidateQuality c;
  c.has_quads = !result.quads.quads.empty();
  c.topology = topology_of(q);
  c.inverted = q.inverted;
  c.flipped = q.flipped;
  c.folds_left = result.extraction.bad_triangles;
  c.dropped_cells = result.extraction.incomplete_cells + result.extraction.degenerate_cells;
  c.stray_boundary_points = result.stray_boundary_points;
  c.min_sound_scaled_jacobian = q.quads > 0 ? q.min_sound_scaled_jacobian : 1.0;
  c.angle_dev_mean = q.angle_dev_mean;
  return c;
}

bool Shortcomings::operator<(const Shortcomings& o) const { return key(*this) < key(o); }
bool Shortcomings::operator<=(const Shortcomings& o) const { return key(*this) <= key(o); }

int shape_criteria_missed(const CandidateQuality& c, const AcceptanceCriteria& criteria) {
  return (c.min_sound_scaled_jacobian < criteria.min_scaled_jacobian ? 1 : 0) +
         (c.angle_dev_mean > criteria.max_mean_angle_deviation_deg ? 1 : 0);
}

Shortcomings shortcomings(const CandidateQuality& c, SurfaceTopology input, const AcceptanceCriteria& criteria) {
  Shortcomings s;
  s.wrong_topology = c.topology == input ? 0 : 1;
  s.inverted_or_flipped = c.inverted + c.flipped;
  s.dropped_or_stray = c.dropped_cells + c.stray_boundary_points;
  s.unmet_criteria = shape_criteria_missed(c, criteria);
  s.negated_min_jacobian = -c.min_sound_scaled_jacobian;
  return s;
}

bool acceptable(const Shortcomings& s) {
  return s.wrong_topology == 0 && s.inverted_or_flipped == 0 && s.dropped_or_stray == 0 && s.unmet_criteria == 0;
}

bool broken(const CandidateQuality& c, SurfaceTopology input) {
  return !c.has_quads || c.folds_left + c.dropped_cells > 0 || c.topology != input;
}

bool faulty(const CandidateQuality& c, SurfaceTopology input) {
  return broken(c, input) || c.stray_boundary_points > 0;
}

bool replaces(const CandidateQuality& challenger, const CandidateQuality& best, SurfaceTopology input,
              const AcceptanceCriteria& criteria) {
  return challenger.has_quads && shortcomings(challenger, input, criteria) < shortcomings(best, input, criteria);
}

bool at_least_as_good(const CandidateQuality& a, const CandidateQuality& b, SurfaceTopology input,
                      const AcceptanceCriteria& criteria) {
  return shortcomings(a, input, criteria) <= shortcomings(b, input, criteria);
}

}  // namespace qm
