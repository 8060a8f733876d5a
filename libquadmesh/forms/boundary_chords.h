// Interior edges whose two ends lie on the boundary ("chords"; an ear's inner edge
// is one) would carry four triangles on the doubled surface, since both ends are
// shared by S+ and S-. Doubling needs none (method.md section 6: split ears first).
#pragma once

#include "libquadmesh/core/triangle_soup.h"

namespace qm {

/// Splits every chord at its midpoint (each of its two triangles into two), until
/// none is left; returns the number of splits. New points get label -1.
/// Precondition: the soup is an oriented manifold (a supported AnalyzedSurface's).
std::size_t split_boundary_chords(TriangleSoup& soup);

}  // namespace qm
