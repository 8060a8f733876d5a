// After the quads are chosen and refined: their corners moved on S for shape and
// fidelity (extract/quad_smoothing.h, quad_fitting.h, quad_angle_smoothing.h).
#pragma once

#include "libquadmesh/pipeline/internal/stages.h"
#include "libquadmesh/pipeline/mesh_quads.h"

namespace qm {

/// Smooths the worst quads of `result` (extract/quad_smoothing.h), each point
/// moving at most half the requested size; returns what it did. The first step of
/// improve_quads; the cone route also runs it on a candidate with inverted or
/// flipped quads before judging it (cone_route.h), as the quads written would be.
QuadSmoothingReport smooth_worst(QuadMeshResult& result);

/// Smooths the worst quads (QuadMeshOptions::smoothing; a smoothing done before,
/// `best.smoothing`, is added to the report), fits the corners onto S
/// where the quads cut across it (with a tolerance, `best.max_deviation` > 0: when
/// refined, where the deviation is within reach; the cone route's quads unless it
/// judged them within the tolerance, `best.judged_deviation`),
/// then moves every regular interior corner towards right angles. The topology of
/// `best.quads` does not change. Once: sets `best.improved`, and does nothing when
/// it is set (the cone route improves its candidate to judge it as written).
void improve_quads(QuadMeshResult& best, const QuadMeshOptions& options, Stages& stages);

}  // namespace qm
