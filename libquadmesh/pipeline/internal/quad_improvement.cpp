#include "libquadmesh/pipeline/internal/quad_improvement.h"

#include "libquadmesh/pipeline/internal/deviation_budget.h"
#include "libquadmesh/quality/size_band.h"

namespace qm {

namespace {

/// The smoothing moves a corner at most this fraction of the requested size, and
/// the angle smoothing keeps the quads within it of S when no tolerance is set.
constexpr double max_move_fraction = 0.5;

}  // namespace

QuadSmoothingReport smooth_worst(QuadMeshResult& result) {
  QuadSmoothingOptions smoothing;
  smoothing.max_move = max_move_fraction * result.size_requested;
  return smooth_worst_quads(result.surface, result.quads, result.boundary_loop_of_point, smoothing);
}

void improve_quads(QuadMeshResult& best, const QuadMeshOptions& options, Stages& stages) {
  if (best.improved) return;
  best.improved = true;
  if (options.smoothing && !best.quads.quads.empty()) {
    stages.next("smoothing", "smoothing the worst quads");
    const QuadSmoothingReport earlier = best.smoothing;
    best.smoothing = smooth_worst(best);
    if (earlier.moved_points > 0) {
      best.smoothing.moved_points += earlier.moved_points;
      best.smoothing.min_before = earlier.min_before;
    }
  }
  std::vector<char> fitted(best.quads.points.size(), 0);  // the corners the fitting moved stay
  // the cone route's quads are not refined: the route measured their two-sided
  // distance from S when it judged them (or not), and the smoothing keeps its
  // points on S, so within the tolerance there is nothing to fit
  const bool cones = best.singularities == "cones";
  const bool judged_within = cones && best.judged_deviation >= 0 && best.judged_deviation <= best.max_deviation;
  if (best.max_deviation > 0 && !best.quads.quads.empty() &&
      (cones || best.refinement.deviation_after <= within_reach * best.max_deviation)) {
    stages.next("fitting", "moving corners onto S where the quads cut across it");
    if (judged_within) {
      best.fitting.deviation_before = best.fitting.deviation_after = best.judged_deviation;
    } else if (!cones && best.smoothing.moved_points == 0 &&
               best.refinement.deviation_after <= best.max_deviation) {
      // the refinement measured these very quads (same samples, same tolerance)
      // within the tolerance: the fitting would measure that again and stop
      best.fitting.deviation_before = best.fitting.deviation_after = best.refinement.deviation_after;
    } else {
      const std::vector<Vec3> before_fitting = best.quads.points;
      QuadFittingOptions fitting;
      fitting.tolerance = best.max_deviation;
      best.fitting = fit_quads_to_surface(best.surface, best.quads, best.boundary_loop_of_point, fitting);
      for (std::size_t v = 0; v < fitted.size(); ++v) fitted[v] = best.quads.points[v] != before_fitting[v];
    }
  }
  if (options.smoothing && !best.quads.quads.empty()) {
    stages.next("angle_smoothing", "moving quad corners towards right angles");
    QuadAngleSmoothingOptions angles;
    angles.max_move = max_move_fraction * best.size_requested;
    angles.max_deviation = best.max_deviation > 0 ? best.max_deviation : max_move_fraction * best.size_requested;
    // the cones' quads kept within the largest size the acceptance allows (the
    // Abel quads, `abel` unchanged, are far larger where they are large)
    if (cones) angles.max_mean_edge = size_ratio_limit * best.size_requested;
    // more sweeps where four leave the quads off the acceptance's mean angle
    angles.target_mean_deg = options.acceptance.max_mean_angle_deviation_deg;
    best.angle_smoothing = smooth_quad_angles(best.surface, best.quads, best.boundary_loop_of_point, fitted, angles);
  }
}

}  // namespace qm
