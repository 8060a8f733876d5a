#include "libquadmesh/pipeline/internal/retry_policy.h"

#include <fmt/format.h>

#include <cmath>

namespace qm {

AttemptPlan RetryPolicy::first() const {
  AttemptPlan plan;
  plan.reason = AttemptPlan::Reason::first;
  plan.request = inputs_.first;
  return plan;
}

void RetryPolicy::advance(Step step) {
  step_ = step;
  started_ = false;
  index_ = 0;
}

std::optional<AttemptPlan> RetryPolicy::next(const CandidateStanding& best) {
  if (step_ == Step::without_tips) {
    advance(Step::rounding);
    if (inputs_.free_coefficients.size() > 0 && !best.acceptable) {
      AttemptPlan plan;
      plan.reason = AttemptPlan::Reason::without_tips;
      plan.request.coefficients = inputs_.free_coefficients;
      plan.request.boundary_tips = 0;
      plan.tips_dropped = inputs_.first.boundary_tips;
      return plan;
    }
  }
  if (step_ == Step::rounding) {
    if (!started_) {
      started_ = true;
      densities_.clear();
      if (best.faulty) {
        // the requested size itself first, when the scale had moved off it
        if (std::abs(best.base_density - 1.0) > density_tolerance) densities_.push_back(1.0);
        for (const double factor : rounding_retry_densities) densities_.push_back(best.base_density * factor);
      }
    }
    if (best.faulty && index_ < densities_.size()) {
      AttemptPlan plan;
      plan.reason = AttemptPlan::Reason::rounding;
      plan.request.coefficients = best.coefficients;
      plan.request.boundary_tips = best.boundary_tips;
      plan.request.density = densities_[index_++];
      plan.request.choose_scale = false;
      return plan;
    }
    advance(Step::basis_forms);
  }
  if (step_ == Step::basis_forms) {
    if (!started_) {
      started_ = true;
      // a basis form is far less uniform than auto's: not worth it for stray
      // boundary points alone
      if (inputs_.automatic && best.broken && inputs_.basis_order) order_ = inputs_.basis_order();
    }
    if (best.broken && index_ < order_.size()) {
      const Eigen::Index G = inputs_.first.coefficients.size();
      AttemptPlan plan;
      plan.reason = AttemptPlan::Reason::basis_form;
      plan.basis_form = order_[index_];
      plan.basis_rank = static_cast<int>(index_);
      plan.request.coefficients = Eigen::VectorXd::Unit(G, plan.basis_form);
      ++index_;
      return plan;
    }
    advance(Step::done);
  }
  return std::nullopt;
}

StageNote announce(const AttemptPlan& plan, int basis_count) {
  switch (plan.reason) {
    case AttemptPlan::Reason::first:
      return {};  // not announced: it runs within the form choice's stage
    case AttemptPlan::Reason::without_tips:
      return {"form_choice",
              fmt::format("meshing the form without zeros at the {} boundary tips as well", plan.tips_dropped)};
    case AttemptPlan::Reason::rounding:
      return {"rounding", fmt::format("folds, dropped cells or quads off the boundary left: rounding "
                                      "again at {:.0f}% of the target quad count",
                                      100 * plan.request.density)};
    case AttemptPlan::Reason::basis_form:
      return {"form_choice", fmt::format("folds, dropped cells or the topology still wrong: trying "
                                         "symmetric basis form {} ({} of {})",
                                         plan.basis_form + 1, plan.basis_rank + 1, basis_count)};
  }
  return {};
}

bool long_edge_split_allowed(const QuadMeshOptions& options) {
  return options.remesh != RemeshPolicy::always && options.split_long_edges;
}

bool long_edge_split_worth_it(double long_edge_area_fraction) {
  return !(long_edge_area_fraction < long_edge_area_threshold);
}

}  // namespace qm
