#include "ceilplan/mission/vehicle.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ceilplan::mission {

Vehicle Vehicle::defaultQuad() {
  environment::VehicleGeometry shape;
  // A 450 mm diagonal X frame (0.225 m arms) with 10-inch (0.254 m) propellers.
  shape.rotor_positions_m = environment::rotorPositions(environment::RotorLayout::X, 4, 0.225);
  shape.rotor_radius_m = 0.127;
  shape.rotor_plane_height_m = 0.03;
  shape.top_height_m = 0.06;
  shape.bottom_height_m = -0.12;
  shape.collision_radius_m = 0.36;  // arm + propeller radius, rounded up
  shape.margin_m = 0.10;
  shape.top_margin_m = 0.02;  // contact-style ceiling work needs it small
  return assemble("quad-10in", shape, energy::paperQuadParameters());
}

Vehicle Vehicle::assemble(std::string name, environment::VehicleGeometry geometry, energy::EnergyParameters energy) {
  Vehicle vehicle;
  vehicle.name = std::move(name);
  geometry.name = vehicle.name;
  energy::AirframeParameters& airframe = energy.airframe;
  const std::vector<Eigen::Vector2d>& rotors = geometry.rotor_positions_m;
  airframe.rotor_count = static_cast<int>(rotors.size());
  airframe.rotor_radius_m = geometry.rotor_radius_m;
  // d (adjacent) and b (opposite): the smallest and the largest distance between two rotor axes.
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (std::size_t i = 0; i < rotors.size(); ++i)
    for (std::size_t j = i + 1; j < rotors.size(); ++j) {
      const double distance = std::hypot(rotors[i].x() - rotors[j].x(), rotors[i].y() - rotors[j].y());
      smallest = std::min(smallest, distance);
      largest = std::max(largest, distance);
    }
  airframe.adjacent_rotor_spacing_m = rotors.size() > 1 ? smallest : 0.0;
  airframe.opposite_rotor_spacing_m = largest;
  vehicle.geometry = std::move(geometry);
  vehicle.energy = energy;
  vehicle.validate();
  return vehicle;
}

void Vehicle::validate() const {
  geometry.validate();
  const energy::EnergyModel check(energy);  // every rule of the energy model's parameters
  const int rotors = static_cast<int>(geometry.rotor_positions_m.size());
  if (rotors != energy.airframe.rotor_count)
    throw InputError("vehicle '" + name + "': the shape has " + std::to_string(rotors) + " rotors, the energy model " +
                     std::to_string(energy.airframe.rotor_count));
  if (std::abs(geometry.rotor_radius_m - energy.airframe.rotor_radius_m) > 1e-12)
    throw InputError("vehicle '" + name + "': rotor radius " + formatNumber(geometry.rotor_radius_m) +
                     " m in the shape, " + formatNumber(energy.airframe.rotor_radius_m) + " m in the energy model");
}

}  // namespace ceilplan::mission
