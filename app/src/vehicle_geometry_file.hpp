#pragma once
// Reads the geometry keys of a vehicle file (maps/vehicles/quad.yaml documents them) into an
// environment::VehicleGeometry; other keys (mass, power, ...) belong to other readers.

#include "ceilplan/environment/vehicle_geometry.hpp"
#include "ceilplan/core/error.hpp"

#include <filesystem>

namespace ceilplan::app {

// Throws ceilplan::InputError naming the file and the missing or bad key.
environment::VehicleGeometry readVehicleGeometry(const std::filesystem::path& file);

// The vehicle file used when none is given: maps/vehicles/quad.yaml under the current directory.
std::filesystem::path defaultVehicleFile();

}  // namespace ceilplan::app
