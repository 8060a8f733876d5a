// An integer-grid map with prescribed quarter-turn cones (method.md section 11),
// stage by stage: the cone set's Gauss-Bonnet check, the flat cone metric, its
// cross field, the cut through the cones, the seamless map and its quantization.
// The quads are then the map's lattice cells (extract/lattice_quads.h), with
// rotations across the cut.
#pragma once

#include "libquadmesh/cones/cone_metric.h"
#include "libquadmesh/cones/cone_set.h"
#include "libquadmesh/cones/loop_alignment.h"
#include "libquadmesh/cones/seamless_map.h"

namespace qm {

struct ConeMap {
  FaceMap map;
  std::vector<int> quads;  ///< per vertex, the quads it is meant to be in
  Eigen::VectorXd u;       ///< the cone metric's log scale per vertex
  CrossField field;
  CutGraph cut;
  SeamlessMapReport report;
  /// the interior cones the map winds round to another angle than their quads
  /// (cone_winding.h): where it folds, these have to move
  std::vector<int> misturned;
};

/// What the maps of the cone sets tried on one surface share, each part computed
/// at its first use and kept: the cone metric's factored Laplacian (cone placement
/// solves with it first) and the loop potentials of the cross field. Both on the
/// soup the map is made on (the same object); one thread at a time.
struct SurfaceSolvers {
  const ConeMetricSolver& metrics;
  LoopPotentials& potentials;
};

/// `size` the target quad edge (> 0); `order` the quantization's (seamless_map.h).
/// Throws qm::Error: bad_input when the cones
/// break Gauss-Bonnet or name no vertex; unsupported when a boundary loop cannot
/// be aligned with the field (several boundary loops need cones placed for it:
/// the placement stage); solver when a solve fails. With `stop`, asked before each
/// of its solves: Stopped (stop_request.h) when it says so.
/// With `shared`, its metric and potentials are those solvers' (the same bits as
/// made afresh). A map that folds round one cone it winds a turn short is
/// quantized again from other offsets of the lattice; one still folded, with
/// boundary segments under a quad and a half between corners, is made once more
/// with those held to one quad (seamless_map.h `hold_short_segments`); either is
/// kept where it folds less (report.lattice_shifts, report.segments_held).
ConeMap cone_map(const TriangleSoup& soup, const SurfaceAdjacency& adjacency, const std::vector<Cone>& cones,
                 double size, RoundingOrder order = RoundingOrder::cones_first, const StopRequest& stop = {},
                 const SurfaceSolvers* shared = nullptr);

}  // namespace qm
