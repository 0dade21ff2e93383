#pragma once
/// @file
/// A state sampler that puts a share of its samples in the thin band under ceilings, where a
/// ceiling-hugging optimum lies and uniform sampling rarely looks: pick a random point, find the
/// ceiling above it, and place the rotor plane a random gap between the minimum gap and the
/// band's depth (about 2 R) below it. The rest, and every point with no ceiling above, is uniform.

#include "ceilplan/environment/environment.hpp"

#include <ompl/base/StateSampler.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>

namespace ceilplan::planner {

/// How a CeilingBandSampler aims samples at the band just under a ceiling.
struct CeilingBandOptions {
  double band_fraction = 0.5;  ///< share of samples aimed at the band
  double min_gap_m = 0.05;     ///< rotor plane to ceiling
  double max_gap_m = 0.254;    ///< 2 R of the default vehicle
};

/// OMPL state sampler that puts a share of its samples in the band under a ceiling where ceiling mode pays
/// (docs/planner.md).
class CeilingBandSampler : public ompl::base::StateSampler {
 public:
  /// `environment` must outlive the sampler.
  CeilingBandSampler(const ompl::base::StateSpace* space, const environment::Environment& environment,
                     CeilingBandOptions options);

  /// OMPL: a sample, from the band with probability band_fraction, else uniform.
  void sampleUniform(ompl::base::State* state) override;
  /// OMPL: a sample within `distance` of `near`.
  void sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) override;
  /// OMPL: a Gaussian sample around `mean`.
  void sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) override;

 private:
  const environment::Environment& environment_;
  CeilingBandOptions options_;
  ompl::base::RealVectorStateSampler uniform_;
};

}  // namespace ceilplan::planner
