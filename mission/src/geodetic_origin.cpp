#include "ceilplan/mission/geodetic_origin.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>

namespace ceilplan::mission {

void GeodeticOrigin::validate() const {
  if (!(latitude_deg >= -90.0 && latitude_deg <= 90.0))
    throw InputError("origin latitude must be in [-90, 90] degrees, got " + formatNumber(latitude_deg));
  if (!(longitude_deg >= -180.0 && longitude_deg <= 180.0))
    throw InputError("origin longitude must be in [-180, 180] degrees, got " + formatNumber(longitude_deg));
  if (!std::isfinite(altitude_m)) throw InputError("origin altitude must be finite, got " + formatNumber(altitude_m));
}

}  // namespace ceilplan::mission
