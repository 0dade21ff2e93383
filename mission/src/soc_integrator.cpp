#include "ceilplan/mission/soc_integrator.hpp"

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
