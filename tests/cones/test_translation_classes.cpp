// The translation classes of translation_classes.h: cut edges that share a
// transition, seen from the same side or from the other, carry one lattice vector
// up to a quarter turn. Checked against the transitions themselves: with wedge
// values chosen freely on one side, the other side's values follow from each
// class's representative, and every edge's own transition must then hold.
#include "libquadmesh/cones/internal/translation_classes.h"

#include <doctest/doctest.h>

#include <complex>
#include <map>

using namespace qm;

namespace {

using Complex = std::complex<double>;

Complex turn(int k) {
  static const Complex powers[4] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  return powers[((k % 4) + 4) % 4];
}

}  // namespace

TEST_CASE("cut edges sharing a transition, from either side, have one translation up to a quarter turn") {
  // a path of four cut edges through wedges 10..14 (one side) and 20..24 (the
  // other), quarter turn 1 from the first side; edges 2 and 3 are seen from the
  // other side (their lower-numbered triangle lies there); edge 4 is elsewhere
  const std::vector<std::array<TransitionEnd, 2>> ends = {
      {TransitionEnd{20, 10, 1}, TransitionEnd{21, 11, 1}},
      {TransitionEnd{21, 11, 1}, TransitionEnd{22, 12, 1}},
      {TransitionEnd{12, 22, 3}, TransitionEnd{13, 23, 3}},
      {TransitionEnd{13, 23, 3}, TransitionEnd{14, 24, 3}},
      {TransitionEnd{30, 40, 2}, TransitionEnd{31, 41, 2}},
  };
  const TranslationClasses classes = translation_classes(ends);
  REQUIRE(classes.representative.size() == 5);
  const int path = classes.representative[0];
  for (int i = 0; i < 4; ++i) CHECK(classes.representative[static_cast<std::size_t>(i)] == path);
  CHECK(classes.representative[4] == 4);
  CHECK(classes.quarter_turns[4] == 0);
  CHECK(classes.quarter_turns[static_cast<std::size_t>(path)] == 0);

  // the path's translation t = 3 + 2i and the near side's values free: the far
  // side follows from edges 0 and 1 (W_far = i W_near + t)...
  const Complex t_path(3, 2);
  std::map<int, Complex> w;
  for (int v = 10; v <= 14; ++v) w[v] = Complex(0.5 * v, -0.25 * v * v);
  auto translation = [&](std::size_t i) { return turn(classes.quarter_turns[i]) * t_path; };
  for (std::size_t i = 0; i < 2; ++i)
    for (const TransitionEnd& e : ends[i]) w[e.far] = turn(e.quarter_turns) * w[e.near] + translation(i);
  // ...and edges 2 and 3 (seen from the far side, W_near = i^3 W_far + t') must fill
  // wedges 23 and 24 consistently with edge 1's wedge 22: their own transitions hold
  w[23] = w[22] + (w[13] - w[12]) * turn(1);  // the far side moves as the near side turned
  w[24] = w[22] + (w[14] - w[12]) * turn(1);
  for (std::size_t i = 2; i < 4; ++i)
    for (const TransitionEnd& e : ends[i]) {
      const Complex residual = w[e.far] - (turn(e.quarter_turns) * w[e.near] + translation(i));
      CHECK(std::abs(residual) < 1e-12);
    }
}
