// A triangle of the soup in its own plane: the corners as complex numbers with
// corner 0 at 0 and corner 1 on the positive real axis, and the cotangents of its
// corner angles. The cone stages measure angles and lengths in these local frames.
#pragma once

#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/param/face_map.h"

#include <array>
#include <optional>

namespace qm {

/// Corners of triangle f in its local frame (counter-clockwise, the soup's order).
CornerValues local_corners(const TriangleSoup& soup, std::size_t f);

/// A 3D direction in triangle f's local frame (that of local_corners), projected
/// onto the triangle's plane and made unit; nothing when the triangle or the
/// projection is degenerate.
std::optional<Complex> local_direction(const TriangleSoup& soup, std::size_t f, const Vec3& direction);

/// cot of the angle at each corner of triangle f.
std::array<double, 3> corner_cotangents(const TriangleSoup& soup, std::size_t f);

}  // namespace qm
