#include "libquadmesh/pipeline/mesh_quads.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/forms/coarsen.h"
#include "libquadmesh/forms/long_edges.h"
#include "libquadmesh/param/form_choice.h"
#include "libquadmesh/pipeline/internal/attempt.h"
#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/cone_route.h"
#include "libquadmesh/pipeline/internal/deviation_budget.h"
#include "libquadmesh/pipeline/internal/form_setup.h"
#include "libquadmesh/pipeline/internal/quad_improvement.h"
#include "libquadmesh/pipeline/internal/retry_policy.h"
#include "libquadmesh/pipeline/internal/stages.h"
#include "libquadmesh/quality/size_band.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace qm {

namespace {

/// The best candidate as the retry policy reads it.
CandidateStanding standing(const Candidate& c, SurfaceTopology input, const AcceptanceCriteria& criteria) {
  CandidateStanding s;
  s.broken = broken(c.quality, input);
  s.faulty = faulty(c.quality, input);
  s.acceptable = acceptable(shortcomings(c.quality, input, criteria));
  s.coefficients = c.result.coefficients;
  s.boundary_tips = c.result.boundary_tips;
  s.base_density = c.result.base_density;
  return s;
}

/// The retry policy's inputs: the chosen form, auto's without tips, and the basis
/// forms by uniformity (computed only when the policy asks).
RetryPolicy::Inputs retry_inputs(const FormSetup& setup, const QuadMeshOptions& options) {
  RetryPolicy::Inputs inputs;
  inputs.first.coefficients = setup.preamble.coefficients;
  inputs.first.boundary_tips = setup.preamble.boundary_tips;
  inputs.free_coefficients = setup.free_coefficients;
  inputs.automatic = options.coefficients.empty() && options.form < 0;
  inputs.basis_order = [&setup] {
    const int G = static_cast<int>(setup.basis.size());
    std::vector<std::pair<double, int>> by_uniformity;
    for (int k = 0; k < G; ++k)
      by_uniformity.push_back({uniformity_ratio(setup.soup, setup.basis, Eigen::VectorXd::Unit(G, k)), k});
    std::sort(by_uniformity.begin(), by_uniformity.end());
    std::vector<int> order;
    for (const auto& [ratio, k] : by_uniformity) order.push_back(k);
    return order;
  };
  return inputs;
}

/// One run of the whole pipeline on one triangulation of S.
QuadMeshResult mesh_quads_on(TriangleSoup soup, const QuadMeshOptions& options, const ProgressCallback& progress) {
  std::vector<std::pair<std::string, double>> timings;
  Stages stages(timings, progress);
  // (the chord splits and the remeshing keep it)
  const SurfaceTopology input = topology_of(soup);
  FormSetup setup = prepare_surface(std::move(soup), input, options, stages);
  // the forms first where the cone route does not come first, or where the options
  // name a form (checked against the surface before any work)
  const bool form_asked = !options.coefficients.empty() || options.form >= 0;
  if (form_asked || !cones_first(setup.soup, setup.preamble.size_requested, options))
    compute_forms(setup, options, stages);

  // auto on a surface with CAD corners: the cone route first (cone_route.h), the
  // forms only when its quads are not kept
  ConesFirst first = try_cones_first(setup, options, input, stages);
  // remeshed for the forms: the cones again on the surface the Abel quads will be on
  if (!first.kept && !setup.forms_computed && compute_forms(setup, options, stages))
    first = try_cones_first(setup, options, input, stages);
  const bool cones_tried_first = first.tried.has_value() || !first.failure.empty();
  Candidate best;
  ConeRouteOutcome cones;
  int form_attempts = 0, rounding_attempts = 0;
  if (first.kept) {
    best = std::move(*first.kept);
  } else {
    const int basis_count = static_cast<int>(setup.basis.size());
    choose_form(setup, options, stages);
    // attempts as the retry policy orders them, the best kept (candidate_ranking.h)
    RetryPolicy retries(retry_inputs(setup, options));
    best = mesh_attempt(setup, options, retries.first().request, stages);
    form_attempts = 1;
    while (const std::optional<AttemptPlan> plan = retries.next(standing(best, input, options.acceptance))) {
      const StageNote note = announce(*plan, basis_count);
      stages.next(note.key, note.message);
      ++(plan->reason == AttemptPlan::Reason::rounding ? rounding_attempts : form_attempts);
      Candidate challenger = mesh_attempt(setup, options, plan->request, stages);
      if (replaces(challenger.quality, best.quality, input, options.acceptance)) best = std::move(challenger);
    }
    cones = try_cones_if_off_band(setup, options, input, stages, best, std::move(first));
  }
  if (options.max_deviation >= 0 && best.quality.has_quads && best.result.singularities == "abel")
    refine_where_deviating(best, options, setup.diagonal, stages, [&](double density) {
      AttemptRequest coarser;
      coarser.coefficients = best.result.coefficients;
      coarser.boundary_tips = best.result.boundary_tips;
      coarser.density = density;
      return mesh_attempt(setup, options, coarser, stages);
    });
  keep_nearer_cones(best, cones, options, input, stages);
  split_abel_quads_above_band(best, options, input, stages);
  QuadMeshResult result = std::move(best.result);
  // the forms' figures, where they were computed after the cones' quads were made
  result.doubled_genus = setup.preamble.doubled_genus;
  result.residuals = setup.preamble.residuals;
  result.remeshed = setup.preamble.remeshed;
  result.input_hodge_star_squared = setup.preamble.input_hodge_star_squared;
  improve_quads(result, options, stages);
  prefer_field_cones(result, setup, options, input, stages);
  prefer_cones_to_written_abel(result, cones_tried_first || !cones.failure.empty(), setup, options, input, stages);
  stages.close();
  note_stray_boundary(result);
  if (!result.quads.quads.empty() && result.size_requested > 0)
    result.size_band_share = quad_size_band(polygon_mesh(result.quads), result.size_requested).share_in_band;
  result.abel_size_band_share = cones.abel_size_band_share;
  result.cone_route_failure = cones.failure;
  result.rounding_attempts = rounding_attempts;
  result.form_attempts = form_attempts;
  result.timings = std::move(timings);
  return result;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

/// The working triangulation's edge length as a fraction of the quad size (the
/// automatic remeshing's bound too: form_setup.cpp)...
constexpr double working_edge_fraction = 1.0 / 3.0;
/// ...made when the input's mean edge is under this fraction of the quad size...
constexpr double coarsen_when_mean_edge_below = 0.25;
/// ...and kept when it has at most this fraction of the input's triangles.
constexpr double coarsen_kept_fraction = 0.5;

QuadMeshResult mesh_quads_maybe_split(TriangleSoup soup, const QuadMeshOptions& options,
                                      const ProgressCallback& progress) {
  if (!long_edge_split_allowed(options)) return mesh_quads_on(std::move(soup), options, progress);
  // Triangles wider than the quads carry one linear map across several quads:
  // where they cover enough of the area, split them (long_edges.h). The finer
  // triangulation changes where the zeros and folds fall, not always for the
  // better, so the input as it is is meshed too and the better result kept.
  const double size = requested_size(soup, options).edge;
  if (!long_edge_split_worth_it(long_edge_area_fraction(soup, size)))
    return mesh_quads_on(std::move(soup), options, progress);
  TriangleSoup split = soup;
  const std::size_t splits = split_long_edges(split, size);
  if (splits == 0) return mesh_quads_on(std::move(soup), options, progress);
  if (progress)
    progress(fmt::format("the input has triangles wider than the quads: {} edges split; meshing that and the input "
                         "as it is, to keep the better",
                         splits));
  const SurfaceTopology topology = topology_of(soup);
  auto start = std::chrono::steady_clock::now();
  QuadMeshResult fine;
  bool fine_ok = true;
  try {
    fine = mesh_quads_on(std::move(split), options, progress);
  } catch (const Error&) {
    fine_ok = false;
  }
  const double fine_seconds = seconds_since(start);
  // the cone route ran first there and met every criterion it is held to (sound,
  // the size band, every corner, the Hausdorff distance: cone_route.h
  // try_cones_first), so the Abel route was not run: nor is the input as it is
  if (fine_ok && fine.singularities == "cones" && std::isnan(fine.abel_size_band_share)) {
    fine.long_edges_split = splits;
    fine.long_edges_kept = true;
    return fine;
  }
  if (progress) progress("meshing the input as it is");
  start = std::chrono::steady_clock::now();
  // where the cone route failed on the finer triangulation, or gave quads kept only
  // for being nearer S than the Abel ones, it is not tried again on the coarser one
  // (each try is several seamless maps)
  const bool cones_failed =
      fine_ok && (!fine.cone_route_failure.empty() || std::isfinite(fine.abel_distance_relative));
  QuadMeshOptions as_is_options = options;
  if (cones_failed) as_is_options.singularities = Singularities::abel;
  QuadMeshResult as_is = mesh_quads_on(std::move(soup), as_is_options, progress);
  if (cones_failed) {
    as_is.cone_route_failure =
        !fine.cone_route_failure.empty()
            ? fine.cone_route_failure
            : "the cones' quads were farther from the surface than allowed and no better than the Abel quads of "
              "the input as it is";
    as_is.abel_size_band_share = as_is.size_band_share;
  }
  const double as_is_seconds = seconds_since(start);
  const bool keep_fine =
      fine_ok && at_least_as_good(assess_candidate(fine), assess_candidate(as_is), topology, options.acceptance);
  QuadMeshResult best = keep_fine ? std::move(fine) : std::move(as_is);
  best.long_edges_split = splits;
  best.long_edges_kept = keep_fine;
  // the run not kept, as one stage
  best.timings.insert(best.timings.begin(), {"other_triangulation", keep_fine ? as_is_seconds : fine_seconds});
  return best;
}

}  // namespace

QuadMeshResult mesh_quads(TriangleSoup soup, const QuadMeshOptions& options, const ProgressCallback& progress) {
  if (surface_adjacency(soup).boundary_loops.empty())
    throw Error(ErrorCode::unsupported,
                "quad meshing of closed surfaces is not implemented yet (their forms are: see `quadmesh forms`)");
  require_within_work_limit(soup, options);
  const double quad_edge = requested_size(soup, options).edge;
  const double working_edge = working_edge_fraction * quad_edge;
  if (!options.coarsen || !soup.cad.edges.empty() ||
      !(mean_edge_length(soup) < coarsen_when_mean_edge_below * quad_edge))
    return mesh_quads_maybe_split(std::move(soup), options, progress);
  const auto start = std::chrono::steady_clock::now();
  if (progress) progress(fmt::format("coarsening the input's {} triangles to edges of {:.4g}", soup.triangles.size(),
                                     working_edge));
  CoarsenOptions coarsening;
  coarsening.edge_length = working_edge;
  TriangleSoup working = coarsen(soup, coarsening);
  const std::size_t input_triangles = soup.triangles.size();
  if (static_cast<double>(working.triangles.size()) > coarsen_kept_fraction * static_cast<double>(input_triangles))
    return mesh_quads_maybe_split(std::move(soup), options, progress);
  const double seconds = seconds_since(start);
  if (progress)
    progress(fmt::format("meshing a working triangulation of {} triangles (from {})", working.triangles.size(),
                         input_triangles));
  soup = TriangleSoup{};  // the input's memory back before the forms
  QuadMeshResult result = mesh_quads_maybe_split(std::move(working), options, progress);
  result.coarsened_from = input_triangles;
  result.timings.insert(result.timings.begin(), {"coarsening", seconds});
  return result;
}

}  // namespace qm
