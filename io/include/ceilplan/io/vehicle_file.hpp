#pragma once
/// @file
/// Vehicle files (maps/vehicles/quad.yaml documents every key; docs/missions.md lists their
/// ranges): the airframe, rotors, collision cylinder and clearance, and the energy model's
/// constants, read once into the one mission::Vehicle.

#include "ceilplan/energy/energy_parameters.hpp"
#include "ceilplan/mission/vehicle.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace ceilplan::io {

/// Throws ceilplan::InputError "FILE: ..." naming the key: a missing or unreadable file,
/// malformed YAML, an unknown key (with the nearest valid one), a missing key, a number outside
/// its physical range, a file of another kind.
mission::Vehicle readVehicle(const std::filesystem::path& file);
/// readVehicle, or for an empty path the built-in vehicle (mission::Vehicle::defaultQuad, as
/// maps/vehicles/quad.yaml): what every command's optional --vehicle means.
mission::Vehicle readVehicleOrDefault(const std::filesystem::path& file);

/// Writes a vehicle file with the energy model's constants replaced by explicit values of
/// `parameters` (power.* and max_speed_m_s; hover power and K1, K2 rather than the anchors they
/// were solved from), every other key of `source` kept; with no `source`, the built-in vehicle.
/// `comment` goes on top; `calibration` (when given) is written under the key `calibration:`
/// (its residual spread, and the covariance when it has one). Written atomically.
void writeCalibratedVehicle(const std::filesystem::path& out, const std::filesystem::path& source,
                            const energy::EnergyParameters& parameters, const std::string& comment,
                            const std::optional<energy::FitUncertainty>& calibration = std::nullopt);

}  // namespace ceilplan::io
