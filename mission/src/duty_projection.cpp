#include "ceilplan/mission/duty_projection.hpp"

namespace ceilplan::mission {

battery::LoadProfile dischargeProfile(const std::vector<planner::PathSample>& samples) {
  battery::LoadProfile profile;
  double bin_s = 0.0, bin_as = 0.0;
  for (std::size_t k = 1; k < samples.size(); ++k) {
    const planner::PathSample &a = samples[k - 1], &b = samples[k];
    const double dt = b.t_s - a.t_s;
    bin_s += dt;
    bin_as += 0.5 * (a.current_a + b.current_a) * dt;
    if (bin_s >= 1.0 || k + 1 == samples.size()) {
      if (bin_s > 0.0) profile.push_back(battery::Segment::discharge(bin_as / bin_s, bin_s));
      bin_s = bin_as = 0.0;
    }
  }
  return profile;
}

battery::LoadProfile flightProfile(const planner::PathEvaluation& evaluation, int repeats) {
  const battery::LoadProfile once = dischargeProfile(evaluation.samples);
  battery::LoadProfile profile;
  for (int r = 0; r < repeats; ++r) profile.insert(profile.end(), once.begin(), once.end());
  return profile;
}

}  // namespace ceilplan::mission
