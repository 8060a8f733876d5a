// The shape and fidelity a quad mesh must have to be accepted (issue 4's
// criteria): one home for the thresholds that decide things. The pipeline ranks
// its candidate results by them (pipeline/internal/candidate_ranking.h) and keeps
// a coarser base lattice only if it stays above the Jacobian floor; the tests,
// `quadmesh mesh --report` (its "acceptance" object) and scripts/mesh-table and
// scripts/plate-sweep read them from here.
#pragma once

namespace qm {

struct AcceptanceCriteria {
  /// Element shape: every quad's scaled Jacobian at least this (dimensionless, in
  /// [-1, 1]; 1 a rectangle, <= 0 inverted). The pipeline holds the quads to the
  /// sound figure, Verdict's capped by the normal consistency
  /// (QuadQuality::min_sound_scaled_jacobian), which is never above Verdict's
  /// (QuadQuality::min_scaled_jacobian) that the report's criteria show.
  double min_scaled_jacobian = 0.3;
  /// Right angles: the mean over all quad corners of |angle - 90 degrees| at most
  /// this (degrees; QuadQuality::angle_dev_mean).
  double max_mean_angle_deviation_deg = 5.0;
  /// Geometric fidelity: the two-sided Hausdorff distance to the input at most this
  /// fraction of its bounding-box diagonal (dimensionless; QuadQuality::hausdorff_rel).
  /// Not a ranking criterion (the pipeline does not measure it per candidate; the
  /// size adaptivity, QuadMeshOptions::max_deviation, serves it).
  double max_hausdorff_relative = 0.01;
};

}  // namespace qm
