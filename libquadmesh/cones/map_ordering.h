// The fill-reducing ordering the seamless maps of one cone set share
// (seamless_map.h): CHOLMOD's minimum degree, or METIS's nested dissection where
// the systems are large enough for it to pay.
#pragma once

#include "libquadmesh/core/parallel.h"

#include <functional>
#include <memory>
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
  /// An ordering offered and not yet taken is withdrawn; one being computed is
  /// waited for.
  ~MapOrdering() {
    if (offered_) offered_->withdraw();
  }
  MapOrdering(const MapOrdering&) = delete;
  MapOrdering& operator=(const MapOrdering&) = delete;

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

  /// Whether the nested dissection is computed (waiting for it while a thread
  /// computes it): a map of the cone set then takes it without analysing its
  /// system by minimum degree first.
  bool has_nested_dissection() {
    std::lock_guard<std::mutex> lock(mutex_);
    return !permutation_.empty();
  }

  /// The nested dissection computed by `order` on a worker thread that is idle
  /// (core/parallel.h IdleWork), ahead of the map that may ask for it: the first
  /// map, factored by minimum degree, offers it once its analysis shows that the
  /// nested dissection pays, and the maps from lattice offsets, made only if it
  /// folds, find it done (bunny-open's kept placement: METIS's 0.31 s on the
  /// thread the batch's other placement left idle). A failed `order` leaves it to
  /// be computed, and to fail, when asked. Once per cone set.
  void offer_nested_dissection(std::function<std::vector<int>()> order) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (offered_ || !permutation_.empty()) return;
    offered_ = std::make_unique<IdleWork>([this, order = std::move(order)] {
      try {
        nested_dissection(order);
      } catch (...) {
        // (asked for, it is computed again and its error thrown there)
      }
    });
  }

 private:
  double flops_per_unknown_;
  std::mutex mutex_;
  std::vector<int> permutation_;
  std::unique_ptr<IdleWork> offered_;
};

}  // namespace qm
