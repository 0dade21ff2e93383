#include "ceilplan/mission/mission.hpp"

#include "ceilplan/core/error.hpp"

namespace ceilplan::mission {

const GeodeticOrigin& Mission::requireOrigin() const {
  if (!origin)
    throw InputError(name() +
                     ": missing key 'origin' ({lat, lon, alt} of the map frame): needed to export to an autopilot");
  return *origin;
}

}  // namespace ceilplan::mission
