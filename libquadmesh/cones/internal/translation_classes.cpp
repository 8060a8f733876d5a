#include "libquadmesh/cones/internal/translation_classes.h"

#include <map>
#include <tuple>

namespace qm {

namespace {

/// Disjoint sets whose members carry a quarter turn against their parent:
/// t_i = i^turn[i] t_parent[i].
class QuarterTurnSets {
 public:
  explicit QuarterTurnSets(std::size_t n) : parent_(n), turn_(n, 0) {
    for (std::size_t i = 0; i < n; ++i) parent_[i] = static_cast<int>(i);
  }

  /// The root of i's set and k with t_i = i^k t_root.
  std::pair<int, int> find(int i) {
    int k = 0, r = i;
    while (parent_[static_cast<std::size_t>(r)] != r) {
      k += turn_[static_cast<std::size_t>(r)];
      r = parent_[static_cast<std::size_t>(r)];
    }
    // path compression: i hangs from the root directly
    parent_[static_cast<std::size_t>(i)] = r;
    turn_[static_cast<std::size_t>(i)] = k % 4;
    return {r, k % 4};
  }

  /// Records t_i = i^k t_j (nothing when they are already one set).
  void unite(int i, int j, int k) {
    const auto [ri, ki] = find(i);
    const auto [rj, kj] = find(j);
    if (ri == rj) return;
    // t_ri = i^-ki t_i = i^(k - ki) t_j = i^(k - ki + kj) t_rj
    parent_[static_cast<std::size_t>(ri)] = rj;
    turn_[static_cast<std::size_t>(ri)] = ((k - ki + kj) % 4 + 4) % 4;
  }

 private:
  std::vector<int> parent_;
  std::vector<int> turn_;
};

}  // namespace

TranslationClasses translation_classes(const std::vector<std::array<TransitionEnd, 2>>& ends) {
  QuarterTurnSets sets(ends.size());
  std::map<std::tuple<int, int, int>, int> first_at;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (const TransitionEnd& e : ends[i]) {
      const int me = static_cast<int>(i);
      if (const auto same = first_at.find({e.far, e.near, e.quarter_turns}); same != first_at.end()) {
        sets.unite(me, same->second, 0);
        continue;
      }
      // the same transition seen from the other side: W_near = i^-q W_far + t'
      if (const auto other = first_at.find({e.near, e.far, (4 - e.quarter_turns) % 4}); other != first_at.end())
        sets.unite(me, other->second, (e.quarter_turns + 2) % 4);
      first_at.emplace(std::make_tuple(e.far, e.near, e.quarter_turns), me);
    }
  TranslationClasses out;
  out.representative.resize(ends.size());
  out.quarter_turns.resize(ends.size());
  for (std::size_t i = 0; i < ends.size(); ++i) {
    const auto [root, k] = sets.find(static_cast<int>(i));
    out.representative[i] = root;
    out.quarter_turns[i] = k;
  }
  return out;
}

}  // namespace qm
