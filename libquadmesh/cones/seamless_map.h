// The seamless map with rotational transitions (method.md section 11; cf. MIQ
// [Bommes, Zimmer, Kobbelt 2009], QGP [Campen, Bommes, Kobbelt 2015]): the map W
// whose gradient fits the cone metric's scaled frame,
//   minimize  sum_f  area_f | dW - e^(u_f - i angle_f) / h |^2     (per triangle),
// with one value per wedge (cut_graph.h) and, across every cut edge from triangle f
// to its twin g, the transition W_g = i^q W_f + t (q from the cross field);
// boundary edges along one axis (Im W or Re W constant on them). Quantization then
// makes the map an integer-grid map: greedily, the value nearest to an integer is
// fixed to it and the map solved again, until every cone sits on a lattice point,
// every translation t is a Gaussian integer and every boundary segment lies on an
// integer line. The constraints are kept by a stiff penalty (relative residual
// about 1e-9), which also makes redundant ones harmless. Triangles the quantized
// map folds are then stiffened (their weight, and their neighbours', raised) and
// the map solved again, until none is folded [Bommes, Zimmer, Kobbelt 2009].
#pragma once

#include "libquadmesh/cones/cut_graph.h"
#include "libquadmesh/cones/map_ordering.h"
#include "libquadmesh/cones/tip_shear.h"
#include "libquadmesh/core/stop_request.h"
#include "libquadmesh/param/face_map.h"

#include <optional>

namespace qm {

struct SeamlessMapReport {
  std::size_t integer_values = 0;   ///< values made integer by quantization
  std::size_t solves = 0;           ///< linear solves, the first one included
  double max_seam_residual = 0;     ///< largest constraint residual (lattice units)
  double max_rounding = 0;          ///< largest distance a value was moved to its integer
  std::size_t inverted_triangles = 0;  ///< image area <= 0
  int stiffening_rounds = 0;        ///< re-solves with folded triangles weighing more
  std::size_t factorizations = 0;   ///< numeric factorizations of the system
  /// of them, those ordered by nested dissection (map_ordering.h)
  std::size_t nested_dissection_factorizations = 0;
  /// the rounding's columns H0^-1 e_v (low_rank_columns.h), and the back-substitutions
  /// that computed them
  std::size_t low_rank_columns = 0;
  std::size_t low_rank_column_solves = 0;
  /// updates of the factorization in place (OrderedCholesky::update): the
  /// rounding's fixes, 64 at a time, and the stiffening's rounds
  std::size_t factorization_updates = 0;
  /// the stiffening stopped where its folds grew past their fewest round an interior
  /// cone the map winds a turn short (cone_winding.h): it was losing
  bool stiffening_lost = false;
  /// roundings that took the next integer, not the nearest, to keep two corners off
  /// one lattice point (cones/internal/boundary_segments.h) or a value the integers
  /// determine off a half or a quarter
  std::size_t other_integers = 0;
  /// maps quantized again from chosen lattice offsets, where the first folded
  /// round a cone it winds a turn short (cone_map.h; set by cone_map)
  int lattice_shifts = 0;
  /// boundary segments between corners whose target is under 1.5 quads
  /// (boundary_segments.h short_segments), and of them those held to one quad in
  /// the fit (`hold_short_segments`; cone_map.h maps a folded map again so)
  std::size_t short_segments = 0;
  std::size_t segments_held = 0;
};

/// The order the quantization makes values integer in, phase by phase. The cones'
/// positions first, then the boundary lines, then the cut translations: a
/// translation ending at a cone is (1 - i^q) times its position, integer once the
/// position is. The translations first, then the cones, then the lines: where the
/// cones and lines rounded first leave the translations (and so the boundary
/// segments a cut ends in) far from their fit and the map folds (fertility's
/// coarse hole polygons: half of its boundary segments more than a quad off).
enum class RoundingOrder { cones_first, translations_first };

/// Per triangle corner, the value of the wedge it belongs to. `u` from
/// cone_metric, `size` the target quad edge in the surface's units (> 0); `shape`,
/// when given, what the fit asks of the gradient beside the scaled frame (the
/// acute tips' shear, tip_shear.h). The fit leaves the map's translation free,
/// and the quantization starts from wherever the first solve's round-off puts it;
/// with `lattice_shift` (lattice units) the map is first moved to the translation
/// that brings the values made integer nearest to integers (their circular mean
/// per axis) plus the shift: the same cones quantized from a chosen offset of the
/// lattice (cone_map.h tries some where the map folds round a cone).
/// With `stop`, asked before each solve: Stopped is thrown when it says so.
/// `ordering`: the cone set's shared ordering (the map's own when null). Where it
/// orders by nested dissection, a map without `lattice_shift` is still first
/// factored in the minimum degree ordering: the first solve's round-off gives the
/// translation the quantization starts from, as it always has (afterwards the
/// values fixed hold it, and the ordering moves only the round-off).
/// With `hold_short_segments`, every boundary segment whose target is under 1.5
/// quads (boundary_segments.h short_segments) is held to one quad in the fit
/// itself, a row of the system beside the seams' rows, not only kept from 0 by the
/// rounding: where the fit alone crosses such a segment, no rounding mends it
/// (bunny-open-large's first solve put a segment of 0.6 quads at -0.44, which the
/// rounding then made -2). The rows change the system's pattern: such a map takes
/// no `ordering` shared with maps without them.
/// Throws qm::Error (solver) when the system cannot be factored.
FaceMap seamless_map(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const Eigen::VectorXd& u,
                     const CrossField& field, const CutGraph& cut, const std::vector<int>& quads, double size,
                     SeamlessMapReport& report, RoundingOrder order = RoundingOrder::cones_first,
                     const FitShape* shape = nullptr, std::optional<Complex> lattice_shift = std::nullopt,
                     const StopRequest& stop = {}, MapOrdering* ordering = nullptr,
                     bool hold_short_segments = false);

}  // namespace qm
