#include "ceilplan/io/trajectory_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/json_values.hpp"
#include "json_number.hpp"

#include <array>
#include <cmath>
#include <iterator>

namespace ceilplan::io {
namespace {

constexpr double kPi = 3.14159265358979323846;

// ENU -> NED: swap x and y, negate z.
Eigen::Vector3d toNed(const Eigen::Vector3d& enu) { return {enu.y(), enu.x(), -enu.z()}; }

double wrapAngle(double radians) {
  const double wrapped = std::remainder(radians, 2.0 * kPi);
  return wrapped <= -kPi ? wrapped + 2.0 * kPi : wrapped;
}

// Decimals per column: time, then 9 lengths, yaw, yaw rate, pitch, trigger.
constexpr int kDecimals[] = {3, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 6, 4, 0};
constexpr std::size_t kColumns = std::size(kDecimals);

// trajectoryRow without a vector of its own: a long sortie has tens of thousands of rows.
std::array<double, kColumns> rowValues(const mission::TrajectorySetpoint& s, TrajectoryFrame frame) {
  const bool ned = frame == TrajectoryFrame::Ned;
  const Eigen::Vector3d p = ned ? toNed(s.position_m) : s.position_m;
  const Eigen::Vector3d v = ned ? toNed(s.velocity_m_s) : s.velocity_m_s;
  const Eigen::Vector3d a = ned ? toNed(s.acceleration_m_s2) : s.acceleration_m_s2;
  // NED yaw is clockwise from north: pi/2 - ENU yaw.
  const double yaw = ned ? wrapAngle(0.5 * kPi - s.yaw_rad) : s.yaw_rad;
  const double yaw_rate = ned ? -s.yaw_rate_rad_s : s.yaw_rate_rad_s;
  return {s.t_s,
          p.x(),
          p.y(),
          p.z(),
          v.x(),
          v.y(),
          v.z(),
          a.x(),
          a.y(),
          a.z(),
          yaw,
          yaw_rate,
          s.gimbal_pitch_deg,
          s.trigger ? 1.0 : 0.0};
}

}  // namespace

std::vector<std::string> trajectoryColumns(TrajectoryFrame frame) {
  if (frame == TrajectoryFrame::Ned)
    return {"t_s",     "north_m", "east_m",  "down_m",  "vn_m_s",         "ve_m_s",           "vd_m_s",
            "an_m_s2", "ae_m_s2", "ad_m_s2", "yaw_rad", "yaw_rate_rad_s", "gimbal_pitch_deg", "trigger"};
  return {"t_s",     "x_m",     "y_m",     "z_m",     "vx_m_s",         "vy_m_s",           "vz_m_s",
          "ax_m_s2", "ay_m_s2", "az_m_s2", "yaw_rad", "yaw_rate_rad_s", "gimbal_pitch_deg", "trigger"};
}

std::vector<double> trajectoryRow(const mission::TrajectorySetpoint& s, TrajectoryFrame frame) {
  const std::array<double, kColumns> row = rowValues(s, frame);
  return {row.begin(), row.end()};
}

std::string trajectoryCsv(const mission::Trajectory& trajectory, TrajectoryFrame frame) {
  std::string text;
  const std::vector<std::string> columns = trajectoryColumns(frame);
  for (std::size_t c = 0; c < columns.size(); ++c) text += (c ? "," : "") + columns[c];
  text += '\n';
  // About 14 fields of up to 12 characters a row: reserved once, not grown row by row.
  text.reserve(text.size() + trajectory.setpoints.size() * 14 * 12);
  for (const mission::TrajectorySetpoint& s : trajectory.setpoints) {
    const std::array<double, kColumns> row = rowValues(s, frame);
    for (std::size_t c = 0; c < row.size(); ++c) {
      if (c) text += ',';
      const std::size_t start = text.size();
      appendFixed(text, row[c], kDecimals[c]);
      // Rounding may leave "-0.000000": write a plain zero.
      if (text[start] == '-' && text.find_first_not_of("0.", start + 1) == std::string::npos) text.erase(start, 1);
    }
    text += '\n';
  }
  return text;
}

namespace {

// trajectory.json without its setpoints.
nlohmann::json trajectoryHeader(const mission::Trajectory& trajectory, TrajectoryFrame frame,
                                const std::optional<mission::GeodeticOrigin>& origin) {
  const mission::TrajectoryLimits& l = trajectory.limits;
  return {{"format", "ceilplan-trajectory"},
          {"version", 1},
          {"sortie", trajectory.sortie},
          {"frame", frame == TrajectoryFrame::Ned ? "NED" : "ENU"},
          {"rate_hz", trajectory.rate_hz},
          {"duration_s", trajectory.duration_s()},
          {"length_m", trajectory.length_m},
          {"stops", trajectory.stops},
          {"blended_corners", trajectory.blended_corners},
          {"photos", trajectory.photos},
          {"max_corner_deviation_m", trajectory.max_corner_deviation_m},
          {"limits",
           {{"climb_m_s", l.climb_m_s},
            {"descent_m_s", l.descent_m_s},
            {"max_acceleration_m_s2", l.max_acceleration_m_s2},
            {"max_jerk_m_s3", l.max_jerk_m_s3},
            {"max_yaw_rate_deg_s", l.max_yaw_rate_deg_s}}},
          {"origin", origin ? nlohmann::json{{"lat_deg", origin->latitude_deg},
                                             {"lon_deg", origin->longitude_deg},
                                             {"alt_m", origin->altitude_m}}
                            : nlohmann::json(nullptr)},
          {"columns", trajectoryColumns(frame)}};
}

// One setpoint as trajectory.json holds it: the row's numbers, the trigger as an integer.
nlohmann::json rowJson(const mission::TrajectorySetpoint& s, TrajectoryFrame frame) {
  const std::array<double, kColumns> row = rowValues(s, frame);
  nlohmann::json::array_t values(row.begin(), row.end() - 1);
  values.emplace_back(s.trigger ? 1 : 0);
  return values;
}

// Appends jsonText(rowJson(s, frame)), without a document or serializer of its own.
void appendRowJson(std::string& text, const mission::TrajectorySetpoint& s, TrajectoryFrame frame) {
  const std::array<double, kColumns> row = rowValues(s, frame);
  text += '[';
  for (std::size_t c = 0; c + 1 < row.size(); ++c) {
    appendJsonNumber(text, row[c]);
    text += ',';
  }
  text += s.trigger ? "1]" : "0]";
}

}  // namespace

nlohmann::json trajectoryJson(const mission::Trajectory& trajectory, TrajectoryFrame frame,
                              const std::optional<mission::GeodeticOrigin>& origin) {
  // Arrays sized before they are filled: a long sortie has tens of thousands of setpoints.
  nlohmann::json::array_t setpoints;
  setpoints.reserve(trajectory.setpoints.size());
  for (const mission::TrajectorySetpoint& s : trajectory.setpoints) setpoints.emplace_back(rowJson(s, frame));
  nlohmann::json json = trajectoryHeader(trajectory, frame, origin);
  json["setpoints"] = std::move(setpoints);
  return json;
}

void writeTrajectoryCsv(const std::filesystem::path& file, const mission::Trajectory& trajectory, TrajectoryFrame frame,
                        const Provenance& provenance) {
  const std::string comment = provenance.csvComment(), csv = trajectoryCsv(trajectory, frame);
  writeTextAtomically(file, [&](std::ostream& out) { out << comment << '\n' << csv; });
}

void writeTrajectoryJson(const std::filesystem::path& file, const mission::Trajectory& trajectory,
                         TrajectoryFrame frame, const std::optional<mission::GeodeticOrigin>& origin,
                         const Provenance& provenance) {
  // trajectoryJson's text, with the setpoints written row by row into the header's empty array
  // instead of made a document first (a long sortie's rows are most of the tour's output). In
  // compact JSON a quote inside a string is escaped, so the empty array's key is found only as
  // the key itself.
  nlohmann::json header = trajectoryHeader(trajectory, frame, origin);
  header["setpoints"] = nlohmann::json::array();
  const std::string skeleton = jsonText(withProvenance(std::move(header), provenance));
  const std::string key = "\"setpoints\":[";
  const std::size_t at = skeleton.find(key + "]");
  if (at == std::string::npos) throw Error("trajectory.json lacks its setpoints");
  const std::size_t rows_at = at + key.size();
  std::string text = skeleton.substr(0, rows_at);
  text.reserve(skeleton.size() + trajectory.setpoints.size() * 14 * 12);
  for (std::size_t k = 0; k < trajectory.setpoints.size(); ++k) {
    if (k) text += ',';
    appendRowJson(text, trajectory.setpoints[k], frame);
  }
  text.append(skeleton, rows_at, std::string::npos);
  text += '\n';
  writeTextAtomically(file, [&](std::ostream& out) { out << text; });
}

}  // namespace ceilplan::io
