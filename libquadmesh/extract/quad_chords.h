// Chords of a quad mesh and their splitting: local refinement that adds no
// irregular vertex (beyond the method: size adaptivity without new singularities).
//
// A chord (dual strip, "sheet") is the sequence of quads met by walking from a quad
// across a pair of its opposite edges, then across the opposite edge of every quad
// entered, until the walk leaves through the boundary or comes back. Direction 0 of
// quad (v0, v1, v2, v3) crosses its edges v0v1 and v2v3, direction 1 crosses v1v2
// and v3v0. A chord may cross a quad twice (once each way) near a singular vertex.
//
// Splitting a chord cuts every quad it crosses in two along the line joining the
// midpoints of the crossed edges (a quad crossed both ways by split chords is cut in
// four). Every new vertex is regular: an edge midpoint has valence 4 inside and 3 on
// the boundary, a quad centre has valence 4. The irregular vertices, the Euler
// characteristic, the boundary loops and the orientation are those of the input.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace qm {

using Quad = std::array<int, 4>;  ///< counter-clockwise corners

struct QuadChords {
  /// per quad and direction (0: across edges 0 and 2, 1: across edges 1 and 3), the chord
  std::vector<std::array<int, 2>> chord_of;
  /// per chord, how many (quad, direction) crossings it has
  std::vector<int> length;
  /// per chord, whether it ends on the boundary (an open strip) rather than closing up
  std::vector<char> open;
};

/// The chords of a conforming, edge-manifold quad mesh (an interior edge is shared
/// by exactly two quads). Precondition: corners index points 0..n-1.
QuadChords quad_chords(const std::vector<Quad>& quads);

/// A point that splitting creates: the midpoint of edge (a, b) (a < b), or the
/// centre of input quad `quad` (a = b = -1).
struct SplitPoint {
  int a = -1, b = -1;
  int quad = -1;
  bool boundary = false;  ///< the edge is a boundary edge of the mesh
};

struct SplitQuads {
  std::vector<Quad> quads;         ///< corners < point_count: old points; above: new_points
  std::vector<SplitPoint> new_points;  ///< point point_count + i is new_points[i]
};

/// Splits the chords with split[c] != 0. `point_count`: the number of points of the
/// input (new points are numbered from it). Orientation is kept.
SplitQuads split_chords(const std::vector<Quad>& quads, int point_count, const QuadChords& chords,
                        const std::vector<char>& split);

}  // namespace qm
