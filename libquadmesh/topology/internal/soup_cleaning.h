// Element-level checks and clean-ups of a triangle soup that need no adjacency.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <vector>

namespace qm {

/// Removes points no triangle uses, keeping labels; returns how many were dropped.
std::size_t drop_unreferenced_points(TriangleSoup& soup);

/// Points with a NaN or infinite coordinate.
std::vector<int> nonfinite_points(const TriangleSoup& soup);

/// Triangles that use one point twice (combinatorially degenerate).
std::vector<int> repeated_corner_triangles(const TriangleSoup& soup);

/// Triangles with three distinct but collinear points: zero area, decided
/// exactly (CGAL's filtered collinearity predicate). Triangles with non-finite
/// points or repeated corners are not tested.
std::vector<int> zero_area_triangles(const TriangleSoup& soup);

/// Triangles whose point set equals that of an earlier triangle (either
/// orientation); each duplicate is listed once, the first occurrence is not.
std::vector<int> duplicate_triangles(const TriangleSoup& soup);

/// The soup restricted to the given triangles, with unused points dropped.
TriangleSoup sub_soup(const TriangleSoup& soup, const std::vector<int>& triangles);

}  // namespace qm
