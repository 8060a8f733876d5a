// The quarter-turn cone route of `--singularities auto` (method.md section 11;
// libquadmesh/cones/): cones placed, the integer-grid map with quarter-turn
// transitions, its lattice cells as quads. Tried when the Abel result misses the
// size band; kept when it is sound and keeps more quads in the band.
#pragma once

#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cone_placement.h"
#include "libquadmesh/cones/loop_alignment.h"
#include "libquadmesh/pipeline/internal/candidate_ranking.h"
#include "libquadmesh/pipeline/internal/form_setup.h"
#include "libquadmesh/pipeline/internal/stages.h"
#include "libquadmesh/quality/size_band.h"

#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace qm {

/// Meshes `setup.soup` by the cone route at the requested quad edge times
/// `lattice_factor` (the quality still measured against the requested one): the result
/// (the preamble's fields, surface, quads, boundary loops of the points, cones,
/// extraction) measured. With `smooth_inverted`, quads left inverted or flipped by
/// the extraction have the worst quads smoothed first (quad_improvement.h
/// smooth_worst, what the written quads get), kept when fewer are left so.
/// Throws qm::Error when a stage cannot be done (a boundary loop the field cannot
/// meet, a failed solve), or when the cones placed are a set in `placed` (tried
/// before); else adds them there.
Candidate cone_attempt(const FormSetup& setup, const ConePlacementOptions& placement, Stages& stages,
                       std::vector<std::vector<Cone>>& placed, double lattice_factor, bool smooth_inverted);

/// One placement's attempt run beside others (cone_attempts_side_by_side): its
/// cones (none when the placement threw), its candidate or the qm::Error that
/// stopped it, any other exception (to rethrow), its progress messages and stage
/// timings.
struct ConeAttempt {
  std::optional<std::vector<Cone>> cones;
  std::optional<Candidate> candidate;
  std::string error;
  /// the placement was refused as an UncappedProtrusion (cone_placement.h)
  bool uncapped_protrusion = false;
  std::exception_ptr unexpected;
  std::vector<std::string> messages;
  std::vector<std::pair<std::string, double>> timings;  ///< its stages (Stages)
};

/// The capped placements (cone_placements) are mapped only when their metric
/// leaves at least this share of the area with quads within [0.5, 2] x the size
/// (the lowest of the placements kept on the shared meshes and examples: 85%)...
constexpr double capped_min_metric_band = 0.85;
/// ...and no quads above this many times the size: where the caps leave the quads
/// that large (bunny-open, its ears capped: 71-140 x near the base's ragged holes,
/// with 65-92% of the area in the band) the map folds (141 triangles), at seven
/// times the Abel run's cost. Pig's kept placement: 2.9 x.
constexpr double capped_max_metric_largest = 10.0;

/// What the cone route needs of `setup` (its soup, preamble, area and diagonal, not
/// the forms), with S's boundary spikes shorter than a quad clipped
/// (boundary_spikes.h) and its boundary vertices that the corners at the requested
/// size turn by more than 45 degrees given the inner edges to turn on split
/// (wide_corners.h split_turned_boundary): a scan's teeth; nothing on a CAD part.
FormSetup turned_boundary_setup(const FormSetup& setup);

/// How many placements the route tries at a time when the threads allow.
constexpr std::size_t placements_side_by_side = 2;

/// What every placement on one soup solves alike: its adjacency and its cone
/// metric's factor, with the metrics already solved (ConeMetricSolver remembers
/// them); and the loop potentials of the maps' cross fields. The map of a
/// placement whose corners need no split is made on them too (cone_map.h
/// SurfaceSolvers): its metric is one the placement solved, and the potentials
/// are factored once per surface, not once per cone set (bunny-open: 0.2 s and
/// 0.23 s of each of its cone sets' maps). Made by the first placement that needs
/// it, kept for the next ones of one search; one placement uses it at a time. The
/// solves give the same bits as a solver made afresh (the square flange's eleven
/// placements: the factor once).
struct PlacementSurface {
  explicit PlacementSurface(const TriangleSoup& soup);
  PlacementSurface(const PlacementSurface&) = delete;
  PlacementSurface& operator=(const PlacementSurface&) = delete;
  SurfaceAdjacency adjacency;
  ConeMetricSolver metrics;    ///< on the soup and `adjacency`
  LoopPotentials potentials;   ///< on the same (the maps' cross fields)
};

/// One PlacementSurface per attempt run side by side, made when first needed.
using PlacementSurfaces = std::vector<std::unique_ptr<PlacementSurface>>;

