// How the pipeline ranks its candidate results (docs/style.md, "Policy apart from
// mechanism"): the attempts of one run (retry_policy.h) and the two triangulations
// of the long-edge split are compared here and nowhere else.
//
// A candidate is measured once (assess_candidate: one quad_quality); the ranking
// reads only that measurement, so it can be tested on made-up figures.
#pragma once

#include "libquadmesh/pipeline/acceptance_criteria.h"
#include "libquadmesh/pipeline/mesh_quads.h"

#include <cstddef>
#include <limits>

namespace qm {

/// Euler characteristic and boundary loop count, as the quality module counts them.
struct SurfaceTopology {
  int euler_characteristic = 0;
  int boundary_loops = 0;
  bool operator==(const SurfaceTopology& o) const {
    return euler_characteristic == o.euler_characteristic && boundary_loops == o.boundary_loops;
  }
  bool operator!=(const SurfaceTopology& o) const { return !(*this == o); }
};

/// The topology of a triangulated surface (the input the quads must match).
SurfaceTopology topology_of(const TriangleSoup& soup);

/// What the ranking reads of a result.
struct CandidateQuality {
  bool has_quads = false;
  SurfaceTopology topology;               ///< of the quads
  std::size_t inverted = 0;               ///< QuadQuality::inverted
  std::size_t flipped = 0;                ///< QuadQuality::flipped
  std::size_t folds_left = 0;             ///< ExtractionReport::bad_triangles (folds the untangling left)
  std::size_t dropped_cells = 0;          ///< ExtractionReport: incomplete + degenerate cells
  std::size_t stray_boundary_points = 0;  ///< QuadMeshResult::stray_boundary_points
  /// QuadQuality::min_sound_scaled_jacobian; 1 without quads.
  double min_sound_scaled_jacobian = 1.0;
  /// QuadQuality::angle_dev_mean (degrees); NaN without quads.
  double angle_dev_mean = std::numeric_limits<double>::quiet_NaN();
};

/// A result with its measurement (taken when the result is complete; a later
/// change of its quads, such as the refinement's, leaves `quality` stale).
struct Candidate {
  QuadMeshResult result;
  CandidateQuality quality;
};

/// Measures `result` (one quad_quality of its quads).
CandidateQuality assess_candidate(const QuadMeshResult& result);

/// What is wrong with a candidate, worst first, compared lexicographically (lower
/// is better): the topology is not the input's; inverted or flipped quads; dropped
/// cells and quad boundary points off S's boundary; acceptance criteria not met
/// (AcceptanceCriteria: the Jacobian floor, on the sound scaled Jacobian, and the
/// mean angle deviation); then the smallest sound scaled Jacobian, negated.
struct Shortcomings {
  int wrong_topology = 0;                ///< 0 or 1
  std::size_t inverted_or_flipped = 0;
  std::size_t dropped_or_stray = 0;
  int unmet_criteria = 0;                ///< 0, 1 or 2
  double negated_min_jacobian = -1.0;
  bool operator<(const Shortcomings& o) const;
  bool operator<=(const Shortcomings& o) const;
};

/// How many of the shape criteria the quads miss: the Jacobian floor (on the sound
/// scaled Jacobian) and the mean angle deviation (0, 1 or 2).
int shape_criteria_missed(const CandidateQuality& c, const AcceptanceCriteria& criteria);

Shortcomings shortcomings(const CandidateQuality& c, SurfaceTopology input, const AcceptanceCriteria& criteria);

/// Sound and shapely: nothing but the Jacobian's size left to improve (the first
/// four shortcomings are 0).
bool acceptable(const Shortcomings& s);

/// Broken: no quads, folds left, cells dropped, or not the input's topology.
bool broken(const CandidateQuality& c, SurfaceTopology input);

/// Faulty: broken, or quad boundary points off S's boundary (a hole's arc cut short).
bool faulty(const CandidateQuality& c, SurfaceTopology input);

/// Whether `challenger` replaces `best`: it has quads and fewer shortcomings.
bool replaces(const CandidateQuality& challenger, const CandidateQuality& best, SurfaceTopology input,
              const AcceptanceCriteria& criteria);

/// Whether `a` is kept over `b` when either would do (ties go to `a`).
bool at_least_as_good(const CandidateQuality& a, const CandidateQuality& b, SurfaceTopology input,
                      const AcceptanceCriteria& criteria);

}  // namespace qm
