#include "libquadmesh/quality/size_band.h"

#include "libquadmesh/core/error.h"

#include <algorithm>
#include <limits>

namespace qm {

SizeBand quad_size_band(const PolygonMesh& mesh, double target) {
  QM_ASSERT(target > 0);
  SizeBand band;
  std::size_t inside = 0;
  band.min_ratio = std::numeric_limits<double>::infinity();
  for (const auto& face : mesh.faces) {
    if (face.size() != 4) continue;
    double perimeter = 0;
    for (std::size_t k = 0; k < 4; ++k)
      perimeter += (mesh.points[static_cast<std::size_t>(face[(k + 1) % 4])] - mesh.points[static_cast<std::size_t>(face[k])]).norm();
    const double ratio = perimeter / 4 / target;
    ++band.quads;
    inside += ratio >= size_band_low && ratio <= size_band_high;
    band.max_ratio = std::max(band.max_ratio, ratio);
    band.min_ratio = std::min(band.min_ratio, ratio);
  }
  band.share_in_band = band.quads ? static_cast<double>(inside) / static_cast<double>(band.quads)
                                  : std::numeric_limits<double>::quiet_NaN();
  if (!band.quads) band.min_ratio = band.max_ratio = std::numeric_limits<double>::quiet_NaN();
  return band;
}

}  // namespace qm
