#include "libquadmesh/pipeline/internal/placement_summary.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <vector>

namespace qm {

namespace {

/// What `p` does that the plain placement (ConePlacementOptions{}) does not, in
/// the order the route adds such placements.
std::vector<std::string> differences(const ConePlacementOptions& p) {
  std::vector<std::string> out;
  if (!(p.pair_band_goal > 0)) out.emplace_back("no cone pairs");
  if (!p.steer_handles) out.emplace_back("handles not steered");
  if (p.boundary_cones) out.emplace_back("cones on the boundary where the interior has no room");
  if (p.protrusion_caps) out.emplace_back("protrusions capped");
  if (p.fillet_cones) out.emplace_back("a cone beside each fillet");
  if (p.square_every_hole)
    out.emplace_back(std::isinf(p.square_hole_max_length)
                         ? std::string("every hole made a square however long")
                         : fmt::format("holes up to {:g} quads round made squares", p.square_hole_max_length));
  if (p.squares_face_frame) out.emplace_back("squares turned to the frame");
  if (!p.avoided_points.empty())
    out.emplace_back(fmt::format("away from {} cone{} a map folded round", p.avoided_points.size(),
                                 p.avoided_points.size() == 1 ? "" : "s"));
  return out;
}

}  // namespace

std::string placement_summary(const ConePlacementOptions& placement) {
  std::string out = placement.interior == InteriorCones::cross_field
                        ? std::string("corners, then the smoothest cross field's singularities")
                        : fmt::format("corners, then the interior, {:g} quads from the boundary and {:g} apart",
                                      placement.boundary_distance, placement.cone_spacing);
  const std::vector<std::string> more = differences(placement);
  if (!more.empty()) out += fmt::format("; {}", fmt::join(more, ", "));
  return out;
}

}  // namespace qm
