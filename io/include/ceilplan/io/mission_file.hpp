#pragma once
/// @file
/// Mission files and battery files (docs/missions.md). Paths inside a mission file are relative
/// to it. Every key is checked before anything is planned: unknown keys (with the nearest valid
/// one), missing keys, wrong types, NaN and infinity, numbers outside their physical range, files
/// of the wrong kind, and files that do not exist.

#include "ceilplan/mission/battery_spec.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/vehicle.hpp"

#include <filesystem>

namespace ceilplan::io {

/// Throws ceilplan::InputError with one line "FILE: ..." naming the key.
mission::Mission readMission(const std::filesystem::path& file);

/// A battery file for `vehicle` (read from `vehicle_file`, empty for one built in code):
/// capacity_ah, charge_current_a, cell_count, soc_min, state_of_health, start_soc, reserve_soc at
/// its top level, each optional (the founding paper's pack at 95 % and the vehicle's cell count
/// otherwise); or a mission file, whose `battery:` section is read. Throws ceilplan::InputError,
/// naming both files for a cell count that is not the vehicle's.
mission::BatterySpec readBattery(const std::filesystem::path& file,
                                 const mission::Vehicle& vehicle = mission::Vehicle::defaultQuad(),
                                 const std::filesystem::path& vehicle_file = {});
/// readBattery, or for an empty path the founding paper's pack at 95 % (mission::BatterySpec{})
/// with the vehicle's cell count: what an optional --battery means.
mission::BatterySpec readBatteryOrDefault(const std::filesystem::path& file,
                                          const mission::Vehicle& vehicle = mission::Vehicle::defaultQuad(),
                                          const std::filesystem::path& vehicle_file = {});

}  // namespace ceilplan::io
