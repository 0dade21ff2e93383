#include "ceilplan/planner/ceiling_band_sampler.hpp"

#include "ceilplan/planner/ompl_state.hpp"

#include <cmath>

namespace ceilplan::planner {

CeilingBandSampler::CeilingBandSampler(const ompl::base::StateSpace* space, const environment::Environment& environment,
                                       CeilingBandOptions options)
    : ompl::base::StateSampler(space), environment_(environment), options_(options), uniform_(space) {}

void CeilingBandSampler::sampleUniform(ompl::base::State* state) {
  uniform_.sampleUniform(state);
  if (rng_.uniform01() >= options_.band_fraction) return;
  const Eigen::Vector3d point = toPosition(state);
  const double plane_height = environment_.vehicle().rotor_plane_height_m;
  const Eigen::Vector3d plane(point.x(), point.y(), point.z() + plane_height);
  if (!environment_.contains(plane)) return;
  const double gap = environment_.ceilingGapAt(plane);
  if (!std::isfinite(gap)) return;  // nothing overhead: keep the uniform sample
  const double wanted = rng_.uniformReal(options_.min_gap_m, options_.max_gap_m);
  setPosition(state, {point.x(), point.y(), point.z() + gap - wanted});
  space_->enforceBounds(state);
}

void CeilingBandSampler::sampleUniformNear(ompl::base::State* state, const ompl::base::State* near, double distance) {
  uniform_.sampleUniformNear(state, near, distance);
}

void CeilingBandSampler::sampleGaussian(ompl::base::State* state, const ompl::base::State* mean, double stdDev) {
  uniform_.sampleGaussian(state, mean, stdDev);
}

}  // namespace ceilplan::planner
