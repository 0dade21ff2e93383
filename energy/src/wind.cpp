#include "ceilplan/energy/wind.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <string>

namespace ceilplan::energy {

void Wind::validate() const {
  if (!(speed_m_s >= 0.0 && speed_m_s <= kMaxSpeed_m_s))
    throw InputError("wind: speed_m_s must be in [0, " + formatNumber(kMaxSpeed_m_s) + "] m/s, got " +
                     formatNumber(speed_m_s));
  if (!(from_deg >= 0.0 && from_deg < 360.0))
    throw InputError("wind: from_deg must be in [0, 360) deg (where the wind comes from, clockwise from north), got " +
                     formatNumber(from_deg));
  if (!(gust_m_s >= 0.0 && gust_m_s <= kMaxSpeed_m_s))
    throw InputError("wind: gust_m_s must be in [0, " + formatNumber(kMaxSpeed_m_s) + "] m/s, got " +
                     formatNumber(gust_m_s));
  if (!(sheltered_fraction >= 0.0 && sheltered_fraction <= 1.0))
    throw InputError("wind: sheltered_fraction must be in [0, 1], got " + formatNumber(sheltered_fraction));
}

Eigen::Vector2d Wind::airVelocityM_s() const {
  if (calm()) return Eigen::Vector2d::Zero();
  const double from_rad = from_deg * (M_PI / 180.0);
  // From the north (+y) it blows towards -y; from the east (+x) towards -x.
  return {-speed_m_s * std::sin(from_rad), -speed_m_s * std::cos(from_rad)};
}

RelativeWind relativeWind(const Eigen::Vector2d& air_velocity_m_s, const Eigen::Vector2d& track_direction) {
  if (air_velocity_m_s.isZero()) return {};
  if (track_direction.isZero()) return {air_velocity_m_s.norm(), 0.0};
  const double along_m_s = air_velocity_m_s.dot(track_direction);
  const double across_m_s = air_velocity_m_s.x() * track_direction.y() - air_velocity_m_s.y() * track_direction.x();
  return {-along_m_s, std::abs(across_m_s)};
}

}  // namespace ceilplan::energy
