#pragma once
/// @file
/// Writes a time-scaled trajectory (mission/trajectory.hpp) as CSV and JSON, in the map frame
/// (ENU: x east, y north, z up; yaw counter-clockwise from east) or in PX4's local NED frame
/// (x north, y east, z down; yaw clockwise from north), docs/flying.md.
///
/// ENU columns: t_s, x_m, y_m, z_m, vx_m_s, vy_m_s, vz_m_s, ax_m_s2, ay_m_s2, az_m_s2, yaw_rad,
/// yaw_rate_rad_s, gimbal_pitch_deg, trigger. NED columns name the axes: north_m, east_m,
/// down_m, vn_m_s, ve_m_s, vd_m_s, an_m_s2, ae_m_s2, ad_m_s2, so a file cannot be read in the
/// wrong frame by mistake.

#include "ceilplan/io/provenance.hpp"
#include "ceilplan/mission/geodetic_origin.hpp"
#include "ceilplan/mission/trajectory.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

/// The frame a trajectory file is written in: the map's ENU, or NED for PX4's TrajectorySetpoint.
enum class TrajectoryFrame {
  Enu,  ///< the map's frame: x east, y north, z up
  Ned   ///< north, east, down (PX4's local frame)
};

/// The column names of a trajectory row in `frame`.
std::vector<std::string> trajectoryColumns(TrajectoryFrame frame);

/// One row of numbers per setpoint, in trajectoryColumns' order (trigger 0 or 1).
std::vector<double> trajectoryRow(const mission::TrajectorySetpoint& setpoint, TrajectoryFrame frame);

/// Header, then one row per setpoint: time to 1 ms, lengths to 1 um, angles to 1 urad.
std::string trajectoryCsv(const mission::Trajectory& trajectory, TrajectoryFrame frame = TrajectoryFrame::Enu);

/// {"format": "ceilplan-trajectory", "version": 1, "sortie", "frame", "rate_hz", "duration_s",
///  "length_m", "stops", "blended_corners", "photos", "max_corner_deviation_m", "limits",
///  "origin" (the map frame's geodetic origin, or null), "columns", "setpoints": [[row], ...]}
nlohmann::json trajectoryJson(const mission::Trajectory& trajectory, TrajectoryFrame frame = TrajectoryFrame::Enu,
                              const std::optional<mission::GeodeticOrigin>& origin = std::nullopt);

/// Both written atomically (whole or not at all), with `provenance`: the CSV's first line is its
/// comment, the JSON holds it as "provenance".
void writeTrajectoryCsv(const std::filesystem::path& file, const mission::Trajectory& trajectory, TrajectoryFrame frame,
                        const Provenance& provenance);
/// trajectory.json, written atomically with `provenance`.
void writeTrajectoryJson(const std::filesystem::path& file, const mission::Trajectory& trajectory,
                         TrajectoryFrame frame, const std::optional<mission::GeodeticOrigin>& origin,
                         const Provenance& provenance);

}  // namespace ceilplan::io
