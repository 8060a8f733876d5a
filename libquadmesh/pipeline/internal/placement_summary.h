// What a cone placement's progress line says of it: where its interior cones go,
// and what sets it apart from the plain placement at the same distances (the
// route may try twenty of them on one part: a user reading the progress, or a
// report's messages, tells each from the others).
#pragma once

#include "libquadmesh/cones/cone_placement.h"

#include <string>

namespace qm {

/// "corners, then the interior, B quads from the boundary and S apart", then, for
/// a placement that differs from the plain one in more than its distances, what
/// differs ("; no cone pairs, protrusions capped", ...); for the cross field's
/// placement "corners, then the smoothest cross field's singularities" (and what
/// differs). Two placements the route tries (cone_route.h: cone_placements,
/// fallback_placements, capped_placements, fillet_placements,
/// squared_hole_placements, cross_field_placement) never share a summary.
std::string placement_summary(const ConePlacementOptions& placement);

}  // namespace qm
