#pragma once
/// @file
/// Informed sampling that keeps the space's own sampler (the ceiling-band one): OMPL 1.5.2's
/// RejectionInfSampler draws from the space's default sampler, which would bypass the band.
/// Rejects samples whose admissible solution-cost bound (cost-to-come heuristic + cost-to-go)
/// cannot beat the current best.

#include <ompl/base/StateSampler.h>
#include <ompl/base/samplers/InformedStateSampler.h>

namespace ceilplan::planner {

/// OMPL informed sampler by rejection from the space's own sampler, so informed planners keep the ceiling band.
class RejectionBandSampler : public ompl::base::InformedSampler {
 public:
  /// Samples for `definition`, giving up after `max_calls` draws per sample.
  RejectionBandSampler(const ompl::base::ProblemDefinitionPtr& definition, unsigned int max_calls);

  /// OMPL: a sample whose heuristic cost is below `max_cost`.
  bool sampleUniform(ompl::base::State* state, const ompl::base::Cost& max_cost) override;
  /// OMPL: a sample whose heuristic cost lies between `min_cost` and `max_cost`.
  bool sampleUniform(ompl::base::State* state, const ompl::base::Cost& min_cost,
                     const ompl::base::Cost& max_cost) override;
  /// OMPL: no closed-form informed measure.
  bool hasInformedMeasure() const override { return false; }
  /// OMPL: the whole space's measure.
  double getInformedMeasure(const ompl::base::Cost&) const override { return space_->getMeasure(); }

 private:
  ompl::base::StateSamplerPtr base_;
};

}  // namespace ceilplan::planner
