#pragma once
// Reads the energy model's parameters from a vehicle YAML file (maps/vehicles/quad.yaml) and
// writes calibrated ones back. The geometry keys (mass_kg, rotors.*) are shared with the
// rest of the vehicle file; everything energy-only lives under `power:` and `max_speed_m_s`.

#include "ceilplan/energy/energy_parameters.hpp"
#include "ceilplan/core/error.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>

namespace ceilplan::app {

struct VehicleEnergyFile {
  std::string name;  // the file's `name`, or "built-in default"
  energy::EnergyParameters parameters;
  YAML::Node document;  // the whole file, to be rewritten with calibrated values
};

// Throws ceilplan::InputError with one line naming the file and the bad key.
VehicleEnergyFile readVehicleEnergyFile(const std::filesystem::path& path);

// The founding paper's quadrotor (energy::paperQuadParameters) when no file is given.
VehicleEnergyFile builtInVehicle();

// The `power:` section (and `max_speed_m_s`) of `vehicle` replaced by explicit values of
// `parameters`, every other key kept; `comment` goes on top. Written atomically.
void writeVehicleEnergyFile(const std::filesystem::path& path, const VehicleEnergyFile& vehicle,
                            const energy::EnergyParameters& parameters, const std::string& comment);

}  // namespace ceilplan::app
