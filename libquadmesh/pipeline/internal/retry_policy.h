// Which meshing attempts the pipeline makes, and in what order (docs/style.md,
// "Policy apart from mechanism"). Folds the untangling could not remove (and the
// cells they drop) depend on the form and on how s h rounds, so a faulty result is
// met by meshing again, differently:
//  1. the chosen form (auto's with zeros at the boundary tips, when it has some);
//  2. with tips: auto's most uniform form without them, unless (1) is sound and
//     meets the acceptance criteria (zeros at the tips move the other zeros and
//     change |h| everywhere);
//  3. while the best result is faulty (broken, or quad boundary points off S's
//     boundary): the same form rounded at nearby scales, nearest first
//     (rounding_retry_densities), starting with the requested size itself when the
//     scale had moved off it;
//  4. with form auto, while the best result is broken (folds, dropped cells, wrong
//     topology): the symmetric basis forms, most uniform first.
// The best result is kept throughout (candidate_ranking.h). Separately, the input
// with long edges split is meshed as a second triangulation (long_edge_split_*).
#pragma once

#include "libquadmesh/pipeline/mesh_quads.h"

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace qm {

/// One attempt: what an attempt (attempt.h) is asked to mesh.
struct AttemptRequest {
  Eigen::VectorXd coefficients;   ///< h = sum_k c_k h_k (unit vector)
  std::size_t boundary_tips = 0;  ///< boundary tips this form vanishes at (QuadMeshResult::boundary_tips)
  /// The base lattice's quad count as a fraction of the target.
  double density = 1.0;
  /// Let the scale move within the rounding window to where the periods round best
  /// (QuadMeshResult::base_density then says where it landed).
  bool choose_scale = true;
};

/// Why an attempt is made, and how it is counted (QuadMeshResult::form_attempts,
/// rounding_attempts) and announced.
struct AttemptPlan {
  enum class Reason {
    first,         ///< the chosen form
    without_tips,  ///< auto's form without the zeros at the boundary tips
    rounding,      ///< the best form rounded again at another scale
    basis_form,    ///< a symmetric basis form
  };
  Reason reason = Reason::first;
  AttemptRequest request;
  std::size_t tips_dropped = 0;  ///< without_tips: the tips the first form vanished at
  int basis_form = -1;           ///< basis_form: k (from 0)
  int basis_rank = 0;            ///< basis_form: its place in the order (from 0)
};

/// How the best result so far stands (candidate_ranking.h), as the policy sees it.
struct CandidateStanding {
  bool broken = false;
  bool faulty = false;
  bool acceptable = false;  ///< sound and meets the acceptance criteria
  Eigen::VectorXd coefficients;
  std::size_t boundary_tips = 0;
  double base_density = 1.0;
};

/// Quad counts, as factors of the faulty result's own, at which its form is
/// rounded again, nearest first. With the rounding window (6% of the count) the
/// base lattice stays within 11% of the target (issue 4 allows 15%); the
/// refinement never takes the count above 1.1 x the target.
inline constexpr double rounding_retry_densities[] = {0.97, 1.03, 0.95, 1.05};

/// The requested size is tried again first when the scale had moved off it by more
/// than this fraction of the quad count.
inline constexpr double density_tolerance = 0.01;

/// Steps 1-4 above as a sequence: first(), then next() after each attempt has
/// been ranked, until it returns nothing.
class RetryPolicy {
 public:
  struct Inputs {
    AttemptRequest first;               ///< the chosen form
    Eigen::VectorXd free_coefficients;  ///< auto's form without the tips; empty: none
    bool automatic = false;             ///< the form was chosen by auto (QuadMeshOptions::form < 0, no coefficients)
    /// The basis forms, most uniform first (asked once, when step 4 begins).
    std::function<std::vector<int>()> basis_order;
  };
  explicit RetryPolicy(Inputs inputs) : inputs_(std::move(inputs)) {}

  AttemptPlan first() const;
  /// The next attempt, given the best result after the last one; nothing: done.
  std::optional<AttemptPlan> next(const CandidateStanding& best);

 private:
  enum class Step { without_tips, rounding, basis_forms, done };
  Inputs inputs_;
  Step step_ = Step::without_tips;
  bool started_ = false;  ///< the current step has begun (its list is made)
  std::vector<double> densities_;
  std::vector<int> order_;
  std::size_t index_ = 0;
  void advance(Step step);
};

/// The stage key (QuadMeshResult::timings) and progress message of a retry.
struct StageNote {
  std::string key;
  std::string message;
};
StageNote announce(const AttemptPlan& plan, int basis_count);

/// Whether the long-edge split is considered at all: not when the input is
/// remeshed anyway (RemeshPolicy::always) or the split is off.
bool long_edge_split_allowed(const QuadMeshOptions& options);

/// The fraction of the area in triangles wider than the quads from which the
/// input split at its long edges is meshed too (a few long edges, a scan's hole
/// rim, are not worth a second run).
inline constexpr double long_edge_area_threshold = 0.05;

/// Whether that second run is worth it, given the fraction of the area in
/// triangles with an edge longer than the quads (long_edge_area_fraction).
bool long_edge_split_worth_it(double long_edge_area_fraction);

}  // namespace qm
