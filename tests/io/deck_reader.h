// A reader of the solver decks quadmesh writes (.inp .bdf .unv), independent of
// the writer: what the deck tests check the files with.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace qm::test {

struct DeckElementRead {
  int id = 0;
  std::string type;
  std::vector<int> nodes;  ///< in the Gmsh / Abaqus order (.unv's perimeter order undone)
};

struct DeckRead {
  std::map<int, Vec3> nodes;
  std::vector<DeckElementRead> elements;
  std::map<std::string, std::vector<int>> node_sets;
  std::map<std::string, std::vector<std::pair<int, std::string>>> surfaces;  ///< (element, "S2")
  std::map<std::string, std::vector<int>> element_sets;
  int line_elements = 0;  ///< 1D elements (T3D2, CBAR, ...): a deck of ours has none
};

DeckRead read_inp(const std::string& path);
DeckRead read_bdf(const std::string& path);
DeckRead read_unv(const std::string& path);

/// The element's points, for the Jacobian.
std::vector<Vec3> element_points(const DeckRead& deck, const DeckElementRead& e);

}  // namespace qm::test
