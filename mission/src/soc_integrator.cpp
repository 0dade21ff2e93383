#include "ceilplan/mission/soc_integrator.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::mission {

void flyProfile(SocIntegrator& flight, const std::vector<LoadSample>& profile, const SampleVisitor& visit) {
  double previous_a = flight.currentFor(profile.front().load);
  if (visit) visit(0, previous_a);
  for (std::size_t k = 1; k < profile.size(); ++k) {
    const double current_a = flight.currentFor(profile[k].load);
    flight.advance(profile[k].t_s - profile[k - 1].t_s, 0.5 * (previous_a + current_a));
    if (visit) visit(k, current_a);
    previous_a = current_a;
  }
}

std::vector<LoadSample> stepProfile(const std::vector<LoadSample>& profile, double step_s) {
  if (!(step_s > 0.0) || !std::isfinite(step_s))
    throw ceilplan::InputError("a profile's step must be a positive number of seconds, got " + formatNumber(step_s));
  if (profile.size() < 3) return profile;
  std::vector<LoadSample> steps;
  for (std::size_t first = 0, last = 0; first + 1 < profile.size(); first = last) {
    double integral = 0.0;
    for (last = first + 1;; ++last) {
      integral += 0.5 * (profile[last - 1].load + profile[last].load) * (profile[last].t_s - profile[last - 1].t_s);
      if (last + 1 == profile.size() || profile[last + 1].t_s - profile[first].t_s > step_s) break;
    }
    const double duration_s = profile[last].t_s - profile[first].t_s;
    const double load = duration_s > 0.0 ? integral / duration_s : 0.5 * (profile[first].load + profile[last].load);
    steps.push_back({profile[first].t_s, load});
    steps.push_back({profile[last].t_s, load});
  }
  return steps;
}

std::size_t hoverSteps(double duration_s) {
  return duration_s > 0.0 ? static_cast<std::size_t>(std::ceil(duration_s / kHoverStepS)) : 0;
}

void hover(SocIntegrator& flight, double load, double duration_s, const SampleVisitor& visit) {
  const std::size_t steps = hoverSteps(duration_s);
  double previous_a = flight.currentFor(load);
  if (visit) visit(0, previous_a);
  for (std::size_t k = 1; k <= steps; ++k) {
    const double current_a = flight.currentFor(load);
    flight.advance(duration_s / static_cast<double>(steps), 0.5 * (previous_a + current_a));
    if (visit) visit(k, current_a);
    previous_a = current_a;
  }
}

}  // namespace ceilplan::mission
