// Chords of a quad mesh and their splitting (extract/quad_chords.h): exact counts
// on grids, regular new vertices, the Euler characteristic and orientation kept.
#include "libquadmesh/extract/quad_chords.h"

#include <doctest/doctest.h>

#include <map>
#include <set>

using namespace qm;

namespace {

/// nx x ny unit squares, counter-clockwise; `periodic`: column nx is column 0 (a
/// cylinder, points nx * (ny + 1)).
std::vector<Quad> grid(int nx, int ny, bool periodic) {
  const int columns = periodic ? nx : nx + 1;
  auto id = [&](int i, int j) { return (i % columns) + columns * j; };
  std::vector<Quad> quads;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
  return quads;
}

struct Counts {
  int vertices = 0, edges = 0, boundary_edges = 0;
  std::map<int, int> valence;  ///< quads at each point
};

Counts counts(const std::vector<Quad>& quads) {
  Counts c;
  std::map<std::pair<int, int>, int> directed;
  std::set<int> points;
  for (const Quad& q : quads)
    for (int i = 0; i < 4; ++i) {
      points.insert(q[i]);
      ++c.valence[q[i]];
      ++directed[{q[i], q[(i + 1) % 4]}];
    }
  for (const auto& [e, n] : directed) {
    CHECK(n == 1);  // oriented: no directed edge used twice
    if (!directed.count({e.second, e.first})) ++c.boundary_edges;
  }
  c.vertices = static_cast<int>(points.size());
  c.edges = (static_cast<int>(directed.size()) + c.boundary_edges) / 2;
  return c;
}

int euler(const std::vector<Quad>& quads) {
  const Counts c = counts(quads);
  return c.vertices - c.edges + static_cast<int>(quads.size());
}

}  // namespace

TEST_CASE("chords of a 4 x 3 grid: 4 columns of 3 quads, 3 rows of 4, all open") {
  const std::vector<Quad> quads = grid(4, 3, false);
  const QuadChords c = quad_chords(quads);
  REQUIRE(c.length.size() == 7);
  std::multiset<int> lengths(c.length.begin(), c.length.end());
  CHECK(lengths == std::multiset<int>{3, 3, 3, 3, 4, 4, 4});
  for (char open : c.open) CHECK(open);
  // quad 0's direction 0 crosses its bottom and top edges: its column
  CHECK(c.length[static_cast<std::size_t>(c.chord_of[0][0])] == 3);
  CHECK(c.length[static_cast<std::size_t>(c.chord_of[0][1])] == 4);
  CHECK(c.chord_of[4][0] == c.chord_of[0][0]);  // quad (0, 1) is in column 0
  CHECK(c.chord_of[1][1] == c.chord_of[0][1]);  // quad (1, 0) is in row 0
}

TEST_CASE("splitting a column, then a row and a column: counts, valences, orientation") {
  const std::vector<Quad> quads = grid(4, 3, false);
  const QuadChords c = quad_chords(quads);
  const int points = 5 * 4;
  std::vector<char> split(c.length.size(), 0);
  split[static_cast<std::size_t>(c.chord_of[1][0])] = 1;  // column 1
  SplitQuads one = split_chords(quads, points, c, split);
  CHECK(one.quads.size() == 15);
  CHECK(one.new_points.size() == 4);  // the midpoints of the 4 crossed edges
  int boundary = 0;
  for (const SplitPoint& p : one.new_points) boundary += p.boundary;
  CHECK(boundary == 2);
  CHECK(euler(one.quads) == 1);
  Counts k = counts(one.quads);
  CHECK(k.boundary_edges == 2 * (4 + 3) + 2);
  for (int i = 0; i < 4; ++i) {
    const int v = points + i;
    CHECK(k.valence[v] == (one.new_points[static_cast<std::size_t>(i)].boundary ? 2 : 4));
  }

  split[static_cast<std::size_t>(c.chord_of[4][1])] = 1;  // and row 1
  SplitQuads two = split_chords(quads, points, c, split);
  CHECK(two.quads.size() == 12 + 3 + 4 + 1);  // the crossing quad is cut in four
  CHECK(two.new_points.size() == 4 + 5 + 1);  // column midpoints, row midpoints, a centre
  CHECK(euler(two.quads) == 1);
  k = counts(two.quads);
  for (std::size_t i = 0; i < two.new_points.size(); ++i)
    CHECK(k.valence[points + static_cast<int>(i)] == (two.new_points[i].boundary ? 2 : 4));
  // the old points keep their valence: nothing irregular is created
  const Counts before = counts(quads);
  for (int v = 0; v < points; ++v) CHECK(k.valence[v] == before.valence.at(v));
}

TEST_CASE("a cylinder: the rows close up, splitting one keeps chi 0 and two boundary loops") {
  const std::vector<Quad> quads = grid(6, 2, true);
  const QuadChords c = quad_chords(quads);
  REQUIRE(c.length.size() == 6 + 2);
  int closed = 0;
  for (std::size_t k = 0; k < c.length.size(); ++k)
    if (!c.open[k]) {
      ++closed;
      CHECK(c.length[k] == 6);
    }
  CHECK(closed == 2);
  std::vector<char> split(c.length.size(), 0);
  split[static_cast<std::size_t>(c.chord_of[0][1])] = 1;  // row 0, around the cylinder
  const SplitQuads s = split_chords(quads, 6 * 3, c, split);
  CHECK(s.quads.size() == 18);
  CHECK(s.new_points.size() == 6);
  for (const SplitPoint& p : s.new_points) CHECK_FALSE(p.boundary);
  CHECK(euler(s.quads) == 0);
  CHECK(counts(s.quads).boundary_edges == 12);
}
