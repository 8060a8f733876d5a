// The retry policy (pipeline/internal/retry_policy.h) on made-up standings: which
// attempts follow a result, in what order, and when the search ends. No meshing.
#include "libquadmesh/pipeline/internal/retry_policy.h"

#include <doctest/doctest.h>

#include <vector>

using namespace qm;

namespace {

using Reason = AttemptPlan::Reason;

/// A policy for a surface with `G` basis forms, the chosen form the first; with
/// `tips`, auto's form vanishes at that many tips and the one without is the second.
RetryPolicy policy(int G, bool automatic, std::size_t tips, int* order_asked = nullptr) {
  RetryPolicy::Inputs in;
  in.first.coefficients = Eigen::VectorXd::Unit(G, 0);
  in.first.boundary_tips = tips;
  if (tips > 0) in.free_coefficients = Eigen::VectorXd::Unit(G, 1);
  in.automatic = automatic;
  in.basis_order = [G, order_asked] {
    if (order_asked) ++*order_asked;
    std::vector<int> order;
    for (int k = G; k-- > 0;) order.push_back(k);  // made up: the last form most uniform
    return order;
  };
  return RetryPolicy(in);
}

CandidateStanding clean(const Eigen::VectorXd& c, double base_density = 1.0) {
  CandidateStanding s;
  s.acceptable = true;
  s.coefficients = c;
  s.base_density = base_density;
  return s;
}

CandidateStanding broken(const Eigen::VectorXd& c, double base_density = 1.0) {
  CandidateStanding s = clean(c, base_density);
  s.broken = s.faulty = true;
  s.acceptable = false;
  return s;
}

/// Stray boundary points only: faulty, not broken.
CandidateStanding stray(const Eigen::VectorXd& c, double base_density = 1.0) {
  CandidateStanding s = clean(c, base_density);
  s.faulty = true;
  s.acceptable = false;
  return s;
}

}  // namespace

TEST_CASE("retry policy: a clean first result ends the search") {
  RetryPolicy p = policy(3, true, 2);
  const AttemptPlan first = p.first();
  CHECK(first.reason == Reason::first);
  CHECK(first.request.boundary_tips == 2);
  CHECK(first.request.density == 1.0);
  CHECK(first.request.choose_scale);
  CHECK_FALSE(p.next(clean(first.request.coefficients)).has_value());
}

TEST_CASE("retry policy: with tips, a sound result short of the criteria tries the form without them once") {
  RetryPolicy p = policy(3, true, 2);
  CandidateStanding shapeless = clean(Eigen::VectorXd::Unit(3, 0));
  shapeless.acceptable = false;  // sound, but the Jacobian floor or the angles not met
  const auto plan = p.next(shapeless);
  REQUIRE(plan.has_value());
  CHECK(plan->reason == Reason::without_tips);
  CHECK(plan->request.coefficients == Eigen::VectorXd::Unit(3, 1));
  CHECK(plan->request.boundary_tips == 0);
  CHECK(plan->tips_dropped == 2);
  CHECK(plan->request.choose_scale);
  CHECK_FALSE(p.next(shapeless).has_value());  // not faulty: no rounding, no basis forms
}

TEST_CASE("retry policy: a faulty result is rounded again at the requested size, then at nearby scales") {
  RetryPolicy p = policy(2, false, 0);
  const Eigen::VectorXd c = Eigen::VectorXd::Unit(2, 0);
  // the scale had moved 4% off the requested count: the requested size first
  std::vector<double> densities;
  for (auto plan = p.next(stray(c, 1.04)); plan; plan = p.next(stray(c, 1.04))) {
    CHECK(plan->reason == Reason::rounding);
    CHECK_FALSE(plan->request.choose_scale);
    CHECK(plan->request.coefficients == c);
    densities.push_back(plan->request.density);
  }
  REQUIRE(densities.size() == 5);
  CHECK(densities[0] == 1.0);
  for (std::size_t i = 0; i < 4; ++i) CHECK(densities[i + 1] == doctest::Approx(1.04 * rounding_retry_densities[i]));
}

TEST_CASE("retry policy: near the requested size, the rounding retries start at the nearby scales") {
  RetryPolicy p = policy(2, false, 0);
  const Eigen::VectorXd c = Eigen::VectorXd::Unit(2, 0);
  const auto plan = p.next(stray(c, 1.005));
  REQUIRE(plan.has_value());
  CHECK(plan->request.density == doctest::Approx(1.005 * rounding_retry_densities[0]));
}

