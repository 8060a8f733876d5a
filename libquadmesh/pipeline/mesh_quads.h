// The whole quad-meshing job on an analysed surface (method.md sections 1-9):
// symmetric forms, the choice of h and of its scale, zeros as vertices,
// quantization, extraction. Tools add reading, writing and reporting around it.
#pragma once

#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/cones/seamless_map.h"
#include "libquadmesh/extract/deviation_refinement.h"
#include "libquadmesh/extract/lattice_quads.h"
#include "libquadmesh/extract/quad_fitting.h"
#include "libquadmesh/extract/quad_angle_smoothing.h"
#include "libquadmesh/extract/quad_smoothing.h"
#include "libquadmesh/extract/size_refinement.h"
#include "libquadmesh/forms/symmetric_forms.h"
#include "libquadmesh/param/branch_points.h"
#include "libquadmesh/param/map_zeros.h"
#include "libquadmesh/param/quantization.h"
#include "libquadmesh/param/untangle.h"
#include "libquadmesh/pipeline/acceptance_criteria.h"

#include <functional>
#include <limits>
#include <string>

namespace qm {

/// When to remesh the input isotropically before the forms (forms/remesh.h).
enum class RemeshPolicy {
  automatic,  ///< when ||Lambda^2 + I|| > 0.1 on the input (the forms are then inaccurate)
  always,
  never,
};

/// Which singular vertices the quads may have (method.md section 11).
enum class Singularities {
  abel,       ///< the Abel differential's zeros only (the seed's method)
  automatic,  ///< as abel; where its quads miss the size band, quarter-turn cones
};

/// Where `automatic` puts its interior cones (cone_placement.h InteriorCones).
enum class ConePlacement {
  greedy,       ///< on the conformal factor, one at a time [Ben-Chen et al. 2008]
  cross_field,  ///< the smoothest boundary-aligned cross field's singularities
};

struct QuadMeshOptions {
  RemeshPolicy remesh = RemeshPolicy::automatic;
  /// automatic by default: where the Abel quads meet the size band and the
  /// corners' quad counts (or the cones fold), they are the result unchanged.
  Singularities singularities = Singularities::automatic;
  ConePlacement cone_placement = ConePlacement::greedy;
  double remesh_size = 0.0;  ///< target edge length of the remeshing; 0: min(0.4 x mean edge, size / 3)
  /// Which h: -1 "auto" (the most uniform |h|, param/form_choice.h), k >= 0 the
  /// k-th symmetric basis form; `coefficients` (when not empty) wins over both.
  int form = -1;
  std::vector<double> coefficients;
  /// Use i h: the grid turned by 90 degrees. The quantization is that of h (its
  /// boundaries are the horizontal ones) and the lattice is invariant under a
  /// quarter turn, so the quads are the same; U and V exchange their roles.
  bool rotate = false;
  double size = 0.0;        ///< target quad edge length; 0: size_relative or 1/60 of the bounding-box diagonal
  double size_relative = 0.0;  ///< target edge length as a fraction of the bounding-box diagonal
  std::size_t quads = 0;    ///< target quad count; wins over size when not 0
  /// Work limit: mesh_quads refuses (qm::Error, bad_input) before any work when
  /// the size or count asked for implies more quads than this (implied_quad_count);
  /// 0: no limit. A few million quads take minutes and gigabytes.
  std::size_t max_quads = 5000000;
  double corner_angle_deg = 30.0;
  /// With "auto": boundary vertices where the surface turns this much or more
  /// (degrees; a slit's end, the sharp corner of a small hole) get a zero of h, so
  /// that four quads share the turn rather than two (param/boundary_tips.h).
  /// Above 360: none.
  double tip_angle_deg = 315.0;
  /// Size adaptivity (extract/deviation_refinement.h): chords are split where the
  /// quads deviate from S by more than this distance. 0: half the target size;
  /// < 0: off. The quad count stays within 10% above the target: when the
  /// refinement needs more, the base lattice is made coarser to pay for it.
  double max_deviation = 0.0;
  double max_deviation_relative = 0.0;  ///< the same as a fraction of the bounding-box diagonal (wins when > 0)
  /// Move the regular interior corners of the worst quads (extract/quad_smoothing.h),
  /// then every regular interior corner towards right angles (extract/quad_angle_smoothing.h).
  bool smoothing = true;
  /// Where triangles wider than the quads cover 5% of the area, also mesh the input
  /// split by longest-edge bisection and keep the better result (forms/long_edges.h).
  bool split_long_edges = true;
  /// Where the input's triangles are far finer than the quads need (mean edge under
  /// a sixth of the quad size, no CAD curves), mesh a working triangulation with
  /// edges of about a third of the quad size, made of the input's own points by
  /// edge collapses (forms/coarsen.h). The quads lie on it; it is inscribed in S.
  bool coarsen = true;
  /// What a sound, well-shaped result is: the attempts are ranked by it
  /// (pipeline/internal/candidate_ranking.h), and a coarser base lattice bought for
  /// the size adaptivity must keep its Jacobian floor.
  AcceptanceCriteria acceptance;
};

struct QuadMeshResult {
  TriangleSoup surface;          ///< S as meshed (chords and zero stars split); locations refer to it
  LatticeQuads quads;            ///< the quad mesh (unreferenced points removed)
  std::vector<int> boundary_loop_of_point;  ///< per quad point: the input boundary loop it lies on, or -1
  int doubled_genus = 0;
  /// Of the forms used; NaN where none were computed (auto's cone quads kept
  /// before any form: a surface with corners at the quad size).
  FormsResiduals residuals;
  bool remeshed = false;         ///< the input was remeshed first
  double input_hodge_star_squared = 0;  ///< ||Lambda^2 + I|| on the input triangulation (NaN: no forms computed)
  Eigen::VectorXd coefficients;  ///< h = sum c_k h_k (unit vector), before rotation
  std::size_t boundary_tips = 0;  ///< boundary tips the auto form was asked to vanish at (tip_angle_deg)
  int form_attempts = 1;         ///< forms tried (auto tries the basis forms while folds, dropped cells or a wrong topology are left)
  int rounding_attempts = 0;     ///< the form rounded again at other scales (the quads were faulty: pipeline/internal/retry_policy.h)
  double uniformity = 0;         ///< R(c) of form_choice.h (1 = uniform |h|)
  double scale = 0;              ///< s: the grid is the integer lattice of s h
  double size = 0;               ///< the target edge length that s implies
  double size_requested = 0;     ///< the quad edge asked for: QuadMeshOptions::size (or its default), or with QuadMeshOptions::quads the edge of a square of area / quads
  double expected_quads = 0;     ///< area / size^2
  MapZeros zeros;                ///< of s h before quantization
  std::vector<ZeroVertex> zero_vertices;  ///< the zeros placed at vertices of `surface`, then the sharp corners
  std::size_t chords_split = 0, star_splits = 0;
  Quantization quantization;     ///< with the parameterization (after untangling)
  UntangleReport untangle;       ///< the local repair of folds left by the quantization
  SnapReport branch_points;      ///< vertices the untangled map branched at, off the cones, moved onto the lattice
  ExtractionReport extraction;
  /// Points on the quads' own boundary off every boundary of S (lattice_quads.h:
  /// stray_boundary_points), of the final quads; 0 for a sound mesh.
  std::size_t stray_boundary_points = 0;
  Vec3 first_stray_point = Vec3::Zero();  ///< where the first one is (when any)
  double base_density = 1.0;     ///< the base lattice's quad count as a fraction of the target (< 1: coarsened)
  double max_deviation = 0.0;    ///< the tolerance used (0: refinement off)
  DeviationRefinementReport refinement;
  SizeRefinementReport size_refinement;  ///< the cone route: chords split through quads above the size band
  QuadSmoothingReport smoothing;  ///< the worst quads' interior points moved on S
  QuadAngleSmoothingReport angle_smoothing;  ///< then every regular interior point, towards right angles
  QuadFittingReport fitting;      ///< corners moved onto S where the quads cut across it (max_deviation > 0)
  bool improved = false;          ///< smoothed and fitted (pipeline/internal/quad_improvement.h): not again
  /// the cone route: its quads' two-sided distance from S when it judged them
  /// (absolute; < 0: not measured)
  double judged_deviation = -1;
  std::vector<std::pair<std::string, double>> timings;  ///< seconds per stage
  /// Edges of the input longer than the target size, split (forms/long_edges.h);
  /// when > 0 the input as it is was meshed too, and the better result kept.
  std::size_t long_edges_split = 0;
  bool long_edges_kept = false;  ///< the result is the split input's
  /// The input's triangle count when a coarser working triangulation was meshed
  /// (QuadMeshOptions::coarsen; `surface` is then that triangulation); 0: not coarsened.
  std::size_t coarsened_from = 0;

