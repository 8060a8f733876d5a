// The fill-reducing ordering the seamless maps of one cone set share
// (seamless_map.h): CHOLMOD's minimum degree, or METIS's nested dissection where
// the systems are large enough for it to pay.
#pragma once

#include <mutex>
#include <vector>

namespace qm {

/// The fill-reducing ordering of one cone set's seamless map systems, which the
/// cone set's maps share (the same cut and seams, the same pattern: a map from
/// another lattice offset or with stiffer triangles changes values only). A map's
/// factorizations are ordered by CHOLMOD's minimum degree unless that ordering's
/// factorization costs more than `flops_per_unknown` per unknown (CHOLMOD's count
/// from the analysis); then by METIS's nested dissection, ordered once, by the
/// first map that asks (a map asking meanwhile waits for it; METIS itself runs
/// under a process-wide lock, seamless_map.cpp, its random state being the
/// process's). Share one between the maps of a cone set, never across cone sets.
class MapOrdering {
 public:
  /// METIS takes as long as a factorization of about 10,000 flops per unknown
  /// (0.13-0.15 s at 30,000 unknowns, 0.32 s at 75,000; CHOLMOD's simplicial
  /// factorization runs at about 2.4 GFlop/s here), and a map factors 4 to 10
  /// times. Its ordering needs 0.37 of the minimum degree's flops on bunny-open's
  /// maps (75,000 unknowns, 14,300 flops per unknown: 0.43 s -> 0.18 s per
  /// factorization), 0.53 on pig's (5,200) and 0.63 on fertility-3holes' (4,500),
  /// where six factorizations just pay for it. A CAD part's maps (6,000 to 10,000
  /// unknowns) need under 2,000: there METIS would cost six factorizations.
  static constexpr double default_flops_per_unknown = 6000;

  explicit MapOrdering(double flops_per_unknown = default_flops_per_unknown)
      : flops_per_unknown_(flops_per_unknown) {}

  /// Whether a system of `unknowns` whose minimum degree factorization takes
  /// `flops` is ordered by nested dissection.
  bool nested_dissection_pays(double flops, int unknowns) const {
    return flops > flops_per_unknown_ * unknowns;
  }

  /// The nested dissection's permutation (CHOLMOD's, postordered) of the cone
  /// set's systems, computed by `order` at the first call.
  template <typename Order>
  const std::vector<int>& nested_dissection(Order&& order) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (permutation_.empty()) permutation_ = order();
    return permutation_;
  }

 private:
  double flops_per_unknown_;
  std::mutex mutex_;
  std::vector<int> permutation_;
};

}  // namespace qm
