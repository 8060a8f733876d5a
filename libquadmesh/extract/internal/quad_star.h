// The quads around each point of a quad mesh, and the moves of its points on S
// that the smoothing and fitting stages try and may undo (quad_smoothing.h,
// quad_angle_smoothing.h, quad_fitting.h). None of them changes the quads'
// structure, so the quads around a point are computed once.
#pragma once

#include "libquadmesh/extract/lattice_quads.h"

#include <utility>
#include <vector>

namespace qm {

/// Per point of `quads`, the quads holding it (indices into quads.quads, ascending).
struct QuadStar {
  const LatticeQuads& quads;  ///< the structure described (its points may move; its quads may not change)
  std::vector<std::vector<int>> quads_at;

  explicit QuadStar(const LatticeQuads& q);

  /// The quads sharing a point with a quad at v (those at v included), ascending.
  std::vector<int> ring(int v) const;

  /// A regular interior corner: on no boundary of S (`boundary_loop_of_point[v] < 0`)
  /// and in four quads. Only those move: the boundary points stay on S's boundary,
  /// and the singular vertices on the lattice points at the zeros.
  bool regular_interior(std::size_t v, const std::vector<int>& boundary_loop_of_point) const {
    return boundary_loop_of_point[v] < 0 && quads_at[v].size() == 4;
  }
};

/// The moves of points of `quads` on S, with where each point started, so that
/// one point or all of them can go back.
class PointMoves {
 public:
  /// Remembers `quads` as they are (the original places); `quads` must outlive this.
  explicit PointMoves(LatticeQuads& quads);

  /// Point v to `to` (a point of S and its location there).
  void move(std::size_t v, const std::pair<Vec3, SurfaceLocation>& to);
  /// Point v back where it started.
  void put_back(std::size_t v);
  /// Every point back where it started.
  void undo_all();

  const LatticeQuads& original() const { return original_; }
  bool moved(std::size_t v) const { return moved_[v] != 0; }
  std::size_t count() const;  ///< points moved (and not put back)

 private:
  LatticeQuads& quads_;
  const LatticeQuads original_;
  std::vector<char> moved_;
};

}  // namespace qm