  // the singularities (Singularities::automatic)
  std::string singularities = "abel";  ///< the route of the quads: "abel" or "cones"
  std::vector<Cone> cones;             ///< the cones placed (the cone route), by vertex of `surface`
  SeamlessMapReport cone_map;          ///< the cone route's quantization
  std::string rounding_order = "cones_first";  ///< the cone route's quantization order (seamless_map.h RoundingOrder)
  std::size_t wide_corners_split = 0;  ///< the cone route's edges split to bisect corners the metric opens too wide
  double size_band_share = std::numeric_limits<double>::quiet_NaN();       ///< quads within [0.5, 2] x size (quality/size_band.h); NaN: not measured
  double abel_size_band_share = std::numeric_limits<double>::quiet_NaN();  ///< the Abel result's, when automatic measured it; NaN: not measured
  std::string cone_route_failure;      ///< why the cone route was not kept (empty: kept, or not tried)
  /// The Abel quads' two-sided Hausdorff distance from S / the diagonal, when the
  /// cones' quads were better but farther than the acceptance allows and the two were
  /// weighed by distance (NaN otherwise): the cones kept when the Abel quads were farther.
  double abel_distance_relative = std::numeric_limits<double>::quiet_NaN();
};

/// The quads the options ask for on this surface: QuadMeshOptions::quads when
/// given, else surface area / size^2 (the size as mesh_quads reads it: size,
/// size_relative x the bounding-box diagonal, or 1/60 of it). What max_quads is
/// compared with; infinite or NaN for a size of 0 or NaN.
double implied_quad_count(const TriangleSoup& soup, const QuadMeshOptions& options);

using ProgressCallback = std::function<void(const std::string&)>;

/// Meshes a supported surface with boundary (an AnalyzedSurface's soup). Throws
/// qm::Error(unsupported) for closed surfaces (not implemented yet), (bad_input)
/// for options that do not fit the surface, (solver) when a stage fails.
QuadMeshResult mesh_quads(TriangleSoup soup, const QuadMeshOptions& options,
                          const ProgressCallback& progress = {});

}  // namespace qm
