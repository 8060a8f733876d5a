// The nodes of the model loaded in Gmsh, turned into points in order of first use
// (unreferenced nodes never become points). For the readers that go through Gmsh.
#pragma once

#include "libquadmesh/core/triangle_soup.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace qm::io {

class GmshNodes {
 public:
  /// Reads every node of the current Gmsh model; `path` is for messages.
  explicit GmshNodes(std::string path);
  /// The index of node `tag` among the used ones. On first use its coordinates are
  /// appended to `points` (and the tag to `labels`, when given). Throws
  /// qm::Error(bad_input) for a node the file does not define.
  int use(std::size_t tag, std::vector<Vec3>& points, std::vector<std::int64_t>* labels = nullptr);
  /// Node tag -> point index, for the nodes used so far.
  const std::unordered_map<std::size_t, int>& used() const { return used_; }

 private:
  std::string path_;
  std::vector<double> coords_;
  std::unordered_map<std::size_t, std::size_t> slot_;
  std::unordered_map<std::size_t, int> used_;
};

}  // namespace qm::io
