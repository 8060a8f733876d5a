// Where the cones go (method.md section 11, "auto"): a quad at every CAD corner
// as its angle asks, and the interior cones that Gauss-Bonnet then demands,
// placed greedily on the conformal factor [Ben-Chen, Gotsman, Bunin 2008].
//
// Corners: a boundary vertex whose angle alpha at the quad scale (the boundary's
// turning within half a quad each way, boundary_corners.h: on a CAD part the sum
// of its triangles' angles) is away from pi gets q = max(1, round(alpha / (pi/2)))
// quads; the vertices between, a scan's teeth among them, are straight (q = 2).
// Interior: the corners leave D = 4 chi - sum (2 - q) quarter turns to the inside
// (a plate with two holes and four right corners: D = -8, eight valence-5 cones).
// They are placed one at a time: with the cones placed so far concentrated and the
// rest of D spread over the interior by area, the cone metric is solved, and the
// next valence-5 cone goes where u is highest (the quads smallest), a valence-3
// cone where it is lowest; a cone there pulls u towards the middle of the band.
// Where the metric's quad size still leaves the band (a protrusion, the end of an
// arm, a surface whose corners carry all of D), valence-5 and valence-3 cones are
// added in pairs at the highest and lowest u while the band improves.
// With several boundary loops the cones are then moved, one at a time and a few
// edges at most, until the field meets every loop at a whole quarter turn ("fix
// it by the choice of cones"); what is left the trivial connection of
// loop_alignment.h takes.
#pragma once

#include "libquadmesh/cones/boundary_corners.h"
#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/cones/seamless_map.h"
#include "libquadmesh/cones/tip_scale.h"
#include "libquadmesh/core/error.h"

#include <Eigen/Core>