/// cone_attempt for each placement, side by side on the worker threads. With
/// `placed` (the cone sets of the batches before this one), an attempt whose cones
/// are one of them stops before its map, as one at a time would; a set the same as
/// an earlier attempt's in this batch is mapped, and left to the caller's check in
/// order. A result does not depend on the threads: each attempt is computed on its
/// own. With `surfaces`, the i-th placement uses (*surfaces)[i] (made if empty; the
/// vector grown to the placements' count). With `protrusion_ends_batch` (the caller
/// drops every attempt after one refused as an UncappedProtrusion), an attempt
/// after such a one stops at its next solve (its error Stopped's, stop_request.h):
/// bunny-open-large's placement without pairs mapped for 6 s beside the refused
/// first one.
std::vector<ConeAttempt> cone_attempts_side_by_side(const FormSetup& setup,
                                                    const std::vector<ConePlacementOptions>& placements,
                                                    double lattice_factor, bool smooth_inverted,
                                                    PlacementSurfaces* surfaces = nullptr,
                                                    const std::vector<std::vector<Cone>>* placed = nullptr,
                                                    bool protrusion_ends_batch = false);

/// The cone placements the route tries in turn, until one gives sound quads: the
/// defaults, then without the valence-3/5 pairs that even the sizes (more cones,
/// more places to fold), then interior cones farther from the boundary and from
/// each other (cramped cones fold the map between them and the boundary); every
/// one with its interior cones from `interior`.
/// On a surface with `handles`, the same again with steer_handles off, after them:
/// steering the handles' turns moves the cones off where the sizes want them, and
/// on a genus-1 scan with one hole every steered placement folds.
std::vector<ConePlacementOptions> cone_placements(InteriorCones interior = InteriorCones::greedy,
                                                  bool handles = false);

/// Tried after cone_placements() and fallback_placements() (greedy) when none was
/// acceptable: those of cone_placements() (without handles) that add pairs, the
/// first, wider and widest ones, preceded by a nearer one at the narrow distances
/// (1.5 quads from the boundary, 2 apart: bunny-open's base holes), all with
/// protrusion_caps (a protrusion's cap cones placed together and kept there: pig's
/// ears) and place_again_where_folded, refused before their maps when their
/// metric leaves the sizes off (capped_min_metric_band, capped_max_metric_largest).
/// Last, as their cones move what the others settle: on a scan they were first
/// for, two cuts lost their band.
std::vector<ConePlacementOptions> capped_placements();

/// Tried last (greedy) when no placement before was acceptable, the part has
/// convex fillet corners at the size (fillet_corners.h) and no placement was
/// refused as an UncappedProtrusion: those of cone_placements() (without handles)
/// that add pairs, with fillet_cones (a valence-3 cone beside each convex fillet,
/// kept there). A plate with four rounded corners 2.9 quads in radius, a slot and
/// two holes: the plain placements' quads reach 4.7 x the size at the fillets (88%
/// in the band, the Abel quads 89%, 3.4 x); with the fillets' valence-3 cones, 97%
/// and 2.6 x.
std::vector<ConePlacementOptions> fillet_placements();

/// Tried last of all (greedy) when no placement was acceptable and none was
/// refused as an UncappedProtrusion: the first placement of cone_placements() with
/// every hole up to square_hole_max_length quads round a square
/// (ConePlacementOptions::square_every_hole), and with fillet_cones where the part
/// has convex fillets (`fillets`); then the same with the squares turned to the
/// frame (ConePlacementOptions::squares_face_frame: where holes crowd, every
/// placement squares them as the first does, so this is the one new placement);
/// then both with every hole without corners a square, however long (shorter than
/// the longest loop): a plate whose large holes each want four valence-5 cones,
/// and its fillets four valence-3 ones, more than the bound allows (100 x 100, six
/// holes 10-32 quads round: 28 interior cones for 24 allowed; the best sound
/// placement 72-76% in the band), has them all on the holes.
std::vector<ConePlacementOptions> squared_hole_placements(bool fillets);

/// Tried, greedy, when the greedy placements (and the lattices centred or finer)
/// give nothing acceptable: the interior cones at the smoothest cross field's singularities
/// (InteriorCones::cross_field), moved off the boundary (field_boundary_distance).
/// CAD parts whose greedy cones leave the sizes off: a square flange with
/// rounded corners, a central bore and four bolt holes (greedy 78-82% in the size
/// band, the Abel quads 89%; the field's 24 cones 100%), a plate with two slots
/// (the largest quad 3.0 x; the field's 1.4 x) and a spanner (every greedy
/// placement's metric 10^5 x the size at the jaw; the field's 100%). On scans the
/// field's singularities are many and fold the maps, so it comes last. Where its
/// map folds round cones it winds a turn short, it is placed again away from them
/// (place_again_where_folded), as the capped placements are: a wheel with a bore
/// and three holes of radius 26 on a pitch circle of 44 (radius 80), greedy at
/// most 81% in the band, the field's first two maps folded, the third 93%.
ConePlacementOptions cross_field_placement();

