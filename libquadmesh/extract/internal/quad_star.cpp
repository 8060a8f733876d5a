#include "libquadmesh/extract/internal/quad_star.h"

#include <algorithm>
#include <set>

namespace qm {

QuadStar::QuadStar(const LatticeQuads& q) : quads(q), quads_at(q.points.size()) {
  for (std::size_t k = 0; k < q.quads.size(); ++k)
    for (int v : q.quads[k]) quads_at[static_cast<std::size_t>(v)].push_back(static_cast<int>(k));
}

std::vector<int> QuadStar::ring(int v) const {
  std::set<int> out;
  for (int a : quads_at[static_cast<std::size_t>(v)])
    for (int u : quads.quads[static_cast<std::size_t>(a)])
      out.insert(quads_at[static_cast<std::size_t>(u)].begin(), quads_at[static_cast<std::size_t>(u)].end());
  return {out.begin(), out.end()};
}

PointMoves::PointMoves(LatticeQuads& quads)
    : quads_(quads), original_(quads), moved_(quads.points.size(), 0) {}

void PointMoves::move(std::size_t v, const std::pair<Vec3, SurfaceLocation>& to) {
  quads_.points[v] = to.first;
  quads_.locations[v] = to.second;
  moved_[v] = 1;
}

void PointMoves::put_back(std::size_t v) {
  quads_.points[v] = original_.points[v];
  quads_.locations[v] = original_.locations[v];
  moved_[v] = 0;
}

void PointMoves::undo_all() {
  quads_ = original_;
  std::fill(moved_.begin(), moved_.end(), 0);
}

std::size_t PointMoves::count() const {
  return static_cast<std::size_t>(std::count(moved_.begin(), moved_.end(), 1));
}

}  // namespace qm
