#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <stdexcept>

namespace ceilplan::environment {
namespace {

void requireFinite(double value, const char* field) {
  if (!std::isfinite(value))
    throw ceilplan::InputError(std::string("vehicle geometry: ") + field + " must be a finite number");
}

void requirePositive(double value, const char* field) {
  requireFinite(value, field);
  if (value <= 0.0)
    throw ceilplan::InputError(std::string("vehicle geometry: ") + field + " must be positive, got " +
                               formatNumber(value));
}

void requireNonNegative(double value, const char* field) {
  requireFinite(value, field);
  if (value < 0.0)
    throw ceilplan::InputError(std::string("vehicle geometry: ") + field + " must not be negative, got " +
                               formatNumber(value));
}

}  // namespace

void VehicleGeometry::validate() const {
  if (rotor_positions_m.empty()) throw ceilplan::InputError("vehicle geometry: needs at least one rotor");
  for (const auto& rotor : rotor_positions_m) {
    requireFinite(rotor.x(), "rotor position x");
    requireFinite(rotor.y(), "rotor position y");
  }
  requirePositive(rotor_radius_m, "rotors.radius_m");
  requireFinite(rotor_plane_height_m, "rotors.plane_height_m");
  requireFinite(top_height_m, "airframe.top_height_m");
  requireFinite(bottom_height_m, "airframe.bottom_height_m");
  if (bottom_height_m > top_height_m)
    throw ceilplan::InputError("vehicle geometry: airframe.bottom_height_m lies above airframe.top_height_m");
  requirePositive(collision_radius_m, "airframe.collision_radius_m");
  requireNonNegative(margin_m, "clearance.margin_m");
  requireNonNegative(top_margin_m, "clearance.top_margin_m");
}

std::vector<Eigen::Vector2d> rotorPositions(RotorLayout layout, int count, double arm_length_m) {
  if (count < 1 || count > 16)
    throw ceilplan::InputError("vehicle geometry: rotors.count must be between 1 and 16, got " + std::to_string(count));
  requirePositive(arm_length_m, "rotors.arm_length_m");
  const double step = 2.0 * M_PI / count;
  const double first = layout == RotorLayout::X ? step / 2.0 : 0.0;
  std::vector<Eigen::Vector2d> positions;
  for (int i = 0; i < count; ++i) {
    const double angle = first + i * step;
    positions.emplace_back(arm_length_m * std::cos(angle), arm_length_m * std::sin(angle));
  }
  return positions;
}

}  // namespace ceilplan::environment
