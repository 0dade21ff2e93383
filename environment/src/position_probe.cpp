#include "ceilplan/environment/position_probe.hpp"

namespace ceilplan::environment {

PositionProbe probePosition(const Environment& environment, const Eigen::Vector3d& body_m) {
  PositionProbe probe{body_m, environment.ceiling(body_m), environment.ground(body_m), 0.0, std::nullopt, false, false};
  probe.clearance_m = environment.clearance_m(body_m);
  probe.violation = environment.stateViolation(body_m);
  probe.assumes_free = environment.assumesFree(body_m);
  probe.point_assumed_free = environment.index()->isAssumedFree(body_m);
  return probe;
}

}  // namespace ceilplan::environment
