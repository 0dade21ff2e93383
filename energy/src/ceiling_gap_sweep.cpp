#include "ceilplan/energy/ceiling_gap_sweep.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>

namespace ceilplan::energy {

std::vector<GapPoint> ceilingGapSweep(const EnergyModel& model, double coverage, const FlightCondition& flight,
                                      double max_radii, int steps_per_radius) {
  if (!(std::isfinite(max_radii) && max_radii > 0.0) || steps_per_radius < 1)
    throw InputError("a gap sweep needs a positive number of rotor radii and of steps per radius, got " +
                     formatNumber(max_radii) + " and " + std::to_string(steps_per_radius));
  const double radius_m = model.rotorRadiusM();
  const int steps = static_cast<int>(std::floor(max_radii * steps_per_radius + 1e-9));
  std::vector<GapPoint> points;
  for (int i = 0; i <= steps; ++i) {
    const double gap_m = radius_m * i / steps_per_radius;
    points.push_back({gap_m, model.breakdown(gap_m, coverage, flight)});
  }
  return points;
}

}  // namespace ceilplan::energy
