#include "io/cgal_polygon_soup.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <iostream>
#include <sstream>

namespace qm::io {

bool read_cgal_polygon_soup(const std::string& path, PolygonSoup& soup) {
  using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
  std::vector<Point> points;
  bool ok = false;
  std::ostringstream swallowed;
  std::streambuf* previous = std::cerr.rdbuf(swallowed.rdbuf());
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, soup.polygons);
  } catch (const std::exception&) {
    ok = false;
  }
  std::cerr.rdbuf(previous);
  soup.points.clear();
  for (const Point& p : points) soup.points.emplace_back(p.x(), p.y(), p.z());
  return ok;
}

}  // namespace qm::io
