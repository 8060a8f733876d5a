#include "libquadmesh/extract/size_refinement.h"

#include "libquadmesh/core/error.h"
#include "libquadmesh/extract/internal/chord_split_round.h"
#include "libquadmesh/quality/internal/triangle_tree.h"
#include "libquadmesh/quality/size_band.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace qm {

SizeRefinementReport refine_to_size(const TriangleSoup& surface, const SurfaceAdjacency& adjacency,
                                    LatticeQuads& quads, std::vector<int>& boundary_loop_of_point,
                                    const SizeRefinementOptions& options) {
  QM_ASSERT(options.size > 0);
  QM_ASSERT(boundary_loop_of_point.size() == quads.points.size());
  SizeRefinementReport report;
  const QuadMeasure ratios = [&](const LatticeQuads& q) { return quad_size_ratios(polygon_mesh(q), options.size); };
  const auto largest = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  };
  std::vector<double> values = ratios(quads);
  report.max_ratio_before = largest(values);
  const std::size_t start = quads.quads.size();
  const TriangleTree index(surface.points, surface.triangles);
  const ChordPointPlacement placement(surface, adjacency, index);
  const auto at_start = inverted_quad_count(quads);
  std::size_t inverted = at_start.first;
  const double jacobian_floor = std::min(at_start.second, options.min_scaled_jacobian);
  std::vector<std::pair<int, int>> crossings;
  for (int round = 0; round < options.max_rounds && largest(values) > options.max_ratio; ++round) {
    const std::optional<std::size_t> chosen = split_chord_round_or_undo(
        placement, ratios, quads, boundary_loop_of_point, values, options.max_ratio,
        std::numeric_limits<std::size_t>::max(), {}, std::numeric_limits<std::size_t>::max(), crossings, inverted,
        jacobian_floor);
    if (!chosen) {
      ++report.rounds_undone;
      break;
    }
    if (*chosen == 0) break;
    report.chords_split += *chosen;
    ++report.rounds;
  }
  report.max_ratio_after = largest(values);
  report.quads_added = quads.quads.size() - start;
  return report;
}

}  // namespace qm
