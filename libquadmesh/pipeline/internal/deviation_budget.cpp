#include "libquadmesh/pipeline/internal/deviation_budget.h"

#include "libquadmesh/quality/quad_quality.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace qm {

namespace {

/// Without a tolerance, the quads may deviate by this fraction of their size.
constexpr double default_tolerance_fraction = 0.5;
/// The refinement's quad count stays within [min, max] x the target count.
constexpr double min_quads_factor = 0.95;
constexpr double max_quads_factor = 1.1;
/// Coarser base lattices tried (quad count as a fraction of the target): 55-75% of
/// the quads buy about two more halvings of the cells where the quads deviate, a
/// quarter of the deviation each.
constexpr double coarser_densities[] = {0.75, 0.55};
/// A refinement whose largest deviation after is above this fraction of the one
/// before (it removed less than 5%) will not do better with more budget.
constexpr double min_refinement_gain = 0.95;

/// The smallest sound_scaled_jacobian of the quads (quad_quality.h: Verdict's
/// scaled Jacobian, capped by the normal consistency). 1 without quads.
double min_scaled_jacobian(const LatticeQuads& quads) {
  const std::vector<double> j = sound_scaled_jacobians(polygon_mesh(quads));
  return j.empty() ? 1.0 : *std::min_element(j.begin(), j.end());
}

}  // namespace

double deviation_tolerance(const QuadMeshOptions& options, double diagonal, const QuadMeshResult& r) {
  return options.max_deviation_relative > 0 ? options.max_deviation_relative * diagonal
         : options.max_deviation > 0        ? options.max_deviation
                                            : default_tolerance_fraction * r.size * std::sqrt(r.base_density);
}

void refine_where_deviating(Candidate& best_candidate, const QuadMeshOptions& options, double diagonal,
                            Stages& stages, const std::function<Candidate(double density)>& rerun) {
  QuadMeshResult& best = best_candidate.result;
  const double tolerance = deviation_tolerance(options, diagonal, best);
  auto refine = [&](QuadMeshResult& a) {
    DeviationRefinementOptions refinement;
    refinement.tolerance = tolerance;
    refinement.max_quads = static_cast<std::size_t>(max_quads_factor * best.expected_quads);
    refinement.min_quads = static_cast<std::size_t>(min_quads_factor * best.expected_quads);
    a.max_deviation = tolerance;
    a.refinement = refine_to_deviation(a.surface, surface_adjacency(a.surface), a.quads, a.boundary_loop_of_point,
                                       refinement);
  };
  stages.next("refinement", fmt::format("splitting chords where the quads are farther than {:.4g} from the surface",
                                         tolerance));
  refine(best);
  const SurfaceTopology topology = assess_candidate(best).topology;
  for (const double density : coarser_densities) {
    // more budget helps only where the deviation comes from the size: splitting
    // helped, the extraction was clean (no fold left, no cell dropped), and the
    // deviation is within reach (a protrusion where h decays deviates far more:
    // not worth the runs)
    const ExtractionReport& x = best.extraction;
    if (best.refinement.tolerance_met ||
        best.refinement.deviation_after > min_refinement_gain * best.refinement.deviation_before ||
        best.refinement.deviation_after > within_reach * tolerance ||
        x.bad_triangles + x.incomplete_cells + x.degenerate_cells + best.stray_boundary_points > 0)
      break;
    stages.next("refinement", fmt::format("largest deviation {:.4g}: a coarser base lattice ({:.0f}% of the quads) "
                                           "to pay for more refinement",
                                           best.refinement.deviation_after, 100 * density));
    Candidate a = rerun(density);
    if (!a.quality.has_quads || a.quality.topology != topology || a.result.stray_boundary_points > 0) continue;
    refine(a.result);
    // geometric fidelity is not bought with element shape: a coarser base is kept
    // only if its worst quad stays as good (or at least at the Jacobian floor)
    if (a.result.refinement.deviation_after < best.refinement.deviation_after &&
        min_scaled_jacobian(a.result.quads) >=
            std::min(min_scaled_jacobian(best.quads), options.acceptance.min_scaled_jacobian))
      best = std::move(a.result);
  }
}

}  // namespace qm
