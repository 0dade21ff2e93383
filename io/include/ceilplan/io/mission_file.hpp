#pragma once
/// @file
/// Mission files and battery files (docs/missions.md). Paths inside a mission file are relative
/// to it. Every key is checked before anything is planned: unknown keys (with the nearest valid
/// one), missing keys, wrong types, NaN and infinity, numbers outside their physical range, files
/// of the wrong kind, and files that do not exist.

#include "ceilplan/mission/battery_spec.hpp"
#include "ceilplan/mission/mission.hpp"

#include <filesystem>

namespace ceilplan::io {

/// Throws ceilplan::InputError with one line "FILE: ..." naming the key.
mission::Mission readMission(const std::filesystem::path& file);

/// A battery file: capacity_ah, charge_current_a, cell_count, soc_min, state_of_health,
/// start_soc, reserve_soc at its top level, each optional (the founding paper's pack at 95 %
/// otherwise); or a mission file, whose `battery:` section is read. Throws ceilplan::InputError.
mission::BatterySpec readBattery(const std::filesystem::path& file);
/// readBattery, or for an empty path the founding paper's pack at 95 % (mission::BatterySpec{}):
/// what an optional --battery means.
mission::BatterySpec readBatteryOrDefault(const std::filesystem::path& file);

}  // namespace ceilplan::io
