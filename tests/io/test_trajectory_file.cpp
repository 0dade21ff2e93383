// Trajectory files: the CSV and JSON forms read back with real parsers give the setpoints, NED
// is the documented conversion, and the path reader takes path.csv's and trajectory.csv's
// columns by name.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/trajectory_file.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace ceilplan::io {
namespace {

constexpr double kPi = 3.14159265358979323846;

mission::Trajectory sampleTrajectory() {
  mission::SortieRoute route;
  route.home_m = {-4, 0, 0.5};
  route.waypoints = {{{-4, 0, 3}}, {{6, 1, 3}, 2.0, 45.0}, {{6, 5, 4}}, {{-4, 0, 3}}, {{-4, 0, 0.5}}};
  route.waypoints[1].take_photo = true;
  route.waypoints[1].gimbal_pitch_deg = 60.0;
  return mission::timeScale(route, mission::TrajectoryLimits{});
}

std::filesystem::path writeText(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file) << text;
  return file;
}

TEST(TrajectoryFile, CsvHasTheDocumentedColumnsAndEverySetpoint) {
  const mission::Trajectory t = sampleTrajectory();
  const std::filesystem::path dir = testing::scratchDirectory("trajectory_csv");
  writeTrajectoryCsv(dir / "trajectory.csv", t, TrajectoryFrame::Enu, Provenance::of("test"));
  const std::vector<std::string> expected{
      "t_s",     "x_m",     "y_m",     "z_m",     "vx_m_s",         "vy_m_s",           "vz_m_s",
      "ax_m_s2", "ay_m_s2", "az_m_s2", "yaw_rad", "yaw_rate_rad_s", "gimbal_pitch_deg", "trigger"};
  const CsvColumns table = CsvColumns::read(dir / "trajectory.csv", expected);
  EXPECT_EQ(table.columnNames(), expected);
  ASSERT_EQ(table.rowCount(), t.setpoints.size());
  int triggers = 0;
  for (std::size_t k = 0; k < t.setpoints.size(); ++k) {
    const mission::TrajectorySetpoint& s = t.setpoints[k];
    EXPECT_NEAR(table.column("t_s")[k], s.t_s, 5e-4);
    EXPECT_NEAR(table.column("x_m")[k], s.position_m.x(), 1e-6);
    EXPECT_NEAR(table.column("y_m")[k], s.position_m.y(), 1e-6);
    EXPECT_NEAR(table.column("z_m")[k], s.position_m.z(), 1e-6);
    EXPECT_NEAR(table.column("vz_m_s")[k], s.velocity_m_s.z(), 1e-6);
    EXPECT_NEAR(table.column("ax_m_s2")[k], s.acceleration_m_s2.x(), 1e-6);
    EXPECT_NEAR(table.column("yaw_rad")[k], s.yaw_rad, 1e-6);
    EXPECT_NEAR(table.column("yaw_rate_rad_s")[k], s.yaw_rate_rad_s, 1e-6);
    EXPECT_NEAR(table.column("gimbal_pitch_deg")[k], s.gimbal_pitch_deg, 1e-4);
    EXPECT_EQ(table.column("trigger")[k], s.trigger ? 1.0 : 0.0);
    triggers += s.trigger;
  }
  EXPECT_EQ(triggers, 1);
  EXPECT_EQ(testing::readWholeFile(dir / "trajectory.csv").find("-0.000000"), std::string::npos);
}

TEST(TrajectoryFile, NedSwapsTheAxesNegatesUpAndTurnsYawToCompass) {
  const mission::Trajectory t = sampleTrajectory();
  const std::vector<std::string> columns = trajectoryColumns(TrajectoryFrame::Ned);
  EXPECT_EQ(columns[1], "north_m");
  EXPECT_EQ(columns[2], "east_m");
  EXPECT_EQ(columns[3], "down_m");
  for (const mission::TrajectorySetpoint& s : t.setpoints) {
    const std::vector<double> enu = trajectoryRow(s, TrajectoryFrame::Enu),
                              ned = trajectoryRow(s, TrajectoryFrame::Ned);
    for (int block : {1, 4, 7}) {
      EXPECT_DOUBLE_EQ(ned[block], enu[block + 1]);
      EXPECT_DOUBLE_EQ(ned[block + 1], enu[block]);
      EXPECT_DOUBLE_EQ(ned[block + 2], -enu[block + 2]);
    }
    EXPECT_NEAR(std::remainder(ned[10] - (kPi / 2 - enu[10]), 2 * kPi), 0.0, 1e-12);
    EXPECT_GT(ned[10], -kPi - 1e-12);
    EXPECT_LE(ned[10], kPi + 1e-12);
    EXPECT_DOUBLE_EQ(ned[11], -enu[11]);
  }
  // Heading 45 (north-east) at the photo: NED yaw pi/4.
  for (const mission::TrajectorySetpoint& s : t.setpoints)
    if (s.trigger) {
      EXPECT_NEAR(trajectoryRow(s, TrajectoryFrame::Ned)[10], kPi / 4, 1e-9);
    }
}

