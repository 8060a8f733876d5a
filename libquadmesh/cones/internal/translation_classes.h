// The translations of a seamless map's cut edges that the seam rows make one
// lattice vector up to a quarter turn. Across a cut edge the map's values obey
// W_a = i^q W_b + t at each end (wedge a on the far side, b on the near side);
// two edges of one cut path meeting at a vertex share that transition, seen from
// the same side (t equal) or from the other (W_b = i^-q W_a - i^-q t: the other
// edge's translation is i^(q+2) t). Each class needs one value made integer, not
// one per edge: each fix costs the quantization a back-substitution.
#pragma once

#include <array>
#include <vector>

namespace qm {

/// One end of a cut edge's transition: W[far] = i^quarter_turns W[near] + t.
struct TransitionEnd {
  int far = -1;
  int near = -1;
  int quarter_turns = 0;
};

/// Per translation, its class's representative and the quarter turns k with
/// t = i^k t_representative (0 for the representative itself).
struct TranslationClasses {
  std::vector<int> representative;
  std::vector<int> quarter_turns;
};

/// `ends[i]`: the transitions at the two ends of translation i's cut edge.
TranslationClasses translation_classes(const std::vector<std::array<TransitionEnd, 2>>& ends);

}  // namespace qm
