#include "io/gmsh_nodes.h"

#include "libquadmesh/core/error.h"

#include <fmt/format.h>
#include <gmsh.h>

namespace qm::io {

GmshNodes::GmshNodes(std::string path) : path_(std::move(path)) {
  std::vector<std::size_t> tags;
  std::vector<double> params;
  gmsh::model::mesh::getNodes(tags, coords_, params, -1, -1, false, false);
  slot_.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) slot_.emplace(tags[i], i);
}

int GmshNodes::use(std::size_t tag, std::vector<Vec3>& points, std::vector<std::int64_t>* labels) {
  const auto found = used_.find(tag);
  if (found != used_.end()) return found->second;
  const auto slot = slot_.find(tag);
  if (slot == slot_.end())
    throw Error(ErrorCode::bad_input,
                fmt::format("{}: an element refers to node {}, which the file does not define", path_, tag));
  const std::size_t s = slot->second;
  const int index = static_cast<int>(points.size());
  points.emplace_back(coords_[3 * s], coords_[3 * s + 1], coords_[3 * s + 2]);
  if (labels) labels->push_back(static_cast<std::int64_t>(tag));
  used_.emplace(tag, index);
  return index;
}

}  // namespace qm::io
