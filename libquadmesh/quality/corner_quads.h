// The quads at the input's corners (issue 18): a convex CAD corner of 60-120
// degrees wants exactly one quad, a concave one of 240-300 degrees exactly three;
// in general a boundary vertex of interior angle a wants max(1, round(a / 90 deg))
// quads (method.md section 11: a boundary cone of q quads has image angle q pi/2).
// The corners are taken from the reference surface (the input), not from the quad
// mesh, so that a corner the quads round off, or split into two 45-degree quads,
// counts as wrong.
#pragma once

#include "libquadmesh/cones/boundary_corners.h"
#include "libquadmesh/core/triangle_soup.h"
#include "libquadmesh/quality/quad_quality.h"

#include <cstddef>
#include <vector>

namespace qm {

/// The ranges the acceptance names, degrees: one quad, three quads.
constexpr double convex_corner_low_deg = 60.0, convex_corner_high_deg = 120.0;
constexpr double concave_corner_low_deg = 240.0, concave_corner_high_deg = 300.0;

/// A quad point counts as at a corner when it is within this share of its own
/// shortest boundary edge from it.
constexpr double corner_match_share = 0.25;

struct CornerCount {
  Vec3 position = Vec3::Zero();  ///< the reference's corner vertex
  double angle_deg = 0;          ///< its interior angle on the reference
  int quads_wanted = 0;          ///< max(1, round(angle / 90))
  int quads = 0;                 ///< quads at the quad point on the corner; 0 when no quad point is there
};

struct CornerQuads {
  std::size_t convex = 0;         ///< corners of 60-120 degrees
  std::size_t convex_wrong = 0;   ///< of those, not in exactly one quad
  std::size_t concave = 0;        ///< corners of 240-300 degrees
  std::size_t concave_wrong = 0;  ///< of those, not in exactly three quads
  std::size_t other = 0;          ///< the other corners (e.g. 30 or 150 degrees)
  std::size_t other_wrong = 0;    ///< of those, not in max(1, round(angle / 90)) quads
  std::vector<CornerCount> corners;  ///< every corner, in the reference's vertex order
};

/// The corners of `reference` at the scale of half a quad (boundary_corners):
/// of `quad_size` when it is > 0 (the requested size, the one the cone
/// placement sees corners at), else of the mean edge of `mesh`; and the quads of
/// `mesh` at each: the faces around the
/// boundary point of `mesh` nearest to the corner, if it is within
/// corner_match_share of its shortest boundary edge, else none (quads = 0).
/// Precondition: `reference` is a manifold triangle surface.
CornerQuads corner_quads(const PolygonMesh& mesh, const TriangleSoup& reference, double quad_size = 0);

}  // namespace qm
