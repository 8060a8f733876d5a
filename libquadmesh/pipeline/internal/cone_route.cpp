#include "libquadmesh/pipeline/internal/cone_route.h"

#include "libquadmesh/cones/boundary_spikes.h"
#include "libquadmesh/cones/cone_map.h"
#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cone_placement.h"
#include "libquadmesh/cones/fillet_corners.h"
#include "libquadmesh/cones/wide_corners.h"
#include "libquadmesh/param/internal/surface_adjacency.h"
#include "libquadmesh/core/error.h"
#include "libquadmesh/core/parallel.h"
#include "libquadmesh/extract/deviation_refinement.h"
#include "libquadmesh/extract/size_refinement.h"
#include "libquadmesh/pipeline/internal/attempt.h"
#include "libquadmesh/pipeline/internal/deviation_budget.h"
#include "libquadmesh/pipeline/internal/placement_summary.h"
#include "libquadmesh/pipeline/internal/quad_improvement.h"
#include "libquadmesh/quality/hausdorff.h"
#include "libquadmesh/quality/quad_quality.h"
#include "libquadmesh/quality/quad_distance.h"
#include "libquadmesh/quality/size_band.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <atomic>
#include <limits>
#include <string>
#include <vector>

namespace qm {

std::vector<ConePlacementOptions> cone_placements(InteriorCones interior, bool handles) {
  ConePlacementOptions first;
  first.interior = interior;
  ConePlacementOptions no_pairs = first;
  no_pairs.pair_band_goal = 0;
  ConePlacementOptions wider = first;
  wider.boundary_distance = 2.5;
  wider.cone_spacing = 3.0;
  ConePlacementOptions widest = first;
  widest.boundary_distance = 3.0;
  widest.cone_spacing = 3.5;
  std::vector<ConePlacementOptions> out{first, no_pairs, wider, widest};
  if (handles)
    for (std::size_t i = 0, n = out.size(); i < n; ++i) {
      ConePlacementOptions unsteered = out[i];
      unsteered.steer_handles = false;
      out.push_back(unsteered);
    }
  return out;
}

ConePlacementOptions nearer_placement() {
  ConePlacementOptions nearer;
  nearer.boundary_distance = 1.2;
  nearer.cone_spacing = 1.7;
  nearer.narrow_boundary_distance = nearer.boundary_distance;
  nearer.narrow_cone_spacing = nearer.cone_spacing;
  return nearer;
}

ConePlacementOptions boundary_cone_placement() {
  ConePlacementOptions on_boundary;
  on_boundary.boundary_cones = true;
  return on_boundary;
}

namespace {

/// The placements of cone_placements() (without handles) that add pairs: those
/// the capped and the fillet placements vary (the caps are a step of the pairs).
std::vector<ConePlacementOptions> pairing_placements() {
  std::vector<ConePlacementOptions> out = cone_placements();
  const auto no_pairs = [](const ConePlacementOptions& p) { return !(p.pair_band_goal > 0); };
  out.erase(std::remove_if(out.begin(), out.end(), no_pairs), out.end());
  return out;
}

}  // namespace

std::vector<ConePlacementOptions> capped_placements() {
  std::vector<ConePlacementOptions> out = pairing_placements();
  ConePlacementOptions nearer = out.front();
  nearer.boundary_distance = nearer.narrow_boundary_distance;
  nearer.cone_spacing = nearer.narrow_cone_spacing;
  out.insert(out.begin(), nearer);
  for (ConePlacementOptions& capped : out) {
    capped.protrusion_caps = true;
    capped.min_metric_band = capped_min_metric_band;
    capped.max_metric_largest = capped_max_metric_largest;
    capped.place_again_where_folded = true;
  }
  return out;
}

std::vector<ConePlacementOptions> squared_hole_placements(bool fillets) {
  ConePlacementOptions squared = cone_placements().front();
  squared.square_every_hole = true;
  squared.fillet_cones = fillets;
  ConePlacementOptions facing_frame = squared;
  facing_frame.squares_face_frame = true;
  std::vector<ConePlacementOptions> out{squared, facing_frame};
  for (ConePlacementOptions every_length : {squared, facing_frame}) {
    every_length.square_hole_max_length = std::numeric_limits<double>::infinity();
    out.push_back(every_length);
  }
  return out;
}

std::vector<ConePlacementOptions> fillet_placements() {
  std::vector<ConePlacementOptions> out = pairing_placements();
  for (ConePlacementOptions& with_fillets : out) with_fillets.fillet_cones = true;
  return out;
}

ConePlacementOptions cross_field_placement() {
  ConePlacementOptions field;
  field.interior = InteriorCones::cross_field;
  field.place_again_where_folded = true;
  return field;
}

std::vector<ConePlacementOptions> fallback_placements(bool some_sound) {
  if (some_sound) return {nearer_placement()};
  ConePlacementOptions narrow;
  narrow.boundary_distance = narrow.narrow_boundary_distance;
  narrow.cone_spacing = narrow.narrow_cone_spacing;
  return {narrow, boundary_cone_placement()};
}

namespace {

/// Whether a surface of this topology has handles (genus > 0).
bool has_handles(SurfaceTopology t) { return 2 - t.euler_characteristic - t.boundary_loops > 0; }

/// The cones `placement` puts on setup.soup at the requested size times
/// `lattice_factor`, with `metrics` (on setup.soup).
std::vector<Cone> placed_cones(const FormSetup& setup, const ConePlacementOptions& placement, Stages& stages,
                               double lattice_factor, const ConeMetricSolver& metrics) {
  stages.next("cone_placement", fmt::format("placing quarter-turn cones ({})", placement_summary(placement)));
  return place_cones(metrics, setup.preamble.size_requested * lattice_factor, placement);
}

/// Whether `cones` is one of the sets in `placed`.
bool placed_before(const std::vector<Cone>& cones, const std::vector<std::vector<Cone>>& placed) {
  const auto same = [&](const std::vector<Cone>& other) {
    return std::equal(other.begin(), other.end(), cones.begin(), cones.end(),
                      [](const Cone& a, const Cone& b) { return a.vertex == b.vertex && a.quads == b.quads; });
  };
  return std::any_of(placed.begin(), placed.end(), same);
}

constexpr const char* placed_before_error = "the same cones as a placement tried before";

/// The quads of `cones` (cone_attempt after the placement); `misturned`, if
/// given, gets the interior cones a folded map winds round a turn short
/// (cone_winding.h). `stop`: the map's (cone_map.h). With `surface` (on
/// setup.soup), the map shares its solvers where no corner is split.
Candidate cone_quads(const FormSetup& setup, std::vector<Cone> cones, Stages& stages, double lattice_factor,
                     bool smooth_inverted, RoundingOrder order, std::vector<int>* misturned = nullptr,
                     const StopRequest& stop = {}, PlacementSurface* surface = nullptr) {
  QuadMeshResult r = setup.preamble;
  // the corners the cone metric would open to a fold are bisected first
  TriangleSoup split_soup = setup.soup;
  WideCornerSplits split = split_wide_corners(split_soup, cones);
  r.wide_corners_split = split.splits;
  const double size = setup.preamble.size_requested * lattice_factor;
  // on the surface as it is, the map is made on setup.soup itself, with the
  // solvers the placement factored
  const bool shared = surface && split.splits == 0;
  const TriangleSoup& soup = shared ? setup.soup : split_soup;
  const SurfaceAdjacency& adjacency = shared ? surface->adjacency : split.adjacency;
  std::optional<SurfaceSolvers> solvers;
  if (shared) solvers.emplace(SurfaceSolvers{surface->metrics, surface->potentials});
  r.cones = std::move(cones);
  int corners = 0;
  for (const Cone& c : r.cones) corners += adjacency.boundary_vertex[static_cast<std::size_t>(c.vertex)];
  stages.next("cone_map", fmt::format("the seamless map with {} corner and {} interior cones", corners,
                                      static_cast<int>(r.cones.size()) - corners));
  const ConeMap map = cone_map(soup, adjacency, r.cones, size, order, stop, solvers ? &*solvers : nullptr);
  if (map.report.lattice_shifts > 0)
    stages.announce(fmt::format("the map folded round a cone it winds round a turn short: quantized again from "
                                "other offsets of the lattice ({} tried), {} folded triangles left",
                                map.report.lattice_shifts, map.report.inverted_triangles));
  if (map.report.segments_held > 0)
    stages.announce(fmt::format("the map folded: mapped again with its {} boundary segment{} under a quad and a "
                                "half held to one quad, {} folded triangles left",
                                map.report.segments_held, map.report.segments_held == 1 ? "" : "s",
                                map.report.inverted_triangles));
  if (order == RoundingOrder::translations_first) r.rounding_order = "translations_first";
  r.cone_map = map.report;
  if (misturned) *misturned = map.misturned;
  stages.next("extraction", "extracting the quads across the rotated cuts");
  r.quads = extract_lattice_quads(soup, adjacency, map.map, r.extraction);
  compact(r.quads);
  r.boundary_loop_of_point = boundary_loop_of_points(soup, adjacency, period_loops(soup), r.quads);
  r.surface = soup;
  r.singularities = "cones";
  r.size = size;
  r.expected_quads = setup.area / (size * size);  // the lattice's cells are size x size in the cone metric
  note_stray_boundary(r);
  Candidate c;
  c.quality = assess_candidate(r);
  if (smooth_inverted && c.quality.inverted + c.quality.flipped > 0) {
    // the smoothing moves only regular interior points, each move kept only when it
    // raises its quads' worst corner: a corner turned over beside a cone is often
    // lifted (fertility's best placement: 4 such quads, none after it)
    QuadMeshResult smoothed = r;
    smoothed.smoothing = smooth_worst(smoothed);
    const CandidateQuality quality = assess_candidate(smoothed);
    if (quality.inverted + quality.flipped < c.quality.inverted + c.quality.flipped) {
      r = std::move(smoothed);
      c.quality = quality;
    }
  }
  c.result = std::move(r);
  return c;
}

/// The largest quad size (x the requested size) the acceptance allows (issue 18).
constexpr double max_size_ratio = size_ratio_limit;

SizeBand size_band(const QuadMeshResult& r) {
  if (r.quads.quads.empty() || !(r.size_requested > 0)) return {};
  return quad_size_band(polygon_mesh(r.quads), r.size_requested);
}

/// A placement is made again this many times at most, each time away from the
/// cones its last map folded round (misturned: cone_winding.h), and only when its
/// quads, folded, have size_band_goal of them in the size band and none above
/// max_size_ratio: what only the folds keep from being acceptable (a placement made
/// again moves a cone or two, not the sizes: each time costs a placement and a map).
constexpr int max_placements_elsewhere = 2;

/// The greedy placements' search ends after this many sound ones in the size band
/// with every corner right that are farther from S than the acceptance allows,
/// judged as written (the nearest kept): the route then goes on to the cross
/// field's singularities and the chords split where the quads deviate, rather than
/// map every other greedy placement. The greedy ones differ in their cones' spacing
/// and pairs, not in how the lattice meets the surface's bends at the quad size. A
/// hinge cut with a hole (its triangles split far finer than the quads): seven such
/// placements 1.00-1.15% of the diagonal from S, each a map of 3-5 s, before the
/// route kept the nearest, 91 s in all (two threads); 63 s with this, the same
/// quads. A generated plate (plate-sweep p3): after three such, the cross field's
/// cones meet every criterion (0.42% from S, 100% of the quads in the band) where
/// the ninth greedy placement did before (0.96%, 90%). None of the 52 regression
/// inputs changes.
constexpr int max_distance_misses = 3;

/// One placement's attempt reported on `stages`; with `placed`, cones placed before
/// are not mapped again (the caller's check refuses them). Where the map folds and
/// winds round some interior cones a turn short, a capped placement or the cross
/// field's (ConePlacementOptions::place_again_where_folded) is made again with
/// those cones' places avoided (ConePlacementOptions::avoided_points), and the
/// map with the fewest folds kept (bunny-open's capped cones 1.5
/// quads from the boundary: 7 folded triangles round one valence-5 cone; placed
/// again, 94% of the quads in the size band and nothing folded). With `stop`,
/// asked before the map and at its solves: the attempt ends with Stopped's error.
ConeAttempt run_attempt(const FormSetup& setup, const ConePlacementOptions& placement, Stages& stages,
                        double lattice_factor, bool smooth_inverted,
                        const std::vector<std::vector<Cone>>* placed = nullptr,
                        std::unique_ptr<PlacementSurface>* surface = nullptr, const StopRequest& stop = {}) {
  ConeAttempt attempt;
  try {
    // the metrics solved for are kept for the placement made again, which repeats
    // the first's steps up to where the cones avoided change them (and, with
    // `surface`, for the placements after this one)
    std::unique_ptr<PlacementSurface> own;
    if (!surface) surface = &own;
    if (!*surface) *surface = std::make_unique<PlacementSurface>(setup.soup);
    const ConeMetricSolver& metrics = (*surface)->metrics;
    attempt.cones = placed_cones(setup, placement, stages, lattice_factor, metrics);
    if (placed && placed_before(*attempt.cones, *placed)) return attempt;
    stop_if_requested(stop);
    std::vector<int> misturned;
    attempt.candidate = cone_quads(setup, *attempt.cones, stages, lattice_factor, smooth_inverted, placement.rounding,
                                   &misturned, stop, surface->get());
    ConePlacementOptions elsewhere = placement;
    for (int again = 0; placement.place_again_where_folded && again < max_placements_elsewhere &&
                        attempt.candidate->quality.folds_left > 0 && !misturned.empty() &&
                        in_size_band(size_band(attempt.candidate->result));
         ++again) {
      for (int c : misturned)
        if (static_cast<std::size_t>(c) < setup.soup.points.size())
          elsewhere.avoided_points.push_back(setup.soup.points[static_cast<std::size_t>(c)]);
      stages.announce(fmt::format("the map folds round {} cone{} it winds round a turn short: the cones placed again "
                                  "away from there",
                                  misturned.size(), misturned.size() == 1 ? "" : "s"));
      try {
        std::vector<Cone> cones = placed_cones(setup, elsewhere, stages, lattice_factor, metrics);
        if (placed && placed_before(cones, *placed)) break;
        Candidate candidate =
            cone_quads(setup, cones, stages, lattice_factor, smooth_inverted, placement.rounding, &misturned, stop,
                       surface->get());
        if (candidate.quality.folds_left < attempt.candidate->quality.folds_left) {
          attempt.cones = std::move(cones);
          attempt.candidate = std::move(candidate);
        }
      } catch (const Stopped&) {
        throw;
      } catch (const Error&) {
        break;  // no placement there: the folded map stands
      }
    }
  } catch (const UncappedProtrusion& e) {
    attempt.error = e.what();
    attempt.uncapped_protrusion = true;
  } catch (const Error& e) {
    attempt.error = e.what();
  } catch (...) {
    attempt.unexpected = std::current_exception();  // rethrown by the caller, in order
  }
  return attempt;
}

}  // namespace

Candidate cone_attempt(const FormSetup& setup, const ConePlacementOptions& placement, Stages& stages,
                       std::vector<std::vector<Cone>>& placed, double lattice_factor, bool smooth_inverted) {
  const SurfaceAdjacency adjacency = surface_adjacency(setup.soup);
  std::vector<Cone> cones =
      placed_cones(setup, placement, stages, lattice_factor, ConeMetricSolver(setup.soup, adjacency));
  if (placed_before(cones, placed)) throw Error(ErrorCode::unsupported, placed_before_error);
  placed.push_back(cones);
  return cone_quads(setup, std::move(cones), stages, lattice_factor, smooth_inverted, placement.rounding);
}

FormSetup turned_boundary_setup(const FormSetup& setup) {
  FormSetup out;
  out.soup = setup.soup;
  out.preamble = setup.preamble;
  out.area = setup.area;
  out.diagonal = setup.diagonal;
  clip_boundary_spikes(out.soup, setup.preamble.size_requested);
  split_turned_boundary(out.soup, corner_cones(out.soup, setup.preamble.size_requested));
  return out;
}

PlacementSurface::PlacementSurface(const TriangleSoup& soup)
    : adjacency(surface_adjacency(soup)), metrics(soup, adjacency), potentials(soup, adjacency) {}

std::vector<ConeAttempt> cone_attempts_side_by_side(const FormSetup& setup,
                                                    const std::vector<ConePlacementOptions>& placements,
                                                    double lattice_factor, bool smooth_inverted,
                                                    PlacementSurfaces* surfaces,
                                                    const std::vector<std::vector<Cone>>* placed,
                                                    bool protrusion_ends_batch) {
  std::vector<ConeAttempt> out(placements.size());
  if (surfaces && surfaces->size() < placements.size()) surfaces->resize(placements.size());
  // the first attempt refused as an UncappedProtrusion, when that ends the batch
  std::atomic<std::size_t> ended_at{placements.size()};
  parallel_for_index(placements.size(), [&](std::size_t i) {
    std::vector<std::string> messages;
    std::vector<std::pair<std::string, double>> timings;
    const ProgressCallback record = [&messages](const std::string& message) { messages.push_back(message); };
    Stages stages(timings, record);
    StopRequest stop;
    if (protrusion_ends_batch) stop = [&ended_at, i] { return ended_at.load() < i; };
    out[i] = run_attempt(setup, placements[i], stages, lattice_factor, smooth_inverted, placed,
                         surfaces ? &(*surfaces)[i] : nullptr, stop);
    if (protrusion_ends_batch && out[i].uncapped_protrusion) {
      std::size_t ended = ended_at.load();
      while (i < ended && !ended_at.compare_exchange_weak(ended, i)) {
      }
    }
    stages.close();
    out[i].messages = std::move(messages);
    out[i].timings = std::move(timings);
  });
  return out;
}

bool sound(const CandidateQuality& c, SurfaceTopology input, const AcceptanceCriteria& criteria) {
  const Shortcomings s = shortcomings(c, input, criteria);
  return c.has_quads && s.wrong_topology == 0 && s.inverted_or_flipped == 0 && s.dropped_or_stray == 0;
}

std::string unsound_reason(const CandidateQuality& c, SurfaceTopology input) {
  if (!c.has_quads) return "no quads";
  std::vector<std::string> parts;
  if (c.topology.euler_characteristic != input.euler_characteristic || c.topology.boundary_loops != input.boundary_loops)
    parts.push_back(fmt::format("chi {} and {} boundary loops against {} and {}", c.topology.euler_characteristic,
                                c.topology.boundary_loops, input.euler_characteristic, input.boundary_loops));
  if (c.inverted + c.flipped > 0) parts.push_back(fmt::format("{} inverted or flipped quads", c.inverted + c.flipped));
  if (c.folds_left > 0) parts.push_back(fmt::format("{} folded triangles", c.folds_left));
  if (c.dropped_cells > 0) parts.push_back(fmt::format("{} dropped cells", c.dropped_cells));
  if (c.stray_boundary_points > 0)
    parts.push_back(fmt::format("{} quad points off the boundary", c.stray_boundary_points));
  return fmt::format("{}", fmt::join(parts, ", "));
}

int criteria_missed(const RouteJudgement& j, const AcceptanceCriteria& criteria) {
  return static_cast<int>(!in_size_band(j.band)) + static_cast<int>(j.corners_wrong > 0) +
         shape_criteria_missed(j.quality, criteria);
}

bool cones_replace(const RouteJudgement& cones, const RouteJudgement& abel, SurfaceTopology input,
                   const AcceptanceCriteria& criteria) {
  if (!sound(cones.quality, input, criteria)) return false;
  const double cones_share = cones.band.share_in_band, abel_share = abel.band.share_in_band;
  // more quads in the band (by more than a point), or the corners right while the
  // band keeps its goal, or the band met where the Abel quads have one too large
  if (cones_share > abel_share + 0.01) return true;
  if (cones.corners_wrong < abel.corners_wrong && cones_share >= size_band_goal) return true;
  if (cones.corners_wrong <= abel.corners_wrong && in_size_band(cones.band) && !in_size_band(abel.band)) return true;
  // fewer criteria missed, with the band's share at most max_share_given lower
  // and the largest quad no larger
  return criteria_missed(cones, criteria) < criteria_missed(abel, criteria) &&
         cones_share >= abel_share - max_share_given && cones.band.max_ratio <= abel.band.max_ratio;
}

namespace {

/// Corners of S at the requested size (cone_placement.h corner_cones) whose quad
/// point is in another number of quads than the corner asks for, or has no quad
/// point.
std::size_t corner_mismatches(const QuadMeshResult& r) {
  const TriangleSoup& soup = r.surface;
  std::vector<int> quads_at(r.quads.points.size(), 0);
  for (const auto& quad : r.quads.quads)
    for (int v : quad) ++quads_at[static_cast<std::size_t>(v)];
  std::vector<int> point_of(soup.points.size(), -1);
  for (std::size_t p = 0; p < r.quads.locations.size(); ++p)
    if (r.quads.locations[p].kind == SurfaceLocation::Kind::vertex)
      point_of[static_cast<std::size_t>(r.quads.locations[p].a)] = static_cast<int>(p);
  std::size_t mismatches = 0;
  for (const Cone& c : corner_cones(soup, r.size_requested)) {
    const int p = point_of[static_cast<std::size_t>(c.vertex)];
    mismatches += p < 0 || quads_at[static_cast<std::size_t>(p)] != c.quads;
  }
  return mismatches;
}

/// Two-sided Hausdorff distance of the quads from S, relative to S's
/// bounding-box diagonal, as the quality report measures it (quality/quad_distance.h).
double relative_hausdorff(const QuadMeshResult& r) {
  const double diagonal = bounding_box_diagonal(r.surface.points, r.surface.triangles);
  return quad_distance(polygon_mesh(r.quads), r.surface).distance.value() / diagonal;
}

}  // namespace

namespace {

/// The lattices tried, finer by these factors, when a sound result has quads
/// above max_size_ratio.
constexpr double finer_lattices[] = {0.95, 0.9};
constexpr int max_finer_attempts = 6;
constexpr double finer_lattice_below = 1.1;

/// The finer_lattices worth trying for quads of these `ratios` (quad size / the
/// requested size) whose size band is `band`: those under which its quads, each
/// scaled, would be within max_size_ratio and keep min(band's share,
/// size_band_goal) of them in the band, less centring_share_slack (the same test
/// a finer result must pass, on a prediction). Bunny-open's capped cones, their
/// largest quad 3.04 x with 82% in the band: on 0.95 x the quads below half the
/// size, a sixth of them, grow in number; none is tried (six placements, 1.7 s).
std::vector<double> finer_lattice_factors(const std::vector<double>& ratios, const SizeBand& band);

/// The lattice scales tried when a sound result has every quad within
/// max_size_ratio but fewer than size_band_goal of them in the band (a size asked
/// for, not a quad count), its sizes
/// off the band's middle (the quads round the small holes of a plate below half
/// the size while most are near it), nearest 1 first: those under which its
/// quads, each scaled, would have at least centring_share_goal of them in the
/// band and none above centred_max_ratio (the same cones mapped again on another
/// lattice give nearly, not exactly, the quads scaled), at most
/// max_centring_attempts of them.
constexpr double centring_lattices[] = {1.04, 0.96, 1.08, 0.92, 1.12, 0.88, 1.16, 1.2};
constexpr double centring_share_slack = 0.02;
constexpr double centring_share_goal = size_band_goal - centring_share_slack;
constexpr double centred_max_ratio = 0.95 * max_size_ratio;
constexpr int max_centring_attempts = 3;

/// The centring_lattices worth mapping for quads of these `ratios` (quad size /
/// the requested size), in order.
std::vector<double> centring_lattice_factors(const std::vector<double>& ratios) {
  std::vector<double> out;
  for (double factor : centring_lattices) {
    const SizeBand scaled = scaled_size_band(ratios, factor);
    if (scaled.share_in_band >= centring_share_goal && scaled.max_ratio <= centred_max_ratio) out.push_back(factor);
    if (out.size() == static_cast<std::size_t>(max_centring_attempts)) break;
  }
  return out;
}

std::vector<double> finer_lattice_factors(const std::vector<double>& ratios, const SizeBand& band) {
  std::vector<double> out;
  const double share_goal = std::min(band.share_in_band, size_band_goal) - centring_share_slack;
  for (double factor : finer_lattices) {
    const SizeBand scaled = scaled_size_band(ratios, factor);
    if (scaled.share_in_band >= share_goal && scaled.max_ratio <= max_size_ratio)
      out.push_back(factor);
  }
  return out;
}

/// The cone candidate judged as its quads would be written: a sound one gets the
/// deviation tolerance the Abel route refines to (the written quads' fitting uses
/// it), and when its quads are farther from S than the acceptance allows, the
/// improvement the written quads get (quad_improvement.h: the worst quads smoothed,
/// corners moved onto S where the quads cut across it, corners towards right
/// angles) before its quality, size band and distance are measured again. The
/// cones' quads are not refined, so their distance is judged after the fitting.
void judge_as_written(ConeCandidate& cones, const QuadMeshOptions& options, double diagonal, SurfaceTopology input,
                      Stages& stages) {
  Candidate& c = cones.candidate;
  if (!std::isnan(cones.distance) || !sound(c.quality, input, options.acceptance)) return;
  cones.distance = relative_hausdorff(c.result);
  c.result.judged_deviation = cones.distance * diagonal;
  if (options.max_deviation >= 0) c.result.max_deviation = deviation_tolerance(options, diagonal, c.result);
  if (cones.distance <= options.acceptance.max_hausdorff_relative) return;
  c.result.judged_deviation = -1;  // the fitting measures it again
  improve_quads(c.result, options, stages);
  c.quality = assess_candidate(c.result);
  cones.band = size_band(c.result);
  cones.distance = relative_hausdorff(c.result);
  c.result.judged_deviation = cones.distance * diagonal;
}

/// What cones_replace and criteria_missed weigh of a cone candidate.
RouteJudgement route_judgement(const ConeCandidate& c) {
  return {c.candidate.quality, c.band, corner_mismatches(c.candidate.result)};
}

/// Whether the sound candidate `later` comes nearer the route's acceptance than
/// `kept`, a placement before it: fewer of the criteria missed (criteria_missed:
/// the band, the corners, the shape; and the distance to S where it was judged,
/// which it is only for a candidate that meets the band and the corners), or as
/// many with more of its quads in the size band (by more than a point) and none
/// larger. A plate with rounded corners and three holes (200 x 80, its fillets 1.5
/// quads in radius): the first sound placement has 71% of its quads in the band and
/// one 5.5 x the size at a fillet; the fillets' cones, tried last, 89% and 3.0 x.
bool closer_to_acceptance(const ConeCandidate& later, const ConeCandidate& kept, const AcceptanceCriteria& criteria) {
  const auto missed = [&](const ConeCandidate& c) {
    return criteria_missed(route_judgement(c), criteria) + static_cast<int>(c.distance > criteria.max_hausdorff_relative);
  };
  const int later_missed = missed(later), kept_missed = missed(kept);
  if (later_missed != kept_missed) return later_missed < kept_missed;
  return later.band.share_in_band > kept.band.share_in_band + 0.01 && later.band.max_ratio <= kept.band.max_ratio;
}

/// The first placement of cone_placements() (then fallback_placements(), when none
/// gave sound quads with size_band_goal of them in the size band, then, greedy,
/// capped_placements(), at once after a placement refused as an
/// UncappedProtrusion, then fillet_placements() where the part has convex fillet
/// corners and no protrusion) whose quads at `lattice_factor` are acceptable:
/// sound, size_band_goal of them in the size band and none above max_size_ratio x
/// the size, every corner in its quad count, and within the acceptance's distance
/// of S as judged
/// (judge_as_written); each placement one of `attempts_left` (counted down, a
/// thrown one too), and the search ended after max_distance_misses that miss only
/// the distance. The first sound one may miss the band or a corner where a later
/// one does not (fertility, its handles steered: the first sound placement has 85%
/// of its quads in the band and two corners wrong). When none is acceptable: the sound one
/// nearest acceptance (closer_to_acceptance; the first of equals), judged if it was; when none
/// is sound, the last that gave quads, measured;
/// nothing when every one threw (`failure` then says why the first did).
std::optional<ConeCandidate> first_acceptable_placement(const FormSetup& setup, const QuadMeshOptions& options,
                                                   SurfaceTopology input, Stages& stages, double lattice_factor,
                                                   int& attempts_left, std::string& failure) {
  std::optional<ConeCandidate> last, best_sound;
  std::vector<std::vector<Cone>> placed;
  const InteriorCones interior = options.cone_placement == ConePlacement::cross_field ? InteriorCones::cross_field
                                                                                     : InteriorCones::greedy;
  std::vector<ConePlacementOptions> placements = cone_placements(interior, has_handles(input));
  // with two threads, two placements at a time (each a seamless map of up to
  // several seconds, on one core); the first acceptable one in order is kept, as
  // one at a time would, and what a placement after it found is dropped
  const std::size_t width = std::max<std::size_t>(1, std::min<std::size_t>(placements_side_by_side, worker_threads()));
  // each place in a batch keeps its surface's solvers for the next batch
  PlacementSurfaces surfaces(width);
  bool found = false;
  // whether some placement's quads were sound, and whether one of those had
  // size_band_goal of them in the size band
  bool some_sound = false, sound_share_in_band = false;
  bool fallbacks_added = false, capped_added = false, fillets_added = false, squares_added = false,
       protrusion = false;
  // whether the part has convex fillets, found once when a stage first asks
  std::optional<bool> has_convex_fillets;
  const auto convex_fillets = [&] {
    if (!has_convex_fillets) {
      const std::vector<BoundaryCorner> fillets =
          fillet_corners(setup.soup, setup.preamble.size_requested * lattice_factor);
      has_convex_fillets = std::any_of(fillets.begin(), fillets.end(), convex_fillet);
    }
    return *has_convex_fillets;
  };
  int distance_misses = 0;  // max_distance_misses
  for (std::size_t start = 0; attempts_left > 0 && !found && distance_misses < max_distance_misses;) {
    while (start >= placements.size() && interior == InteriorCones::greedy && !squares_added) {
      std::vector<ConePlacementOptions> more;
      if (!fallbacks_added && !sound_share_in_band && !capped_added) {
        fallbacks_added = true;
        more = fallback_placements(some_sound);
      } else if (!capped_added) {
        // the protrusions' caps after those: their cones move what the others settle
        capped_added = true;
        more = capped_placements();
      } else if (!fillets_added) {
        // the fillets' cones, where the part has convex fillets and no protrusion
        // lacks its caps' cones (the fillet placements have no caps)
        fillets_added = true;
        if (!protrusion && convex_fillets()) more = fillet_placements();
      } else {
        // the holes squares last (no caps either)
        squares_added = true;
        if (!protrusion) more = squared_hole_placements(convex_fillets());
      }
      placements.insert(placements.end(), more.begin(), more.end());
    }
    if (start >= placements.size()) break;
    const std::size_t count = std::min({width, placements.size() - start, static_cast<std::size_t>(attempts_left)});
    std::vector<ConeAttempt> attempts;
    if (count == 1) {  // on this thread, its progress as it goes
      attempts.push_back(
          run_attempt(setup, placements[start], stages, lattice_factor, options.smoothing, &placed, &surfaces[0]));
    } else {
      const std::vector<ConePlacementOptions> batch(placements.begin() + static_cast<std::ptrdiff_t>(start),
                                                    placements.begin() + static_cast<std::ptrdiff_t>(start + count));
      stages.announce(fmt::format("trying {} cone placements side by side", count));
      // checked against the batches before it (`placed` grows only below, in order)
      // a placement refused as an UncappedProtrusion ends the batch below while
      // the capped placements are still to come: those beside it stop at once
      const bool protrusion_ends_batch = interior == InteriorCones::greedy && !capped_added;
      attempts = cone_attempts_side_by_side(setup, batch, lattice_factor, options.smoothing, &surfaces, &placed,
                                            protrusion_ends_batch);
    }
    std::size_t consumed = 0;  // the attempts taken in order (the rest dropped)
    for (ConeAttempt& attempt : attempts) {
      ++consumed;
      if (attempt.unexpected) std::rethrow_exception(attempt.unexpected);
      --attempts_left;
      stages.replay(attempt.messages, attempt.timings);
      std::string error = attempt.error;
      if (attempt.cones && placed_before(*attempt.cones, placed)) {
        error = placed_before_error;
      } else if (attempt.cones) {
        placed.push_back(*attempt.cones);
      }
      if (!error.empty()) {
        if (failure.empty()) failure = error;
        protrusion = protrusion || attempt.uncapped_protrusion;
        if (attempt.uncapped_protrusion && interior == InteriorCones::greedy && !capped_added) {
          // a protrusion's cap that lacks its cones lacks them in every placement
          // without the caps: the capped ones next, the others dropped (those made
          // beside this one too, as one thread would not have made them)
          capped_added = true;
          placements.resize(start + consumed);
          const std::vector<ConePlacementOptions> capped = capped_placements();
          placements.insert(placements.end(), capped.begin(), capped.end());
          break;
        }
        continue;
      }
      last.emplace();
      last->candidate = std::move(*attempt.candidate);
      last->band = size_band(last->candidate.result);
      if (!sound(last->candidate.quality, input, options.acceptance)) continue;
      some_sound = true;
      sound_share_in_band = sound_share_in_band || last->band.share_in_band >= size_band_goal;
      if (in_size_band(last->band) && corner_mismatches(last->candidate.result) == 0) {
        judge_as_written(*last, options, setup.diagonal, input, stages);
        const bool sound_in_band = sound(last->candidate.quality, input, options.acceptance) && in_size_band(last->band);
        found = sound_in_band && last->distance <= options.acceptance.max_hausdorff_relative;
        if (found) break;
        distance_misses += sound_in_band;
      }
      if (!best_sound || closer_to_acceptance(*last, *best_sound, options.acceptance)) best_sound = std::move(last);
      // (the attempts after it dropped, as one at a time would not make them)
      if (distance_misses >= max_distance_misses) break;
    }
    start += consumed;
  }
  if (!found && best_sound) last = std::move(best_sound);
  if (!last || !last->candidate.quality.has_quads) return std::nullopt;
  return last;
}

/// The cones of `r` (sound, `band` its size band) mapped again on a lattice
/// `factor` x the requested size, judged and improved as written: kept when sound,
/// within the acceptance's distance of S, in the size band (size_band_goal of its
/// quads in it and none above max_size_ratio, both as mapped and as written: the
/// smoothing moves the largest quads' corners too), with more of them in it than
/// `band` and no more corners in another quad count.
std::optional<ConeCandidate> centred_candidate(const FormSetup& setup, const QuadMeshOptions& options,
                                               SurfaceTopology input, Stages& stages, const QuadMeshResult& r,
                                               const SizeBand& band, double factor) {
  stages.announce(fmt::format("{:.0f}% of the quads in the size band: the same cones on a lattice {:g} x the size",
                              100 * band.share_in_band, factor));
  const RoundingOrder order =
      r.rounding_order == "translations_first" ? RoundingOrder::translations_first : RoundingOrder::cones_first;
  ConeCandidate centred;
  try {
    centred.candidate = cone_quads(setup, r.cones, stages, factor, options.smoothing, order);
  } catch (const Error&) {
    return std::nullopt;  // no map on that lattice
  }
  if (!sound(centred.candidate.quality, input, options.acceptance)) return std::nullopt;
  if (corner_mismatches(centred.candidate.result) > corner_mismatches(r)) return std::nullopt;
  const SizeBand as_mapped = size_band(centred.candidate.result);
  judge_as_written(centred, options, setup.diagonal, input, stages);
  improve_quads(centred.candidate.result, options, stages);
  centred.band = size_band(centred.candidate.result);
  const bool in_band = std::min(as_mapped.share_in_band, centred.band.share_in_band) >= size_band_goal &&
                       std::max(as_mapped.max_ratio, centred.band.max_ratio) <= max_size_ratio;
  if (!in_band || !(centred.band.share_in_band > band.share_in_band) ||
      !(centred.distance <= options.acceptance.max_hausdorff_relative))
    return std::nullopt;
  return centred;
}

/// `cones` (some of its quads above max_size_ratio x the size) with the chords
/// through those quads split (size_refinement.h), when its quads are sound and stay
/// sound and come within the size band (size_band_goal of them in it, none above
/// max_size_ratio) with no more corners in another quad count.
std::optional<ConeCandidate> size_refined(const ConeCandidate& cones, const QuadMeshOptions& options,
                                          SurfaceTopology input, Stages& stages) {
  const QuadMeshResult& kept = cones.candidate.result;
  if (!(kept.size_requested > 0) || !sound(cones.candidate.quality, input, options.acceptance)) return std::nullopt;
  stages.next("size_refinement", fmt::format("splitting the chords through the quads above {:g} x the size",
                                             max_size_ratio));
  QuadMeshResult r = kept;
  SizeRefinementOptions refinement;
  refinement.size = r.size_requested;
  refinement.max_ratio = max_size_ratio;
  r.size_refinement = refine_to_size(r.surface, surface_adjacency(r.surface), r.quads, r.boundary_loop_of_point,
                                     refinement);
  if (r.size_refinement.chords_split == 0) return std::nullopt;
  ConeCandidate out;
  out.candidate.quality = assess_candidate(r);
  out.band = size_band(r);
  if (!sound(out.candidate.quality, input, options.acceptance) || !in_size_band(out.band) ||
      corner_mismatches(r) > corner_mismatches(kept))
    return std::nullopt;
  out.candidate.result = std::move(r);
  return out;
}

/// The quads a deviation refinement of cone quads may reach, as a multiple of their
/// count (the Abel quads' budget is 1.1 x the target count: deviation_budget.h; a
/// chord of a cone mesh runs farther, across the part).
constexpr double max_deviation_refinement_growth = 1.25;
/// The deviation the refinement aims at, as a fraction of the acceptance's
/// distance: below it, since the smoothing and the fitting move corners after.
constexpr double deviation_target_of_acceptance = 0.8;

/// `cones` (sound, in the size band, every corner right, but farther from S than
/// the acceptance allows, as judged) with the chords split where its quads deviate
/// (deviation_refinement.h: within max_deviation_refinement_growth x its quads, to
/// deviation_target_of_acceptance of the acceptance's distance or the deviation
/// tolerance, the smaller), when that is sound, in the band, every corner right and
/// within the distance as judged.
std::optional<ConeCandidate> deviation_refined(const ConeCandidate& cones, const QuadMeshOptions& options,
                                               double diagonal, SurfaceTopology input, Stages& stages) {
  const QuadMeshResult& kept = cones.candidate.result;
  if (!(cones.distance > options.acceptance.max_hausdorff_relative) || options.max_deviation < 0 ||
      !sound(cones.candidate.quality, input, options.acceptance) || !in_size_band(cones.band) ||
      corner_mismatches(kept) > 0)
    return std::nullopt;
  QuadMeshResult r = kept;
  DeviationRefinementOptions refinement;
  refinement.tolerance = std::min(deviation_tolerance(options, diagonal, r),
                                  deviation_target_of_acceptance * options.acceptance.max_hausdorff_relative * diagonal);
  refinement.max_quads = static_cast<std::size_t>(max_deviation_refinement_growth *
                                                  static_cast<double>(r.quads.quads.size()));
  refinement.min_scaled_jacobian = options.acceptance.min_scaled_jacobian;
  stages.next("refinement", fmt::format("{:.2g}% of the diagonal from the surface: splitting the chords where the "
                                        "cones' quads are farther than {:.4g}",
                                        100 * cones.distance, refinement.tolerance));
  r.refinement = refine_to_deviation(r.surface, surface_adjacency(r.surface), r.quads, r.boundary_loop_of_point,
                                     refinement);
  if (r.refinement.chords_split == 0) return std::nullopt;
  r.judged_deviation = -1;  // measured again as written (and max_deviation set: judge_as_written)
  ConeCandidate out;
  out.candidate.quality = assess_candidate(r);
  out.band = size_band(r);
  out.candidate.result = std::move(r);
  return out;
}

/// The greedy (or the asked) placements' candidate on `setup` (turned_boundary_setup):
/// the placements in turn, until one gives sound quads (cramped cones fold the
/// map), then a lattice centred or finer. Throws qm::Error with the first
/// placement's failure when none gives quads.
ConeCandidate placements_candidate(const FormSetup& setup, const QuadMeshOptions& options, SurfaceTopology input,
                                   Stages& stages) {
  std::string failure;
  // every placement, the fallbacks, the capped ones and those with the fillets' cones
  int every_placement =
      static_cast<int>(cone_placements(InteriorCones::greedy, has_handles(input)).size() + 2 +
                       capped_placements().size() + fillet_placements().size() + squared_hole_placements(true).size());
  // (the cones rounded first only: every placement mapped again with the
  // translations rounded first, where none gave sound quads, made none of the 33
  // shared meshes, examples, parts and scan cuts sound; the scans' maps lost their
  // topology that way, and a failing route paid up to ten more maps)
  std::optional<ConeCandidate> cones =
      first_acceptable_placement(setup, options, input, stages, 1.0, every_placement, failure);
  if (!cones) throw Error(ErrorCode::unsupported, failure);
  // sound, but some quads a little larger than the acceptance allows: where the
  // lattice falls against the cone metric's sizes is a matter of rounding, so the
  // lattice a little finer (the cones placed again at its size), kept when its
  // quads stay within max_size_ratio and in the band. Far larger quads are the
  // metric's (too few cones), which no lattice mends
  const SizeBand band = cones->band;
  // (not with a quad count asked for: another lattice is another count)
  if (options.quads == 0 && sound(cones->candidate.quality, input, options.acceptance) &&
      band.max_ratio <= max_size_ratio && band.share_in_band < size_band_goal) {
    const QuadMeshResult& r = cones->candidate.result;
    for (double factor : centring_lattice_factors(quad_size_ratios(polygon_mesh(r.quads), r.size_requested))) {
      if (std::optional<ConeCandidate> centred = centred_candidate(setup, options, input, stages, r, band, factor))
        return std::move(*centred);
    }
    return std::move(*cones);
  }
  if (!sound(cones->candidate.quality, input, options.acceptance) || band.max_ratio <= max_size_ratio ||
      band.max_ratio > finer_lattice_below * max_size_ratio)
    return std::move(*cones);
  int attempts_left = max_finer_attempts;
  for (double scale :
       finer_lattice_factors(quad_size_ratios(polygon_mesh(cones->candidate.result.quads),
                                              cones->candidate.result.size_requested),
                             band)) {
    std::string ignored;
    std::optional<ConeCandidate> finer =
        first_acceptable_placement(setup, options, input, stages, scale, attempts_left, ignored);
    if (!finer || !sound(finer->candidate.quality, input, options.acceptance)) continue;
    if (finer->band.max_ratio <= max_size_ratio &&
        finer->band.share_in_band >= std::min(band.share_in_band, size_band_goal))
      return std::move(*finer);
  }
  return std::move(*cones);
}

/// Whether `cones`, judged as written, meets what the route asks: sound, in the
/// size band, every corner in its quad count, within the acceptance's distance.
bool acceptable(ConeCandidate& cones, const QuadMeshOptions& options, double diagonal, SurfaceTopology input,
                Stages& stages) {
  judge_as_written(cones, options, diagonal, input, stages);
  return sound(cones.candidate.quality, input, options.acceptance) && in_size_band(cones.band) &&
         corner_mismatches(cones.candidate.result) == 0 && cones.distance <= options.acceptance.max_hausdorff_relative;
}

/// The quads of cross_field_placement(), or nothing when it throws.
std::optional<ConeCandidate> field_candidate(const FormSetup& setup, const QuadMeshOptions& options, Stages& stages) {
  ConeAttempt attempt = run_attempt(setup, cross_field_placement(), stages, 1.0, options.smoothing);
  if (attempt.unexpected) std::rethrow_exception(attempt.unexpected);
  if (!attempt.candidate) return std::nullopt;
  ConeCandidate out;
  out.candidate = std::move(*attempt.candidate);
  out.band = size_band(out.candidate.result);
  return out;
}

/// The cone route's candidate: placements_candidate's (the greedy placements,
/// then a lattice centred or finer); where that is not acceptable, greedy, the
/// cross field's singularities (cross_field_placement), kept when they are; then
/// placements_candidate's with the chords through its quads above the band split
/// (size_refined), kept when acceptable: a cone layout that meets the band by
/// itself is preferred to a strip halved. Throws qm::Error with the first
/// placement's failure when neither gives quads.
ConeCandidate cone_candidate(const FormSetup& form_setup, const QuadMeshOptions& options, SurfaceTopology input,
                             Stages& stages) {
  const FormSetup setup = turned_boundary_setup(form_setup);
  std::optional<ConeCandidate> placed;
  std::string failure;
  try {
    placed = placements_candidate(setup, options, input, stages);
    if (acceptable(*placed, options, setup.diagonal, input, stages)) return std::move(*placed);
  } catch (const Error& e) {
    failure = e.what();
  }
  if (options.cone_placement == ConePlacement::greedy) {
    std::optional<ConeCandidate> field = field_candidate(setup, options, stages);
    if (field && acceptable(*field, options, setup.diagonal, input, stages)) return std::move(*field);
  }
  if (!placed) throw Error(ErrorCode::unsupported, failure);
  // last, the placements' quads with the chords through those above the band split,
  // or where they are farther from S than the acceptance allows
  if (placed->band.max_ratio > max_size_ratio)
    if (std::optional<ConeCandidate> refined = size_refined(*placed, options, input, stages))
      if (acceptable(*refined, options, setup.diagonal, input, stages)) return std::move(*refined);
  if (std::optional<ConeCandidate> refined = deviation_refined(*placed, options, setup.diagonal, input, stages))
    if (acceptable(*refined, options, setup.diagonal, input, stages)) return std::move(*refined);
  return std::move(*placed);
}

}  // namespace

bool cones_first(const TriangleSoup& soup, double size, const QuadMeshOptions& options) {
  return options.singularities == Singularities::automatic && !corner_cones(soup, size).empty();
}

ConesFirst try_cones_first(const FormSetup& setup, const QuadMeshOptions& options, SurfaceTopology input,
                           Stages& stages) {
  ConesFirst out;
  if (!cones_first(setup.soup, setup.preamble.size_requested, options)) return out;
  try {
    ConeCandidate cones = cone_candidate(setup, options, input, stages);
    judge_as_written(cones, options, setup.diagonal, input, stages);
    const QuadMeshResult& r = cones.candidate.result;
    const bool enough = sound(cones.candidate.quality, input, options.acceptance) &&
                        cones.band.share_in_band >= size_band_goal && corner_mismatches(r) == 0 &&
                        cones.distance <= options.acceptance.max_hausdorff_relative;
    if (enough)
      out.kept = std::move(cones.candidate);
    else
      out.tried = std::move(cones);
  } catch (const Error& e) {
    out.failure = e.what();
  }
  return out;
}

ConeRouteOutcome try_cones_if_off_band(const FormSetup& setup, const QuadMeshOptions& options, SurfaceTopology input,
                                       Stages& stages, Candidate& best, ConesFirst first) {
  ConeRouteOutcome outcome;
  if (options.singularities != Singularities::automatic) return outcome;
  const RouteJudgement abel{best.quality, best.quality.has_quads ? size_band(best.result) : SizeBand{},
                            best.quality.has_quads ? corner_mismatches(best.result) : 0};
  outcome.abel_size_band_share = abel.band.share_in_band;
  if (in_size_band(abel.band) && abel.corners_wrong == 0) return outcome;
  if (!first.failure.empty()) {  // tried before the Abel route, and failed
    outcome.failure = first.failure;
    return outcome;
  }
  try {
    ConeCandidate tried = first.tried ? std::move(*first.tried) : cone_candidate(setup, options, input, stages);
    judge_as_written(tried, options, setup.diagonal, input, stages);
    Candidate& cones = tried.candidate;
    const RouteJudgement judged = route_judgement(tried);
    if (!cones_replace(judged, abel, input, options.acceptance)) {
      outcome.failure = fmt::format(
          "the cones' quads were not better ({}; {:.0f}% in the size band against {:.0f}%; {} corners with the wrong "
          "quad count against {})",
          sound(cones.quality, input, options.acceptance) ? "sound" : "not sound: " + unsound_reason(cones.quality, input),
          100 * judged.band.share_in_band, 100 * abel.band.share_in_band, judged.corners_wrong, abel.corners_wrong);
      return outcome;
    }
    // nor farther from S than the criterion allows (the Abel quads are refined
    // where they deviate, the cones' only fitted)
    const double distance = tried.distance;
    if (distance > options.acceptance.max_hausdorff_relative) {
      outcome.failure = fmt::format("the cones' quads are {:.2g}% of the diagonal from the surface (at most {:.2g}% "
                                    "allowed)",
                                    100 * distance, 100 * options.acceptance.max_hausdorff_relative);
      outcome.too_far = std::move(tried);
      return outcome;
    }
    best = std::move(cones);
  } catch (const Error& e) {
    outcome.failure = e.what();
  }
  return outcome;
}

void split_abel_quads_above_band(Candidate& best, const QuadMeshOptions& options, SurfaceTopology input,
                                 Stages& stages) {
  if (options.singularities != Singularities::automatic || !best.quality.has_quads ||
      best.result.singularities != "abel")
    return;
  const SizeBand band = size_band(best.result);
  if (!(band.share_in_band >= size_band_goal) || !(band.max_ratio > max_size_ratio)) return;
  ConeCandidate kept;
  kept.candidate.result = best.result;
  kept.candidate.quality = assess_candidate(best.result);  // (refined where it deviates since measured)
  kept.band = band;
  if (std::optional<ConeCandidate> refined = size_refined(kept, options, input, stages))
    best = std::move(refined->candidate);
}

namespace {

/// What the acceptance asks of quads as written that the route judged before the
/// improvement: the mean angle and the size band (QuadQuality's figures).
struct WrittenFigures {
  double angle = 0;               ///< mean |corner angle - 90|, degrees
  double share_in_band = 0;       ///< of the quads, the share in the size band
  bool in_band = false;           ///< size_band_goal of the quads in the band, none above max_size_ratio
  bool singular_within = false;   ///< interior singular vertices within the placement's bound

