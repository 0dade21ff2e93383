#include "ceilplan/planner/rejection_band_sampler.hpp"

#include <ompl/base/OptimizationObjective.h>
#include <ompl/base/ProblemDefinition.h>

namespace ceilplan::planner {

RejectionBandSampler::RejectionBandSampler(const ompl::base::ProblemDefinitionPtr& definition, unsigned int max_calls)
    : ompl::base::InformedSampler(definition, max_calls), base_(space_->allocStateSampler()) {}

bool RejectionBandSampler::sampleUniform(ompl::base::State* state, const ompl::base::Cost& max_cost) {
  for (unsigned int k = 0; k < numIters_; ++k) {
    base_->sampleUniform(state);
    if (opt_->isCostBetterThan(heuristicSolnCost(state), max_cost)) return true;
  }
  return false;
}

bool RejectionBandSampler::sampleUniform(ompl::base::State* state, const ompl::base::Cost& min_cost,
                                         const ompl::base::Cost& max_cost) {
  for (unsigned int k = 0; k < numIters_; ++k) {
    base_->sampleUniform(state);
    const ompl::base::Cost bound = heuristicSolnCost(state);
    if (opt_->isCostBetterThan(bound, max_cost) && !opt_->isCostBetterThan(bound, min_cost)) return true;
  }
  return false;
}

}  // namespace ceilplan::planner
