#include "libquadmesh/topology/surface_parts.h"

#include "libquadmesh/core/internal/union_find.h"
#include "libquadmesh/topology/internal/soup_cleaning.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <tuple>
#include <unordered_map>

namespace qm {

namespace {

/// The physical surface group of every triangle (index into
/// soup.cad.surface_groups), -1 for none.
std::vector<int> group_of_triangles(const TriangleSoup& soup) {
  std::unordered_map<std::int64_t, int> group_of_label;
  for (std::size_t g = 0; g < soup.cad.surface_groups.size(); ++g)
    for (std::int64_t e : soup.cad.surface_groups[g].elements) group_of_label.emplace(e, static_cast<int>(g));
  std::vector<int> group(soup.triangles.size(), -1);
  if (group_of_label.empty()) return group;
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    const auto it = group_of_label.find(soup.triangle_label(static_cast<int>(f)));
    if (it != group_of_label.end()) group[f] = it->second;
  }
  return group;
}

std::string group_name(const PhysicalSurfaceGroup& g) {
  return g.name.empty() ? fmt::format("surface_group_{}", g.tag) : g.name;
}

}  // namespace

std::vector<SurfacePart> surface_parts(const TriangleSoup& soup) {
  const std::vector<int> group = group_of_triangles(soup);
  // triangles that share a point and a group are in one part
  std::vector<std::tuple<int, int, int>> corners;  // (point, group, triangle)
  corners.reserve(3 * soup.triangles.size());
  for (std::size_t f = 0; f < soup.triangles.size(); ++f)
    for (int p : soup.triangles[f]) corners.emplace_back(p, group[f], static_cast<int>(f));
  std::sort(corners.begin(), corners.end());
  UnionFind sets(soup.triangles.size());
  for (std::size_t k = 1; k < corners.size(); ++k)
    if (std::get<0>(corners[k]) == std::get<0>(corners[k - 1]) &&
        std::get<1>(corners[k]) == std::get<1>(corners[k - 1]))
      sets.unite(std::get<2>(corners[k]), std::get<2>(corners[k - 1]));
  std::vector<int> label;
  const int count = sets.labels(label);

  std::vector<SurfacePart> parts(static_cast<std::size_t>(count));
  std::vector<int> part_group(static_cast<std::size_t>(count), -1);
  for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
    parts[static_cast<std::size_t>(label[f])].triangles.push_back(static_cast<int>(f));
    part_group[static_cast<std::size_t>(label[f])] = group[f];
  }
  // names: the group's, numbered when the group has several parts
  std::map<int, int> parts_of_group, seen_of_group;
  for (int g : part_group) ++parts_of_group[g];
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const int g = part_group[p];
    const int k = ++seen_of_group[g];
    if (g < 0)
      parts[p].name = fmt::format("part_{}", k);
    else if (parts_of_group[g] == 1)
      parts[p].name = group_name(soup.cad.surface_groups[static_cast<std::size_t>(g)]);
    else
      parts[p].name = fmt::format("{}_{}", group_name(soup.cad.surface_groups[static_cast<std::size_t>(g)]), k);
  }
  return parts;
}

TriangleSoup part_soup(const TriangleSoup& soup, const SurfacePart& part) {
  return sub_soup(soup, part.triangles);
}

}  // namespace qm