  int misses(const AcceptanceCriteria& criteria) const {
    return static_cast<int>(angle > criteria.max_mean_angle_deviation_deg) + static_cast<int>(!in_band);
  }
};

/// Precondition: `r` has quads and a requested size.
WrittenFigures written_figures(const QuadMeshResult& r) {
  const PolygonMesh mesh = polygon_mesh(r.quads);
  const QuadQuality q = quad_quality(mesh, nullptr);
  const SizeBand band = quad_size_band(mesh, r.size_requested);
  WrittenFigures out;
  out.angle = q.angle_dev_mean;
  out.share_in_band = band.share_in_band;
  out.in_band = in_size_band(band);
  const ConePlacementOptions bound;  // issue 18's bound on interior singular vertices
  out.singular_within = static_cast<double>(q.irregular_interior) <=
                        std::max(bound.max_interior_cones,
                                 bound.max_interior_cone_share * static_cast<double>(r.quads.quads.size()));
  return out;
}

/// `cones`, where it is acceptable to the route, improved as written; it replaces
/// `result` (whose written figures are `kept`, some criterion missed) when it misses
/// fewer of the mean angle and the band as written, or only the angle, as `kept`
/// does, by less, and keeps its interior singular vertices within the bound.
void keep_if_better_written(QuadMeshResult& result, const WrittenFigures& kept, std::optional<ConeCandidate> cones,
                            const QuadMeshOptions& options, double diagonal, SurfaceTopology input, Stages& stages) {
  if (!cones || !acceptable(*cones, options, diagonal, input, stages)) return;
  QuadMeshResult& candidate = cones->candidate.result;
  improve_quads(candidate, options, stages);
  const WrittenFigures other = written_figures(candidate);
  const int kept_misses = kept.misses(options.acceptance), other_misses = other.misses(options.acceptance);
  const bool better = other_misses < kept_misses || (other_misses == 1 && kept_misses == 1 && kept.in_band &&
                                                      other.in_band && other.angle < kept.angle);
  if (better && other.singular_within) result = std::move(candidate);
}

}  // namespace

void prefer_field_cones(QuadMeshResult& result, const FormSetup& setup, const QuadMeshOptions& options,
                        SurfaceTopology input, Stages& stages) {
  if (options.singularities != Singularities::automatic || options.cone_placement != ConePlacement::greedy ||
      !options.smoothing || result.singularities != "cones" || result.quads.quads.empty() || !(result.size_requested > 0))
    return;
  const WrittenFigures kept = written_figures(result);
  if (kept.misses(options.acceptance) == 0) return;
  stages.announce(fmt::format("the cones' quads as written {}: the smoothest cross field's singularities tried",
                              kept.in_band ? fmt::format("{:.2f} degrees from right angles on average", kept.angle)
                                           : std::string("off the size band")));
  const FormSetup turned = turned_boundary_setup(setup);
  keep_if_better_written(result, kept, field_candidate(turned, options, stages), options, turned.diagonal, input,
                         stages);
}

void prefer_cones_to_written_abel(QuadMeshResult& result, bool cones_tried, const FormSetup& setup,
                                  const QuadMeshOptions& options, SurfaceTopology input, Stages& stages) {
  if (options.singularities != Singularities::automatic || !options.smoothing || cones_tried ||
      result.singularities != "abel" || result.quads.quads.empty() || !(result.size_requested > 0))
    return;
  const WrittenFigures kept = written_figures(result);
  if (kept.in_band) return;
  stages.announce(fmt::format("the Abel quads as written leave {:.1f}% of them in the size band: quarter-turn cones "
                              "tried",
                              100 * kept.share_in_band));
  std::optional<ConeCandidate> cones;
  try {
    cones = cone_candidate(setup, options, input, stages);
  } catch (const Error&) {
    return;  // no cones: the Abel quads stand
  }
  // (the Abel quads miss the band: only fewer criteria missed replace them)
  keep_if_better_written(result, kept, std::move(cones), options, setup.diagonal, input, stages);
}

void keep_nearer_cones(Candidate& best, ConeRouteOutcome& outcome, const QuadMeshOptions& options,
                       SurfaceTopology input, Stages& stages) {
  if (!outcome.too_far) return;
  ConeCandidate& cones = *outcome.too_far;
  double abel_distance = std::numeric_limits<double>::infinity();  // no Abel quads: the cones stand
  if (best.quality.has_quads) {
    improve_quads(best.result, options, stages);
    abel_distance = relative_hausdorff(best.result);
    best.result.abel_distance_relative = abel_distance;
  }
  if (!(cones.distance < abel_distance)) {
    outcome.failure += fmt::format(", no nearer than the Abel quads ({:.2g}%)", 100 * abel_distance);
    outcome.too_far.reset();
    return;
  }
  // nor worse shaped (candidate_ranking.h: the Jacobian floor, the angles)
  if (best.quality.has_quads &&
      !at_least_as_good(cones.candidate.quality, assess_candidate(best.result), input, options.acceptance)) {
    outcome.failure += ", and shaped worse than the Abel quads";
    outcome.too_far.reset();
    return;
  }
  cones.candidate.result.abel_distance_relative = abel_distance;
  best = std::move(cones.candidate);
  outcome.failure.clear();
  outcome.too_far.reset();
}

}  // namespace qm