TEST_CASE("retry policy: the first clean rounding ends the search; the densities are the faulty result's") {
  RetryPolicy p = policy(2, true, 0);
  const Eigen::VectorXd c = Eigen::VectorXd::Unit(2, 1);
  const auto plan = p.next(broken(c));
  REQUIRE(plan.has_value());
  CHECK(plan->reason == Reason::rounding);
  CHECK(plan->request.coefficients == c);  // the best form's, whichever it is
  CHECK_FALSE(p.next(clean(c)).has_value());
}

TEST_CASE("retry policy: with auto, a result still broken after the roundings tries the basis forms in order") {
  int asked = 0;
  RetryPolicy p = policy(3, true, 0, &asked);
  const Eigen::VectorXd c = Eigen::VectorXd::Unit(3, 0);
  int roundings = 0;
  auto plan = p.next(broken(c));
  for (; plan && plan->reason == Reason::rounding; plan = p.next(broken(c))) {
    CHECK(asked == 0);  // the basis forms are ranked only when they are needed
    ++roundings;
  }
  CHECK(roundings == 4);  // base density 1: no retry at the requested size
  REQUIRE(plan.has_value());
  CHECK(asked == 1);
  CHECK(plan->reason == Reason::basis_form);
  CHECK(plan->basis_form == 2);  // the made-up order: 2, 1, 0
  CHECK(plan->basis_rank == 0);
  CHECK(plan->request.coefficients == Eigen::VectorXd::Unit(3, 2));
  CHECK(plan->request.density == 1.0);
  CHECK(plan->request.choose_scale);
  plan = p.next(broken(c));
  REQUIRE(plan.has_value());
  CHECK(plan->basis_form == 1);
  CHECK(plan->basis_rank == 1);
  // the first basis form that is not broken ends it (stray points alone do not count)
  CHECK_FALSE(p.next(stray(Eigen::VectorXd::Unit(3, 1))).has_value());
  CHECK(asked == 1);
}

TEST_CASE("retry policy: no basis forms for a chosen form, nor for stray boundary points alone") {
  {
    RetryPolicy p = policy(3, false, 0);
    const Eigen::VectorXd c = Eigen::VectorXd::Unit(3, 0);
    int attempts = 0;
    for (auto plan = p.next(broken(c)); plan; plan = p.next(broken(c))) {
      CHECK(plan->reason == Reason::rounding);
      ++attempts;
    }
    CHECK(attempts == 4);
  }
  {
    int asked = 0;
    RetryPolicy p = policy(3, true, 0, &asked);
    const Eigen::VectorXd c = Eigen::VectorXd::Unit(3, 0);
    int attempts = 0;
    for (auto plan = p.next(stray(c)); plan; plan = p.next(stray(c))) {
      CHECK(plan->reason == Reason::rounding);
      ++attempts;
    }
    CHECK(attempts == 4);
    CHECK(asked == 0);
  }
}

TEST_CASE("retry policy: the announcements say why, with the forms counted from 1") {
  AttemptPlan plan;
  plan.reason = Reason::basis_form;
  plan.basis_form = 0;
  plan.basis_rank = 1;
  const StageNote note = announce(plan, 3);
  CHECK(note.key == "form_choice");
  CHECK(note.message.find("symmetric basis form 1 (2 of 3)") != std::string::npos);
  plan.reason = Reason::rounding;
  plan.request.density = 0.97;
  CHECK(announce(plan, 3).key == "rounding");
  CHECK(announce(plan, 3).message.find("97% of the target quad count") != std::string::npos);
}

TEST_CASE("retry policy: the long-edge split, when allowed and worth a second run") {
  QuadMeshOptions options;
  CHECK(long_edge_split_allowed(options));
  options.split_long_edges = false;
  CHECK_FALSE(long_edge_split_allowed(options));
  options.split_long_edges = true;
  options.remesh = RemeshPolicy::always;
  CHECK_FALSE(long_edge_split_allowed(options));
  CHECK_FALSE(long_edge_split_worth_it(0.5 * long_edge_area_threshold));
  CHECK(long_edge_split_worth_it(long_edge_area_threshold));
  CHECK(long_edge_split_worth_it(0.5));
}