/// A placement tried after cone_placements() (greedy; fallback_placements) when
/// some gave sound quads but none of those had size_band_goal of them in the size band: interior cones
/// 1.2 quads from the boundary and 1.7 apart. Round a hole little wider than a
/// quad, cones kept 2 quads off grade the quads down to a fraction of the size (a
/// strip 6.6 quads wide with a hole 2.8 across: 33% of the quads in the band, 100%
/// with these).
ConePlacementOptions nearer_placement();

/// A placement tried after cone_placements() (greedy; fallback_placements) when
/// none gave sound quads: the defaults with boundary_cones on (cone_placement.h: a
/// valence-5 cone on the boundary where the interior has no room for it). A
/// connecting rod with a hole 1.4 quads across in its shaft 3.4 quads wide: every
/// interior placement folds, this one gives 100% of the quads in the size band.
ConePlacementOptions boundary_cone_placement();

/// What the route tries after cone_placements() (greedy) when none gave sound quads
/// with size_band_goal of them in the size band: with `some_sound` quads (off the
/// band), nearer_placement(); with none, the interior cones 1.5 quads from the
/// boundary and 2 apart from the start (an L-bracket whose arms are 9 quads wide with
/// a hole 3.5 quads across in each: every other placement folds, this one keeps 90%
/// of the quads in the band), then boundary_cone_placement().
std::vector<ConePlacementOptions> fallback_placements(bool some_sound);

/// Sound: quads with the input's topology, no inverted or flipped quad, no dropped
/// cell, no stray boundary point.
bool sound(const CandidateQuality& c, SurfaceTopology input, const AcceptanceCriteria& criteria);

/// What makes a candidate not sound, in words ("3 inverted or flipped quads, 2
/// dropped cells"); empty when it is sound.
std::string unsound_reason(const CandidateQuality& c, SurfaceTopology input);

/// What the route weighs of a candidate against another: its quality, its quads'
/// size band, and its corners of S in other than one quad per 90 degrees.
struct RouteJudgement {
  CandidateQuality quality;
  SizeBand band;
  std::size_t corners_wrong = 0;
};

/// How many of the acceptance's criteria the judged quads miss, of: the size band
/// (in_size_band), every corner's quad count, and the shape criteria
/// (shape_criteria_missed: the Jacobian floor, the mean angle deviation).
int criteria_missed(const RouteJudgement& j, const AcceptanceCriteria& criteria);

/// The band's share a cone candidate may give up against the Abel one when it
/// misses fewer criteria (cones_replace).
constexpr double max_share_given = 0.1;

/// Whether the cone candidate replaces the Abel one: sound, and more of its quads
/// in the size band (by more than a point), or fewer corners of S whose quad count
/// is not one per 90 degrees with size_band_goal of its quads in the band, or, with
/// no more such corners, the band met (in_size_band) where the Abel quads miss it
/// (a quad above size_ratio_limit), or fewer of the criteria missed
/// (criteria_missed), its band's share at most max_share_given below the Abel
/// one's and its largest quad no larger (a gusset whose 45-degree corners the Abel
/// quads split, one quad 6.8 x the size: the cones' corners right, 4.3 x).
bool cones_replace(const RouteJudgement& cones, const RouteJudgement& abel, SurfaceTopology input,
                   const AcceptanceCriteria& criteria);

/// A cone candidate with its quads' size band (measured once).
struct ConeCandidate {
  Candidate candidate;
  SizeBand band;
  /// two-sided Hausdorff distance of its quads from S / the diagonal, as judged
  /// (NaN until measured; measured when sound)
  double distance = std::nan("");
};

