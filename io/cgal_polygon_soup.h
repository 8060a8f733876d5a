// Reading OBJ/OFF/PLY polygon soups with CGAL IO, quietly: CGAL's readers write
// their complaints to std::cerr, and quadmesh's callers speak with their own
// one-line errors instead.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <string>
#include <vector>

namespace qm::io {

struct PolygonSoup {
  std::vector<Vec3> points;
  std::vector<std::vector<std::size_t>> polygons;
};

/// False when CGAL cannot parse the file (nothing is printed).
bool read_cgal_polygon_soup(const std::string& path, PolygonSoup& soup);

}  // namespace qm::io
