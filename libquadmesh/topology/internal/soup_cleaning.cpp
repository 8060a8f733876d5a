#include "libquadmesh/topology/internal/soup_cleaning.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace qm {

namespace {
bool is_finite(const Vec3& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}
bool has_repeated_corner(const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }
}  // namespace

std::size_t drop_unreferenced_points(TriangleSoup& soup) {
  std::vector<int> new_index(soup.points.size(), -1);
  for (const Triangle& t : soup.triangles)
    for (int p : t) new_index[p] = 0;
  int next = 0;
  for (int& i : new_index)
    if (i == 0) i = next++;
  const std::size_t dropped = soup.points.size() - static_cast<std::size_t>(next);
  if (dropped == 0) return 0;
  std::vector<Vec3> points(static_cast<std::size_t>(next));
  std::vector<std::int64_t> labels(static_cast<std::size_t>(next));
  for (std::size_t i = 0; i < new_index.size(); ++i) {
    if (new_index[i] < 0) continue;
    points[new_index[i]] = soup.points[i];
    labels[new_index[i]] = soup.point_label(static_cast<int>(i));
  }
  for (Triangle& t : soup.triangles)
    for (int& p : t) p = new_index[p];
  for (CurveEdge& ce : soup.cad.edges) {
    ce.a = new_index[ce.a];
    ce.b = new_index[ce.b];
  }
  soup.cad.edges.erase(std::remove_if(soup.cad.edges.begin(), soup.cad.edges.end(),
                                      [](const CurveEdge& ce) { return ce.a < 0 || ce.b < 0; }),
                       soup.cad.edges.end());
  soup.points = std::move(points);
  soup.point_labels = std::move(labels);
  return dropped;
}

std::vector<int> nonfinite_points(const TriangleSoup& soup) {
  std::vector<int> bad;
  for (std::size_t i = 0; i < soup.points.size(); ++i)
    if (!is_finite(soup.points[i])) bad.push_back(static_cast<int>(i));
  return bad;
}

std::vector<int> repeated_corner_triangles(const TriangleSoup& soup) {
  std::vector<int> bad;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    if (has_repeated_corner(soup.triangles[f])) bad.push_back(static_cast<int>(f));
  return bad;
}

std::vector<int> zero_area_triangles(const TriangleSoup& soup) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  auto point = [&](int i) {
    const Vec3& p = soup.points[i];
    return K::Point_3(p.x(), p.y(), p.z());
  };
  std::vector<int> bad;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const Triangle& t = soup.triangles[f];
    if (has_repeated_corner(t)) continue;
    if (!is_finite(soup.points[t[0]]) || !is_finite(soup.points[t[1]]) ||
        !is_finite(soup.points[t[2]]))
      continue;
    if (CGAL::collinear(point(t[0]), point(t[1]), point(t[2]))) bad.push_back(static_cast<int>(f));
  }
  return bad;
}

std::vector<int> duplicate_triangles(const TriangleSoup& soup) {
  std::vector<std::pair<Triangle, int>> sorted;
  sorted.reserve(soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    Triangle t = soup.triangles[f];
    std::sort(t.begin(), t.end());
    sorted.push_back({t, static_cast<int>(f)});
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<int> duplicates;
  for (std::size_t i = 1; i < sorted.size(); ++i)
    if (sorted[i].first == sorted[i - 1].first) duplicates.push_back(sorted[i].second);
  std::sort(duplicates.begin(), duplicates.end());
  return duplicates;
}

TriangleSoup sub_soup(const TriangleSoup& soup, const std::vector<int>& triangles) {
  TriangleSoup out;
  out.points = soup.points;
  out.point_labels.resize(soup.points.size());
  for (std::size_t i = 0; i < soup.points.size(); ++i)
    out.point_labels[i] = soup.point_label(static_cast<int>(i));
  out.cad = soup.cad;
  for (int f : triangles) {
    out.triangles.push_back(soup.triangles[f]);
    out.triangle_labels.push_back(soup.triangle_label(f));
  }
  drop_unreferenced_points(out);
  return out;
}

}  // namespace qm
