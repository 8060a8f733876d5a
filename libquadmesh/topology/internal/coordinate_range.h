// Where the input's coordinates lie, against the range the method computes in
// (method.md section 0). The cotangent Laplacian divides by triangle areas and the
// forms integrate edge vectors: a model scaled by 1e100 or 1e-100 overflows or
// underflows there (measured on kitten-2holes: scales 1e-30 to 1e50 mesh, 1e-100
// and 1e100 fail to factor), and coordinates far from the model's own size lose
// the digits its edges are made of. Inputs outside these limits are refused with
// their figures rather than meshed into garbage.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

namespace qm {

/// No coordinate may be larger than this in magnitude.
inline constexpr double kMaxCoordinate = 1e15;
/// The model's bounding-box diagonal may not be smaller than this.
inline constexpr double kMinModelSize = 1e-12;
/// No coordinate may be larger than this many times the model's diagonal (a part
/// far from the origin keeps about 16 - 9 = 7 digits of its own size).
inline constexpr double kMaxOffsetRatio = 1e9;

struct CoordinateRange {
  int largest_vertex = -1;        ///< the point with the largest coordinate magnitude (-1: no finite point)
  double largest_magnitude = 0;   ///< that magnitude
  double diagonal = 0;            ///< bounding-box diagonal of the finite points (inf if it overflows)
};

/// The finite points' largest coordinate and bounding-box diagonal (non-finite
/// points are left to nonfinite_points()). Never overflows on finite input below
/// kMaxCoordinate; above it the diagonal may be inf.
CoordinateRange coordinate_range(const TriangleSoup& soup);

}  // namespace qm