/// Singularities::automatic: when `best` (the Abel result) has fewer than
/// size_band_goal of its quads in the size band or a quad above size_ratio_limit
/// x the size, or none, or a CAD corner with
/// another quad count than one per 90 degrees, meshes by the cone route
/// and keeps what cones_replace says, if its quads are also within the acceptance's
/// Hausdorff distance of S (the cone route has no size adaptivity yet); records both
/// shares and, when the Abel result stays, why (for QuadMeshResult::abel_size_band_share
/// and cone_route_failure, set on the final result). Nothing for abel.
/// Singularities::automatic on a surface with corners at the quad size
/// (cone_placement.h corner_cones): the Abel quads split every right corner in two, so the cone
/// route runs first; its candidate is `kept` (the Abel route skipped) when it is
/// sound, has size_band_goal of its quads in the band, every corner right and
/// lies within the Hausdorff criterion, else it is `tried` (for
/// try_cones_if_off_band to weigh against the Abel quads), or `failure` says why
/// there is none.
struct ConesFirst {
  std::optional<Candidate> kept;
  std::optional<ConeCandidate> tried;
  std::string failure;
};
bool cones_first(const TriangleSoup& soup, double size, const QuadMeshOptions& options);
ConesFirst try_cones_first(const FormSetup& setup, const QuadMeshOptions& options, SurfaceTopology input,
                           Stages& stages);

struct ConeRouteOutcome {
  double abel_size_band_share = std::numeric_limits<double>::quiet_NaN();  ///< NaN: not measured
  std::string failure;  ///< why the cone route was tried and not kept (empty otherwise)
  /// Cones that replace the Abel quads but for their distance from S: weighed by
  /// keep_nearer_cones against the Abel quads as they will be written.
  std::optional<ConeCandidate> too_far;
};
/// `first`: what try_cones_first found (its candidate is reused, not recomputed).
ConeRouteOutcome try_cones_if_off_band(const FormSetup& setup, const QuadMeshOptions& options, SurfaceTopology input,
                                       Stages& stages, Candidate& best, ConesFirst first = {});

/// When the cones' quads were better than the Abel ones but for their distance from
/// S (outcome.too_far), they replace `best` (the Abel result, refined where it
/// deviates, improved as it will be written) if the Abel quads lie farther still
/// from S and are shaped no better (candidate_ranking.h at_least_as_good): the cones
/// then win on every figure and miss the distance criterion, which the warning
/// about the distance says. Sets QuadMeshResult::abel_distance_relative whenever
/// it measures the Abel quads.
void keep_nearer_cones(Candidate& best, ConeRouteOutcome& outcome, const QuadMeshOptions& options,
                       SurfaceTopology input, Stages& stages);

/// Singularities::automatic, where the Abel quads are kept (`best`, sound) with
/// size_band_goal of them in the size band but some above size_ratio_limit x the
/// size: the chords through those are split (extract/size_refinement.h), kept when
/// the quads stay sound and come within the band (size_band_goal of them in it,
/// none above size_ratio_limit) with no more corners in another quad count. A
/// wheel with seven lightening holes at 1.2%: 97% in the band, one quad 3.6 x.
void split_abel_quads_above_band(Candidate& best, const QuadMeshOptions& options, SurfaceTopology input,
                                 Stages& stages);

/// Singularities::automatic with the greedy placement, where the cone quads kept
/// (`result`, improved as written) miss the acceptance's mean angle or its size
/// band (the route judged the band before the smoothing moved the corners): the
/// cross field's singularities (cross_field_placement) are mapped, judged and
/// improved, and replace `result` when they are acceptable to the route (sound, in
/// the size band, every corner in its quad count, within the acceptance's distance
/// of S), miss fewer of those two criteria as written (or only the angle, by less),
/// and keep their interior singular vertices within max(24, 1% of the quads). The
/// field's crosses turn as little as they can, so its cones leave the quads nearer
/// right angles round small holes (a link at 1.5%, two holes in its shank: 5.25 ->
/// 4.21 degrees) and sizes more even (a bent sheet at 1.5%: 89.9% -> 100% in the
/// band). Elsewhere the greedy cones stay (fewer singular vertices for the band).
void prefer_field_cones(QuadMeshResult& result, const FormSetup& setup, const QuadMeshOptions& options,
                        SurfaceTopology input, Stages& stages);

/// Singularities::automatic, where the Abel quads kept (`result`, improved as
/// written) miss the size band while the route judged them in it as mapped (the
/// smoothing moved their corners since) and so never tried the cones: the cone
/// route's candidate (cone_candidate) is mapped, judged and improved, and
/// replaces `result` when it is acceptable to the route (sound, in the size band,
/// every corner in its quad count, within the acceptance's distance of S), misses
/// fewer of the mean angle and the band as written, and keeps its interior
/// singular vertices within max(24, 1% of the quads). Not when the route was
/// tried before (`cones_tried`: first, or where the Abel quads missed as mapped).
/// A flanged pipe at 2%: its Abel quads 90.2% in the band as mapped, 89.8% as
/// written.
void prefer_cones_to_written_abel(QuadMeshResult& result, bool cones_tried, const FormSetup& setup,
                                  const QuadMeshOptions& options, SurfaceTopology input, Stages& stages);

}  // namespace qm
