#include "ceilplan/mission/flight_record.hpp"

#include <algorithm>

namespace ceilplan::mission {

double SortieRecord::chargeAh() const {
  double as = 0.0;
  for (std::size_t k = 1; k < samples.size(); ++k)
    as += 0.5 * (samples[k - 1].current_a + samples[k].current_a) * (samples[k].t_s - samples[k - 1].t_s);
  return as / 3600.0;
}

double SortieRecord::lowestSoc() const {
  double lowest = samples.empty() ? 0.0 : samples.front().soc;
  for (const planner::PathSample& s : samples) lowest = std::min(lowest, s.soc);
  return lowest;
}

}  // namespace ceilplan::mission
