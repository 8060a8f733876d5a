// The parts of an assembly: what `quadmesh mesh --each-component` meshes one by
// one. A part is a connected set of triangles (sharing a point, as in
// connected_components) that lie in one CAD physical surface group; triangles in
// no group form parts by connectivity alone.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <string>
#include <vector>

namespace qm {

struct SurfacePart {
  /// The physical surface group's name (its tag as "surface_group_T" when it has
  /// none); "NAME_k" (k from 1) when the group falls into several connected sets;
  /// "part_k" (k from 1, in order of first triangle) for triangles in no group.
  std::string name;
  std::vector<int> triangles;  ///< indices into the soup, in input order
};

/// The soup's parts, in order of their first triangle. A triangle whose label is
/// in several physical surface groups belongs to the first of them (the group
/// order of soup.cad.surface_groups). Every triangle is in exactly one part.
std::vector<SurfacePart> surface_parts(const TriangleSoup& soup);

/// The soup restricted to the part's triangles (labels and CAD curves kept,
/// unused points dropped): the part as an input of its own.
TriangleSoup part_soup(const TriangleSoup& soup, const SurfacePart& part);

}  // namespace qm
