#pragma once
// Reads an inspection mission file (maps/*.yaml, documented in docs/missions.md): the map, the
// vehicle, the battery, home, the geodetic origin, speeds, mode, seed and the targets. Paths
// are resolved relative to the mission file.

#include "ceilplan/io/autopilot_export.hpp"

#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/viewpoint.hpp"
#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::app {

struct MissionSpeeds {
  double cruise_m_s = 2.0;
  double inspection_m_s = 0.5;
  double climb_m_s = 1.0;
  double descent_m_s = 0.8;
};

struct MissionFile {
  std::filesystem::path file;     // the mission file itself
  std::filesystem::path map;      // resolved against the mission file's directory
  std::filesystem::path vehicle;  // likewise
  mission::SortieBattery battery; // capacity_ah, charge_current_a, start_soc, reserve_soc
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();
  std::optional<mission::GeodeticOrigin> origin;  // only needed to export to an autopilot
  MissionSpeeds speeds;           // key `speeds`, every entry optional (defaults above)
  std::string mode;               // key `mode`, as written (optional; the command decides)
  std::uint64_t seed = 1;         // key `seed` (optional)
  std::vector<mission::InspectionTarget> targets;

  // The origin, or ceilplan::InputError naming the file and the missing key.
  const mission::GeodeticOrigin& requireOrigin() const;
};

// Throws ceilplan::InputError with one line "FILE: ..." naming the key: a missing file or key,
// malformed YAML, a wrong type, NaN or infinity, a non-positive capacity or charge current, an
// SOC outside [0, 1], a reserve at or above the start SOC, a bad standoff range or dwell,
// duplicate or empty target names, a map or vehicle file that does not exist.
MissionFile readMissionFile(const std::filesystem::path& file);

}  // namespace ceilplan::app