namespace qm {

class ConeMetricSolver;  // cone_metric.h

/// Where the interior cones come from.
enum class InteriorCones {
  greedy,       ///< one at a time at the extremes of the conformal factor (above)
  /// the singularities of the smoothest boundary-aligned cross field
  /// (smooth_cross_field.h), moved only to align the loops: no pairs, no size
  /// relaxation (the classical route, measured against the greedy one)
  cross_field,
};

struct ConePlacementOptions {
  InteriorCones interior = InteriorCones::greedy;
  /// A boundary vertex counts as a corner when its angle at the quad scale
  /// (boundary_corners.h) differs from pi by more than this (degrees): 45 puts the
  /// change of quad count half-way between.
  double corner_angle_deg = corner_angle_tolerance_deg;
  /// At most max(max_interior_cones, max_interior_cone_share x the quads the area
  /// holds at the size) interior cones (issue 18's bound on singular vertices): a
  /// surface whose corners leave more is refused (qm::Error, unsupported).
  double max_interior_cones = 24;
  double max_interior_cone_share = 0.01;
  /// The sizes the cones are placed for leave an acute corner's singular scale out
  /// near it (tip_scale.h), as the map does.
  bool tip_sizes = true;
  /// Interior cones keep this far from the boundary (in quads of the target size):
  /// nearer, the cone and the boundary line compete for the same lattice row.
  double boundary_distance = 2.0;
  /// Interior cones keep this far from each other (in quads of the target size,
  /// straight-line distance): two nearer cones fold the map between them.
  double cone_spacing = 2.5;
  /// Where no vertex is that far from the boundary and the other cones (a part
  /// narrower than twice boundary_distance: a shaft, the ring round a bore), the
  /// rest of the interior cones may come this near the boundary and this near
  /// each other (quads; never farther than the two above).
  double narrow_boundary_distance = 1.5;
  double narrow_cone_spacing = 2.0;
  /// With InteriorCones::cross_field, a singularity of the field nearer the
  /// boundary than this (quads) goes to the nearest vertex this far from it and
  /// field_cone_spacing from the singularities placed before it. The field puts
  /// them where its crosses turn fastest, a triangle from a concave fillet's foot
  /// or a slot's rounded end, where the cone and the boundary's lattice line
  /// compete: 2-8 folded triangles on a plate with two slots, a spanner and a
  /// square flange; moved, none. (Further, 1.5 and 2 quads, the spanner's narrow
  /// jaws have no room for them, and the metric's quads reach 10^3 x the size.)
  double field_boundary_distance = 1.0;
  double field_cone_spacing = 1.5;
  /// A valence-5 cone the corners leave may go on the boundary, as a straight
  /// boundary point in three quads, where no vertex that may take an interior cone
  /// is within boundary_distance + 1 quads along the edges and the quads are
  /// smaller there than at any such vertex: a hole in a shaft a few quads wide
  /// (the singular points of a hand-made O-grid round it sit on the shaft's edges).
  bool boundary_cones = false;
  /// Such a cone keeps this far from every other cone (quads, straight line).
  double boundary_cone_spacing = 0.9;
  /// When it falls on a hole at most this long (quads) with no cone on it yet, and
  /// four valence-5 cones are still to place, they go on the hole a quarter of its
  /// length apart: the hole a square on the lattice.
  double square_hole_length = 8.0;
  /// Where the corners leave more interior cones than the bound allows (with
  /// fillet_cones, each fillet's valence-3 cone and the valence-5 one it asks
  /// counted), every hole without corners at most square_hole_max_length quads
  /// round is made a square in the same way, four boundary cones each (a hexagonal
  /// flange with a bore and six bolt holes: 30 quarter turns for 24 cones allowed;
  /// its six bolt holes squared, 6 interior cones).
  bool square_crowded_holes = true;
  double square_hole_max_length = 16.0;
  /// Every such hole a square whether the corners crowd the bound or not.
  bool square_every_hole = false;
  /// A square's corners go at 45 degrees to the normal of the nearest loop of the
  /// frame (a loop with corners, or too long to be a square) rather than of the
  /// nearest loop: beside another hole made a square, the nearest loop turns the
  /// square by the angle between the two holes (a 120 x 50 plate with seven holes,
  /// its squares turned 30-40 degrees against its edges, folds every map between
  /// them; turned to its edges, none).
  bool squares_face_frame = false;
  /// With several boundary loops, each cone goes, among the vertices whose u is
  /// within this of the extreme, where the field meets the loops best.
  double extreme_tolerance = 0.15;
  /// Then a cone may move this far (edges) so that the field meets every loop at
  /// a whole quarter turn (cross_field.h LoopTurns); twice and three times as far
  /// when no nearer move helps and the loops are still turned...
  int alignment_rings = 4;
  /// ...keeping this many edges from the other interior cones, and never nearer
  /// than narrow_cone_spacing quads (straight line: on a fine scan six edges are
  /// a quad or two).
  int cone_separation = 6;
  /// The cones steer the field's turn round every handle too (cross_field.h
  /// LoopTurns' handle rows): what the handles' trivial connection turns back, the
  /// seamless map can only take as shear (fertility: 10.7 -> 3.8 degrees in its
  /// first placement's map before quantization).
  bool steer_handles = true;
  /// Then valence-5 and valence-3 cones in pairs, at the highest and the lowest
  /// u, while less than this share of the area has the metric's quad size within
  /// [0.5, 2] x the size (0: no pairs)...
  double pair_band_goal = 0.95;
  /// ...or a quad size somewhere above this many times the size.
  double pair_largest = 3.0;
  /// A pair (or a cap) that betters neither the share in the band nor the largest
  /// quad of the best set so far ends the pairs, unless that set has less than
  /// pair_patience_below of the area in the band: then up to pair_patience more
  /// go in before the best set is taken back. The first pairs toward the largest
  /// quads can make the sizes worse before the next ones make them better (a scan
  /// of a kitten cut with three holes: 65% of the area in the band, 58% after the
  /// first pair, then 63%, 73%, ... 90%; the 45-degree gusset's first placement
  /// 83% -> 60% -> 92%).
  int pair_patience = 2;
  double pair_patience_below = 0.9;
  /// Where the quads are above pair_largest x the size in a region away from the
  /// boundary that lacks two quarter turns or more (protrusion_caps.h: an ear, a
  /// stub), the pairs go in that many at once, each valence-3 cone at the lowest u
  /// in the region (and a valence-5 one at the highest u), and stay there while the
  /// other cones settle: one pair at a time, the settling moved each cap cone out
  /// again (pig's ears, bunny-open's).
  bool protrusion_caps = false;
  /// A convex rounded corner a few quads in radius, which is no corner at the
  /// quad scale (fillet_corners.h), gets its quarter turn from a valence-3 cone
  /// beside it, at the vertex that may take a cone nearest the middle of its arc,
  /// placed before the greedy ones and kept there while the others settle. A
  /// concave fillet gets none: the quads round it grow away from the arc as a
  /// polar grid's do, which the metric gives without a cone (a valence-5 cone
  /// beside each of the U-channel plate's two concave fillets took its metric
  /// from 90% of the area in the band to 13%).
  bool fillet_cones = false;
  /// A placement whose metric leaves less than this share of the area with its
  /// quad size within [0.5, 2] x the size is refused (qm::Error, unsupported)
  /// rather than mapped: its quads cannot come near the band, and on a large scan
  /// a map costs seconds (bunny-open's ears: 41-52% of the area, quads up to 3400 x
  /// the size). The placements kept on the shared meshes and examples have 85-100%,
  /// pig's tried ones 57-93%. 0: every placement is mapped.
  double min_metric_band = 0.55;
  /// ...or that leaves quads somewhere above this many times the size (0: no bound).
  double max_metric_largest = 0;
  /// A placement whose metric leaves at least min_metric_band but less than this
  /// share in the band is not mapped either, and is not asked whether a protrusion
  /// lacks its caps' cones (its sizes spread over the part, not off at a cap: the
  /// caps tried for such a placement dropped the squared holes a channel's bolt
  /// holes needed). Of the 168 placements mapped on the shared meshes, examples,
  /// parts and scan cuts at 1.5% before this bound, the 39 kept had 93-100%; none
  /// under 85% gave sound quads with 90% of them in the band (the metric's share is
  /// by area, the band's by quads: up to 16 points apart, the Z-plate's 79% -> 95%,
  /// its corners wrong). Not mapping them left every one of those results the same
  /// and cost less (a square flange 2.6 s -> 1.8 s). 0: no such bound.
  double mapped_metric_band = 0.85;
  /// Then the interior cones move, a ring at a time, while the quad sizes spread
  /// less (the area-weighted variance of the log scale u), for at most this many
  /// sweeps (0: they stay)...
  int size_relaxation_passes = 10;
  /// ...keeping the loops' turns within this (radians, summed) of whole quarter
  /// turns, or no worse than they were.
  double relaxation_alignment_slack = 0.02;
  /// No interior cone within avoided_radius quads of these points (3D): where an
  /// earlier map of the same placement wound round a cone a turn short
  /// (cone_winding.h), so that the cone goes elsewhere.
  std::vector<Vec3> avoided_points;
  double avoided_radius = 0.75;
  /// Not the placement's own: where its map folds round cones it winds round a
  /// turn short, the route places it again with those avoided (at most twice).
  bool place_again_where_folded = false;
  /// Not the placement's own: the order the seamless map of these cones rounds its
  /// values in (seamless_map.h), so that a route can try the placements again in
  /// the other order.
  RoundingOrder rounding = RoundingOrder::cones_first;
};

/// place_cones' refusal of a placement without protrusion_caps whose metric
/// leaves a protrusion's cap lacking two quarter turns or more (protrusion_caps.h:
/// the quads grow exponentially towards an ear's tip, bunny-open's 2300-3400 x the
/// size): no placement without the caps takes those turns, so a route may go to
/// the capped ones at once.
class UncappedProtrusion : public Error {
 public:
  using Error::Error;
};

/// The corner cones for quads of edge `size` (> 0): the corners of the boundary
/// at the quad scale (boundary_corners.h, a window of corner_window_quads x size),
/// each in corner_quads_wanted quads (the quality module counts the same corners).
std::vector<Cone> corner_cones(const TriangleSoup& soup, double size, const ConePlacementOptions& options = {});

/// The corner cones and the interior cones that Gauss-Bonnet demands after them,
/// for quads of edge `size` (> 0). Throws qm::Error (unsupported) when no interior
/// vertex is far enough from the boundary to take a cone, or when the cones'
/// metric leaves the sizes off (min_metric_band, max_metric_largest; an
/// UncappedProtrusion when that is an uncapped protrusion's doing).
std::vector<Cone> place_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, double size,
                              const ConePlacementOptions& options = {});

/// The same on `solver`'s surface with its metrics, which it keeps (cone_metric.h):
/// placements made one after another on one surface, each like the last up to a
/// point (a placement made again away from some cones), solve what they share once.
std::vector<Cone> place_cones(const ConeMetricSolver& solver, double size, const ConePlacementOptions& options = {});

}  // namespace qm
