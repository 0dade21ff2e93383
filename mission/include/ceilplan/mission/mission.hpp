#pragma once
/// An inspection mission: the map, the vehicle, the battery, home, where the map lies on the
/// Earth, the planning settings and what to inspect: point targets, surfaces to photograph and contact
/// grids (a coverage mission: docs/coverage.md). Read from a mission file by io::readMission
/// (docs/missions.md).

#include "ceilplan/mission/battery_spec.hpp"
#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/dji_aircraft.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/planning_options.hpp"
#include "ceilplan/mission/trajectory.hpp"
#include "ceilplan/mission/vehicle.hpp"
#include "ceilplan/mission/viewpoint.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// A mission file's contents (docs/missions.md): what planTour plans and io::readMission reads.
struct Mission {
  std::filesystem::path file;          ///< the mission file, empty for a mission built in code
  std::filesystem::path map_file;      ///< the OctoMap (.bt or .ot)
  std::filesystem::path vehicle_file;  ///< empty: the built-in vehicle
  /// the vehicle file's, or the built-in quadrotor
  Vehicle vehicle = Vehicle::defaultQuad();
  BatterySpec battery;  ///< the battery file's (key `battery:`), or the founding paper's pack
  /// take-off and landing point of every sortie, map coordinates
  Eigen::Vector3d home_m = Eigen::Vector3d::Zero();
  std::optional<GeodeticOrigin> origin;  ///< needed only to export to an autopilot
  /// Every planning setting: the file's `speeds:`, `seed:` and `unknown:` (what the map's unknown
  /// voxels count as, docs/environment.md), the rest at their defaults; front ends override fields.
  PlanningOptions planning;
  std::string mode;                       ///< "ceiling", "free" or "both"; empty: the command decides
  TrajectoryOptions trajectory;           ///< time scaling of the flown routes (key `trajectory:`, docs/flying.md)
  bool trajectory_ned = false;            ///< trajectory files in NED instead of the map's ENU
  DjiAircraft dji;                        ///< the KMZ's aircraft, payload and failsafes (key `dji:`)
  std::vector<InspectionTarget> targets;  ///< point targets, each seen from a viewpoint in its standoff range
  /// Coverage (docs/coverage.md): surfaces photographed with the camera, contact grids probed.
  std::optional<Camera> camera;            ///< required by surfaces
  std::vector<CoverageRegion> surfaces;    ///< regions photographed at the camera's GSD and overlap
  std::vector<ContactGrid> contact_grids;  ///< grids of contact points, each probed from below

  /// A coverage mission: it has surfaces or contact grids (point targets may come along).
  bool isCoverage() const { return !surfaces.empty() || !contact_grids.empty(); }

  /// A name for messages: the mission file, or "mission".
  std::string name() const { return file.empty() ? std::string("mission") : file.string(); }

  /// The origin, or ceilplan::InputError naming the mission and the missing key.
  const GeodeticOrigin& requireOrigin() const;
};

}  // namespace ceilplan::mission
