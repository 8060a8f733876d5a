#include "libquadmesh/quality/size_band.h"

#include "libquadmesh/core/error.h"

#include <algorithm>
#include <limits>

namespace qm {

std::vector<double> quad_size_ratios(const PolygonMesh& mesh, double target) {
  QM_ASSERT(target > 0);
  std::vector<double> ratios;
  ratios.reserve(mesh.faces.size());
  for (const auto& face : mesh.faces) {
    if (face.size() != 4) continue;
    double perimeter = 0;
    for (std::size_t k = 0; k < 4; ++k)
      perimeter += (mesh.points[static_cast<std::size_t>(face[(k + 1) % 4])] - mesh.points[static_cast<std::size_t>(face[k])]).norm();
    ratios.push_back(perimeter / 4 / target);
  }
  return ratios;
}

SizeBand scaled_size_band(const std::vector<double>& ratios, double factor) {
  SizeBand band;
  band.quads = ratios.size();
  if (ratios.empty()) {
    band.share_in_band = band.min_ratio = band.max_ratio = std::numeric_limits<double>::quiet_NaN();
    return band;
  }
  std::size_t inside = 0;
  band.min_ratio = std::numeric_limits<double>::infinity();
  for (double r : ratios) {
    const double ratio = r * factor;
    inside += ratio >= size_band_low && ratio <= size_band_high;
    band.max_ratio = std::max(band.max_ratio, ratio);
    band.min_ratio = std::min(band.min_ratio, ratio);
  }
  band.share_in_band = static_cast<double>(inside) / static_cast<double>(band.quads);
  return band;
}

SizeBand quad_size_band(const PolygonMesh& mesh, double target) { return scaled_size_band(quad_size_ratios(mesh, target), 1.0); }

bool in_size_band(const SizeBand& band) {
  return band.share_in_band >= size_band_goal && band.max_ratio <= size_ratio_limit;
}

}  // namespace qm