TEST(TrajectoryFile, JsonCarriesTheSetpointsTheFrameAndTheLimits) {
  const mission::Trajectory t = sampleTrajectory();
  const std::filesystem::path dir = testing::scratchDirectory("trajectory_json");
  const mission::GeodeticOrigin origin{52.218, 0.0923, 12.0};
  writeTrajectoryJson(dir / "trajectory.json", t, TrajectoryFrame::Ned, origin, Provenance::of("test"));
  const nlohmann::json json = nlohmann::json::parse(testing::readWholeFile(dir / "trajectory.json"));
  EXPECT_EQ(json.at("format"), "ceilplan-trajectory");
  EXPECT_EQ(json.at("version"), 1);
  EXPECT_EQ(json.at("sortie"), 1);
  EXPECT_EQ(json.at("frame"), "NED");
  EXPECT_EQ(json.at("rate_hz"), 20.0);
  EXPECT_DOUBLE_EQ(json.at("duration_s").get<double>(), t.duration_s());
  EXPECT_EQ(json.at("photos"), 1);
  EXPECT_EQ(json.at("stops"), t.stops);
  EXPECT_EQ(json.at("limits").at("max_jerk_m_s3"), 4.0);
  EXPECT_EQ(json.at("origin").at("lat_deg"), 52.218);
  EXPECT_EQ(json.at("columns").get<std::vector<std::string>>(), trajectoryColumns(TrajectoryFrame::Ned));
  const nlohmann::json& rows = json.at("setpoints");
  ASSERT_EQ(rows.size(), t.setpoints.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::vector<double> expected = trajectoryRow(t.setpoints[k], TrajectoryFrame::Ned);
    ASSERT_EQ(rows[k].size(), expected.size());
    for (std::size_t c = 0; c < expected.size(); ++c) EXPECT_DOUBLE_EQ(rows[k][c].get<double>(), expected[c]);
  }
  EXPECT_TRUE(trajectoryJson(t).at("origin").is_null());
  EXPECT_EQ(trajectoryJson(t).at("frame"), "ENU");
}

TEST(TrajectoryFile, TheWrittenJsonIsTheDocumentsTextRowByRow) {
  // writeTrajectoryJson writes the rows into the text without making them a document first;
  // the file is still trajectoryJson's compact text with the provenance, to the byte.
  const mission::Trajectory t = sampleTrajectory();
  const std::filesystem::path dir = testing::scratchDirectory("trajectory_json_text");
  const mission::GeodeticOrigin origin{52.218, 0.0923, 12.0};
  const Provenance provenance = Provenance::of("test \"setpoints\":[] quoted");
  for (const TrajectoryFrame frame : {TrajectoryFrame::Enu, TrajectoryFrame::Ned}) {
    writeTrajectoryJson(dir / "trajectory.json", t, frame, origin, provenance);
    EXPECT_EQ(testing::readWholeFile(dir / "trajectory.json"),
              jsonText(withProvenance(trajectoryJson(t, frame, origin), provenance)) + "\n");
  }
}

TEST(PathCsv, ReadsPathCsvAndTrajectoryCsvColumnsByName) {
  const std::filesystem::path dir = testing::scratchDirectory("path_csv");
  // path.csv as the tour writes it: an empty gap where no ceiling is above, joints repeated.
  const auto tour = writeText(dir / "path.csv",
                              "t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,sortie\n"
                              "0,-4,0,0.5,1,,9.5,0.95,1\n1,-4,0,1.5,1,,9.5,0.94,1\n1,-4,0,1.5,0,,9.4,0.94,1\n"
                              "2,-3,0,1.5,1,0.5,9,0.93,1\n");
  const std::vector<Eigen::Vector3d> from_tour = readPathWaypoints(tour);
  ASSERT_EQ(from_tour.size(), 3u);
  EXPECT_EQ(from_tour[2], Eigen::Vector3d(-3, 0, 1.5));
  const mission::Trajectory t = sampleTrajectory();
  writeTrajectoryCsv(dir / "trajectory.csv", t, TrajectoryFrame::Enu, Provenance::of("test"));
  const std::vector<Eigen::Vector3d> from_trajectory = readPathWaypoints(dir / "trajectory.csv");
  EXPECT_LT(from_trajectory.size(), t.setpoints.size());  // hovering setpoints once
  EXPECT_LT((from_trajectory.front() - t.setpoints.front().position_m).norm(), 1e-6);
  EXPECT_LT((from_trajectory.back() - t.setpoints.back().position_m).norm(), 1e-6);
  // Columns in any order, others ignored.
  const auto any = writeText(dir / "any.csv", "note,z,y,x\n1,3,2,1\n2,6,5,4\n");
  EXPECT_EQ(readPathWaypoints(any)[1], Eigen::Vector3d(4, 5, 6));
}

TEST(PathCsv, RefusesWhatIsNotAMapFramePath) {
  const std::filesystem::path dir = testing::scratchDirectory("path_csv_bad");
  const auto refuses = [&](const std::string& name, const std::string& text, const std::string& words) {
    try {
      readPathWaypoints(writeText(dir / name, text));
      ADD_FAILURE() << name;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  const mission::Trajectory t = sampleTrajectory();
  writeTrajectoryCsv(dir / "ned.csv", t, TrajectoryFrame::Ned, Provenance::of("test"));
  refuses("ned.csv", testing::readWholeFile(dir / "ned.csv"), "is in the NED frame");
  refuses("none.csv", "a,b,c\n1,2,3\n4,5,6\n", "neither x, y, z");
  refuses("one.csv", "x,y,z\n1,2,3\n1,2,3\n", "at least 2 distinct points");
  refuses("gap.csv", "x,y,z\n1,,3\n4,5,6\n", "line 2, column 'y': empty field");
  refuses("text.csv", "x,y,z\n1,a,3\n4,5,6\n", "'a' is not a number");
}

}  // namespace
}  // namespace ceilplan::io
