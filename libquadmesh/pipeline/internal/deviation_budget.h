// Size adaptivity within a quad budget (extract/deviation_refinement.h): chords
// are split where the quads deviate from S by more than the tolerance, at most
// 10% above the target count. When that is not enough, coarser base lattices are
// tried and the best kept; whatever is left of the budget goes to the largest
// deviations, so the count stays near the target.
#pragma once

#include "libquadmesh/pipeline/acceptance_criteria.h"
#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/stages.h"
#include "libquadmesh/pipeline/mesh_quads.h"

#include <functional>

namespace qm {

/// A deviation more than this many times the tolerance is out of the reach of the
/// local remedies: two more halvings of the cells by the refinement, and corners
/// moved by the fitting, which move by about one quad edge.
inline constexpr double within_reach = 16.0;

/// The deviation tolerance of `options` for quads `r`: QuadMeshOptions::max_deviation,
/// _relative (of `diagonal`, the input's bounding box's), else half the size (of
/// the base lattice's).
double deviation_tolerance(const QuadMeshOptions& options, double diagonal, const QuadMeshResult& r);

/// Refines `best` (the chosen attempt) to the deviation tolerance of `options`
/// (QuadMeshOptions::max_deviation, _relative, else half the size), then tries
/// coarser base lattices (`rerun(density)`: the same attempt with density x the
/// target count) while they can buy more refinement; one replaces `best` only if
/// it deviates less and its worst quad stays as good (or at least at the
/// acceptance criteria's Jacobian floor). `best.quality` is stale afterwards.
/// `diagonal`: of the input's bounding box.
void refine_where_deviating(Candidate& best, const QuadMeshOptions& options, double diagonal, Stages& stages,
                            const std::function<Candidate(double density)>& rerun);

}  // namespace qm
