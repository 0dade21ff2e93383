#pragma once
/// @file
/// The one vehicle type: everything ceilplan knows of a multirotor, read once from a vehicle
/// file (io::readVehicle, docs/missions.md) or built in. The map queries see its shape
/// (rotor discs, collision cylinder, clearance margins) and the energy model its airframe,
/// rotor power and pack electrics: two views of the same rotors, checked to agree.

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/energy/energy_parameters.hpp"
#include "ceilplan/environment/vehicle_geometry.hpp"

#include <optional>
#include <string>

namespace ceilplan::mission {

/// How hard the vehicle may accelerate and turn when a route is time-scaled into setpoints
/// (mission/trajectory.hpp). Defaults: PX4 v1.14's auto-mode MPC_ACC_HOR, MPC_JERK_AUTO and
/// MPC_YAWRAUTO_MAX (docs/flying.md).
struct MotionLimits {
  double max_acceleration_m_s2 = 3.0;  ///< largest acceleration
  double max_jerk_m_s3 = 4.0;          ///< largest jerk
  double max_yaw_rate_deg_s = 45.0;    ///< fastest yaw rate
};

/// A vehicle (a vehicle file, docs/planner.md): its shape, its energy model's constants and its motion limits.
struct Vehicle {
  std::string name;                       ///< for messages and reports
  environment::VehicleGeometry geometry;  ///< rotor discs, collision cylinder, clearance margins
  energy::EnergyParameters energy;        ///< mass, rotor spacing, power model, pack electrics
  MotionLimits limits;                    ///< vehicle file key `limits:`
  /// How well `calibrate` pinned the energy constants down (vehicle file key `calibration:`,
  /// docs/energy.md): what a mission's battery.reserve_confidence needs. Unset: not calibrated.
  std::optional<energy::FitUncertainty> calibration;

  /// The default vehicle, equal to maps/vehicles/quad.yaml (a test reads the file and compares):
  /// the founding paper's quadrotor, 1.4 kg, 10-inch propellers on a 450 mm X frame, 9.5 A in
  /// free-air hover and 8.0 A 5 cm under a ceiling (Kocer et al. 2019).
  static Vehicle defaultQuad();

  /// A vehicle from its shape and energy constants: the energy model's rotor count, radius and
  /// rotor spacings (the multirotor ground effect's d and b) are taken from the shape, so the
  /// two views cannot disagree. Validates.
  static Vehicle assemble(std::string name, environment::VehicleGeometry geometry, energy::EnergyParameters energy);

  /// Throws ceilplan::InputError naming the first bad field, or the disagreement between the
  /// shape and the energy model (rotor count, rotor radius).
  void validate() const;
};

}  // namespace ceilplan::mission
