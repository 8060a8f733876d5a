// How a quantized cone map winds round its cones (method.md section 11; section 9
// for folds). A cone of n quads is a vertex whose image angle, the sum of the
// signed angles of its triangles' corners there, is n quarter turns. The seam
// rotations fix that angle only modulo a full turn: where the quantization moves a
// cone far from where its metric put it, its star can wind a full turn short (a
// valence-5 cone at one quarter turn), with a triangle folded flat across it and a
// vertex beside it winding a turn more once unfolded. No move of the vertices
// undoes that (measured on the folded maps of scripts/parts-check: untangled, 41 of
// 43 kept such a cone and put a branch point beside it): the cone has to go
// elsewhere. cone_route.cpp places such cones again away from there.
#pragma once

#include "libquadmesh/param/face_map.h"
#include "libquadmesh/param/internal/surface_adjacency.h"

#include <vector>

namespace qm {

/// The interior cones (quads[v] != 4 at a vertex off the boundary) of `map` whose
/// image angle differs from quads[v] quarter turns by more than an eighth of a
/// turn, in vertex order. `quads` per vertex (cone_set.h quads_per_vertex).
std::vector<int> misturned_cones(const TriangleSoup& soup, const SurfaceAdjacency& adjacency,
                                 const FaceMap& map, const std::vector<int>& quads);

}  // namespace qm
