// The shipped missions flown: each tour's sorties (from `ceilplan tour --mode both`, run by the
// ctest fixtures into CEILPLAN_TOURS_DIR) become trajectories that stay within every limit they
// were given, by finite differences, and whose positions pass the dense re-check; on the bridge,
// every export is written and read back with a real parser, each waypoint within 1 cm.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/dji_wpml.hpp"
#include "ceilplan/io/geo_export.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/report_html.hpp"
#include "ceilplan/io/trajectory_file.hpp"
#include "export_parsers.hpp"
#include "flying_fixture.hpp"
#include "run_command.hpp"
#include "trajectory_checks.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <chrono>

namespace ceilplan::testing {
namespace {

const std::filesystem::path kMaps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";
const std::filesystem::path kTours = CEILPLAN_TOURS_DIR;

// `mission_file`'s tour, planned by the fixture into kTours / name.
void flyShippedMission(const std::string& name, const std::filesystem::path& mission_file) {
  const MissionFacts facts = readMissionFacts(mission_file);
  const MapCheck map(facts);
  const std::vector<TourOutput> outputs = readTourOutputs(kTours / name, facts);
  ASSERT_EQ(outputs.size(), 2u);
  mission::TrajectoryOptions options;
  options.path_is_safe = [&](const std::vector<Eigen::Vector3d>& p) { return map.safe(p); };
  for (const TourOutput& output : outputs) {
    for (const mission::SortieRoute& route : output.routes) {
      SCOPED_TRACE(name + " " + output.mode + " sortie " + std::to_string(route.sortie));
      const auto start = std::chrono::steady_clock::now();
      const mission::Trajectory t = mission::timeScale(route, trajectoryLimits(facts), options);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      double fastest = route.cruise_speed_m_s;
      for (const mission::RouteWaypoint& w : route.waypoints) fastest = std::max(fastest, w.speed_m_s.value_or(0.0));
      expectWithinLimits(t, fastest);
      std::vector<Eigen::Vector3d> positions;
      for (const auto& s : t.setpoints) positions.push_back(s.position_m);
      const auto violation = map.environment->checkPathDensely(positions);
      EXPECT_FALSE(violation) << violation->describe();
      const auto rule = map.rules->checkPathDensely(positions);
      EXPECT_FALSE(rule) << *rule;
      // Every photo pose (one per target) is flown to, at rest, with its trigger.
      int photos = 0;
      for (const mission::RouteWaypoint& w : route.waypoints) photos += w.take_photo;
      EXPECT_EQ(t.photos, photos);
      EXPECT_GT(t.blended_corners, 0);
      std::printf(
          "%s %s sortie %d: %zu setpoints, %.1f s (route %.1f m), %d stops, %d blended corners "
          "(furthest %.3f m off), generated in %.3f s\n",
          name.c_str(), output.mode.c_str(), route.sortie, t.setpoints.size(), t.duration_s(), t.length_m, t.stops,
          t.blended_corners, t.max_corner_deviation_m, seconds);
    }
  }
}

void flyShippedMission(const std::string& name) { flyShippedMission(name, kMaps / (name + ".yaml")); }

TEST(ShippedTrajectories, Bridge) { flyShippedMission("bridge"); }
TEST(ShippedTrajectories, Tunnel) { flyShippedMission("tunnel"); }
TEST(ShippedTrajectories, Warehouse) { flyShippedMission("warehouse"); }
TEST(ShippedTrajectories, Open) { flyShippedMission("open"); }
// A coverage tour: photo stops, contact points and a point target (test_coverage_tour_files.cpp).
TEST(ShippedTrajectories, CoverageStrip) {
  flyShippedMission("bridge_strip",
                    std::filesystem::path(CEILPLAN_SOURCE_DIR) / "tests/coverage/missions/bridge_strip.yaml");
}

// The bridge's ceiling-mode sortie, every format written and read back.
class BridgeExports : public ::testing::Test {
 protected:
  void SetUp() override {
    facts_ = readMissionFacts(kMaps / "bridge.yaml");
    output_ = readTourOutput(kTours / "bridge" / "ceiling", facts_);
    ASSERT_EQ(output_.routes.size(), 1u);
    route_ = output_.routes[0];
    dir_ = scratchDirectory("bridge_exports_" +
                            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  }
  MissionFacts facts_;
  TourOutput output_;
  mission::SortieRoute route_;
  std::filesystem::path dir_;
};

TEST_F(BridgeExports, TrajectoryCsvReadsBackWithinLimitsAndAsAPath) {
  const MapCheck map(facts_);
  mission::TrajectoryOptions options;
  options.path_is_safe = [&](const std::vector<Eigen::Vector3d>& p) { return map.safe(p); };
  const mission::Trajectory t = mission::timeScale(route_, trajectoryLimits(facts_), options);
  const io::Provenance provenance = io::Provenance::of("test_flying_tours");
  io::writeTrajectoryCsv(dir_ / "trajectory.csv", t, io::TrajectoryFrame::Enu, provenance);
  io::writeTrajectoryJson(dir_ / "trajectory.json", t, io::TrajectoryFrame::Enu, facts_.origin, provenance);
  // Read back as numbers written to micrometres: the limits still hold by finite differences
  // (rounding adds at most 8 x 0.5 um / dt^3 = 0.03 m/s^3 to the jerk).
  const io::CsvColumns table = io::CsvColumns::read(dir_ / "trajectory.csv", {"t_s", "x_m", "y_m", "z_m", "yaw_rad"});
  std::vector<mission::TrajectorySetpoint> read(table.rowCount());
  for (std::size_t k = 0; k < read.size(); ++k) {
    read[k].t_s = table.column("t_s")[k];
    read[k].position_m = {table.column("x_m")[k], table.column("y_m")[k], table.column("z_m")[k]};
    read[k].yaw_rad = table.column("yaw_rad")[k];
    EXPECT_NEAR(read[k].t_s, k / t.rate_hz, 1e-9);
  }
  const FiniteDifferenceMaxima m = finiteDifferenceMaxima(read, t.rate_hz);
  EXPECT_LE(m.jerk_m_s3, t.limits.max_jerk_m_s3 + 0.05);
  EXPECT_LE(m.acceleration_m_s2, t.limits.max_acceleration_m_s2 + 0.01);
  EXPECT_LE(m.climb_m_s, t.limits.climb_m_s + 1e-3);
  EXPECT_LE(m.descent_m_s, t.limits.descent_m_s + 1e-3);
  EXPECT_LE(m.yaw_rate_deg_s, t.limits.max_yaw_rate_deg_s + 0.01);
  // As `ceilplan evaluate` will read it: the path reader takes the file, and the dense re-check passes.
  const std::vector<Eigen::Vector3d> path = io::readPathWaypoints(dir_ / "trajectory.csv");
  EXPECT_GT(path.size(), 100u);
  EXPECT_FALSE(map.environment->checkPathDensely(path));
  const std::vector<Eigen::Vector3d> tour_path = io::readPathWaypoints(kTours / "bridge" / "ceiling" / "path.csv");
  EXPECT_GT(tour_path.size(), 10u);
  const nlohmann::json json = nlohmann::json::parse(readWholeFile(dir_ / "trajectory.json"));
  EXPECT_EQ(json["setpoints"].size(), t.setpoints.size());
  EXPECT_EQ(json["origin"]["lon_deg"], facts_.origin.longitude_deg);
}

// Where the autopilot files put waypoint k: the route's own, but a route that ends at home ends
// above it at the landing height, from where the vehicle lands (docs/flying.md).
Eigen::Vector3d flownPosition(const mission::SortieRoute& route, std::size_t k) {
  if (k + 1 == route.waypoints.size() && route.endsAtHome())
    return route.home_m + route.landingHeight_m() * Eigen::Vector3d::UnitZ();
  return route.waypoints[k].position_m;
}

TEST_F(BridgeExports, QgcPlanAndWplCarryEveryWaypointWithinOneCentimetre) {
  const io::AutopilotMission mission = io::autopilotMission(route_, facts_.origin);
  io::writeQgcPlan(dir_ / "mission.plan", mission);
  io::writeQgcWpl(dir_ / "mission.waypoints", mission);
  const nlohmann::json plan = nlohmann::json::parse(readWholeFile(dir_ / "mission.plan"));
  const double home_amsl = plan["mission"]["plannedHomePosition"][2].get<double>();
  std::size_t waypoint = 0, photos = 0, gimbal = 0, speed = 0;
  for (const auto& item : plan["mission"]["items"]) {
    const int command = item["command"];
    photos += command == 2000;
    gimbal += command == 1000;
    speed += command == 178;
    if (command != 16) continue;
    const auto& p = item["params"];
    const Eigen::Vector3d back =
        io::toLocal(facts_.origin, {p[4].get<double>(), p[5].get<double>(), home_amsl + p[6].get<double>()});
    ASSERT_LT(waypoint, route_.waypoints.size());
    EXPECT_LT((back - flownPosition(route_, waypoint)).norm(), 0.01) << waypoint;
    EXPECT_EQ(p[0].get<double>(), route_.waypoints[waypoint].hold_s);
    EXPECT_TRUE(p[3].is_number());
    ++waypoint;
  }
  EXPECT_EQ(waypoint, route_.waypoints.size());
  EXPECT_EQ(photos, 13u);  // one per target
  EXPECT_GT(gimbal, 0u);
  EXPECT_GT(speed, 0u);  // the flight record slows near the deck
  EXPECT_EQ(plan["ceilplan"]["ekf_origin"]["lat_deg"], facts_.origin.latitude_deg);
  const std::string wpl = readWholeFile(dir_ / "mission.waypoints");
  EXPECT_EQ(std::count(wpl.begin(), wpl.end(), '\n'), static_cast<long>(plan["mission"]["items"].size() + 2));
}

TEST_F(BridgeExports, DjiKmzKmlAndGeoJsonReadBackWithinOneCentimetre) {
  // Ceiling mode looks at its targets from beside them, within the default H20's +30 degrees.
  io::writeDjiKmz(dir_ / "mission.kmz", route_, facts_.origin);
  // Free mode hovers a metre below soffit targets, looking straight up: the H20 cannot, and
  // the export says so rather than shooting at +30; a payload that can look up takes it.
  const TourOutput free = readTourOutput(kTours / "bridge" / "free", facts_);
  try {
    io::writeDjiKmz(dir_ / "free.kmz", free.routes[0], facts_.origin);
    ADD_FAILURE() << "expected an error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is outside the payload's range [-120, 30]"), std::string::npos) << e.what();
  }
  io::DjiWpmlOptions upward;
  upward.gimbal_pitch_range_deg = {-90.0, 90.0};
  io::writeDjiKmz(dir_ / "free.kmz", free.routes[0], facts_.origin, upward);
  EXPECT_EQ(readZip(dir_ / "free.kmz").size(), 2u);
  io::writeRoutesKml(dir_ / "route.kml", {route_}, facts_.origin, "bridge");
  io::writeRoutesGeoJson(dir_ / "route.geojson", {route_}, facts_.origin);
  const Eigen::Vector3d home = io::toGeodetic(facts_.origin, route_.home_m);
  const auto entries = readZip(dir_ / "mission.kmz");
  ASSERT_EQ(entries.size(), 2u);
  for (const char* name : {"wpmz/template.kml", "wpmz/waylines.wpml"}) {
    tinyxml2::XMLDocument xml;
    ASSERT_EQ(xml.Parse(entries.at(name).c_str()), tinyxml2::XML_SUCCESS) << name;
    const auto placemarks =
        children(xml.RootElement()->FirstChildElement("Document")->FirstChildElement("Folder"), "Placemark");
    ASSERT_EQ(placemarks.size(), route_.waypoints.size()) << name;
    int photos = 0;
    for (std::size_t k = 0; k < placemarks.size(); ++k) {
      double lon = 0, lat = 0;
      ASSERT_EQ(std::sscanf(childText(placemarks[k]->FirstChildElement("Point"), "coordinates").c_str(), "%lf,%lf",
                            &lon, &lat),
                2);
      const double height =
          childNumber(placemarks[k],
                      std::string(name).find("template") != std::string::npos ? "wpml:height" : "wpml:executeHeight");
      EXPECT_LT((io::toLocal(facts_.origin, {lat, lon, home.z() + height}) - flownPosition(route_, k)).norm(), 0.01);
      EXPECT_NEAR(childNumber(placemarks[k], "wpml:waypointSpeed"), route_.speedInto_m_s(k + 1), 5e-4);  // mm/s
      for (const auto* group : children(placemarks[k], "wpml:actionGroup"))
        for (const auto* action : children(group, "wpml:action"))
          photos += childText(action, "wpml:actionActuatorFunc") == "takePhoto";
    }
    EXPECT_EQ(photos, 13) << name;
  }
  tinyxml2::XMLDocument kml;
  ASSERT_EQ(kml.LoadFile((dir_ / "route.kml").c_str()), tinyxml2::XML_SUCCESS);
  const auto folder = kml.RootElement()->FirstChildElement("Document")->FirstChildElement("Folder");
  EXPECT_EQ(children(folder, "Placemark").size(), route_.waypoints.size() + 1);
  const nlohmann::json geojson = nlohmann::json::parse(readWholeFile(dir_ / "route.geojson"));
  std::size_t k = 0;
  for (const auto& feature : geojson["features"]) {
    if (feature["properties"]["kind"] != "waypoint") continue;
    const auto& c = feature["geometry"]["coordinates"];
    const Eigen::Vector3d back =
        io::toLocal(facts_.origin, {c[1].get<double>(), c[0].get<double>(), c[2].get<double>()});
    EXPECT_LT((back - route_.waypoints[k++].position_m).norm(), 0.01);
  }
  EXPECT_EQ(k, route_.waypoints.size());
}

TEST_F(BridgeExports, ReportShowsBothModesTheStructureNearTheRoutesAndTheComparison) {
  const MapCheck map(facts_);
  const std::vector<TourOutput> outputs = readTourOutputs(kTours / "bridge", facts_);
  const io::ReportModel model = reportModel(outputs, facts_, map, kTours / "bridge", "bridge");
  io::writeReportHtml(dir_ / "report.html", model);
  const std::string page = readWholeFile(dir_ / "report.html");
  const std::string open = "<script type=\"application/json\" id=\"ceilplan-data\">";
  const std::size_t begin = page.find(open) + open.size();
  const nlohmann::json data = nlohmann::json::parse(page.substr(begin, page.find("</script>", begin) - begin));
  ASSERT_EQ(data["plans"].size(), 2u);
  EXPECT_EQ(data["plans"][0]["name"], "ceiling");
  EXPECT_EQ(data["plans"][1]["name"], "free");
  EXPECT_EQ(data["plans"][0]["targets"].size(), 13u);
  EXPECT_EQ(data["plans"][0]["samples"]["t"].size(), output_.samples.size());
  const std::size_t voxels = data["structure"]["cells"].size() / 4;
  EXPECT_GT(voxels, 1000u);
  // Every voxel shown lies within 3 m (and half a metre of probe spacing) of a flown sample.
  const double size = data["structure"]["voxel_m"];
  const auto& origin = data["structure"]["origin"];
  for (std::size_t v = 0; v < voxels; v += 97) {
    const Eigen::Vector3d c(origin[0].get<double>() + size * data["structure"]["cells"][4 * v].get<double>(),
                            origin[1].get<double>() + size * data["structure"]["cells"][4 * v + 1].get<double>(),
                            origin[2].get<double>() + size * data["structure"]["cells"][4 * v + 2].get<double>());
    double nearest = 1e9;
    for (const auto& output : outputs)
      for (const auto& s : output.samples) nearest = std::min(nearest, (s.position_m - c).norm());
    EXPECT_LE(nearest, 3.0 + 0.5) << c.transpose();
  }
  EXPECT_GE(data["comparison"]["rows"].size(), 4u);
  EXPECT_EQ(data["comparison"]["header"].size(), 4u);
}

// A scan nobody here made: OctoMap's own geb079 (a corridor of building 079, Freiburg, 0.08 m).
// A route between free places found in it is flown within limits through the dense re-check,
// and the report shows the scanned structure near it. The scan leaves most of the corridor
// unknown, so here unknown space counts as free (the user's policy, `--unknown-free`).
TEST(RealScan, Geb079RouteFlownAndReported) {
  const std::filesystem::path scan = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";
  ASSERT_TRUE(std::filesystem::exists(scan)) << "liboctomap-dev ships " << scan;
  MissionFacts facts;
  facts.map = scan;
  facts.vehicle = kMaps / "vehicles" / "quad.yaml";
  const MapCheck map(facts, true);
  const environment::Environment& env = *map.environment;
  // Free places every half metre at 1.2 m, then a chain of them joined by valid straight motions.
  std::vector<Eigen::Vector3d> places;
  const Eigen::AlignedBox3d box = env.grid().frame().bounds();
  for (double x = box.min().x() + 0.5; x < box.max().x(); x += 0.5)
    for (double y = box.min().y() + 0.5; y < box.max().y(); y += 0.5)
      if (env.isStateValid({x, y, 1.2})) places.emplace_back(x, y, 1.2);
  ASSERT_GT(places.size(), 10u);
  std::vector<Eigen::Vector3d> chain;
  for (std::size_t start = 0; start < places.size() && chain.size() < 4; start += 7) {
    chain = {places[start]};
    for (int hop = 0; hop < 6; ++hop) {
      const Eigen::Vector3d from = chain.back();
      const Eigen::Vector3d* best = nullptr;
      for (const Eigen::Vector3d& p : places) {
        const double d = (p - from).norm();
        const bool visited =
            std::any_of(chain.begin(), chain.end(), [&](const Eigen::Vector3d& c) { return (c - p).norm() < 1.0; });
        if (!visited && d > 1.5 && d < 6.0 && (!best || d > (*best - from).norm()) &&
            !map.rules->checkPathDensely({from, p}))
          best = &p;
      }
      if (!best) break;
      chain.push_back(*best);
    }
  }
  ASSERT_GE(chain.size(), 4u) << "no route through the scan's free space";
  mission::SortieRoute route;
  route.home_m = chain.front();
  for (std::size_t k = 1; k < chain.size(); ++k) route.waypoints.emplace_back(chain[k]);
  route.waypoints.back().hold_s = 5.0;
  route.waypoints.back().yaw_deg = 180.0;
  mission::TrajectoryOptions options;
  options.path_is_safe = [&](const std::vector<Eigen::Vector3d>& p) { return map.safe(p); };
  const mission::Trajectory t = mission::timeScale(route, trajectoryLimits(facts), options);
  expectWithinLimits(t, route.cruise_speed_m_s);
  std::vector<Eigen::Vector3d> positions;
  for (const auto& s : t.setpoints) positions.push_back(s.position_m);
  const auto violation = env.checkPathDensely(positions);
  EXPECT_FALSE(violation) << violation->describe();

  io::ReportModel model;
  model.title = "geb079";
  model.home_m = route.home_m;
  io::ReportPlan plan;
  plan.name = "scan";
  for (const auto& s : t.setpoints) plan.samples.push_back({s.t_s, s.position_m, 9.5, 0.95 - 0.0001 * s.t_s, 1});
  model.plans.push_back(plan);
  model.structure = io::structureNear(env.grid(), positions, 2.0);
  EXPECT_GT(model.structure.centres_m.size(), 500u);
  const std::filesystem::path dir = scratchDirectory("geb079");
  io::writeReportHtml(dir / "report.html", model);
  EXPECT_GT(std::filesystem::file_size(dir / "report.html"), 800000u);
  std::printf("geb079: %zu-waypoint route, %zu setpoints, %d blended corners, %zu structure voxels\n",
              route.waypoints.size(), t.setpoints.size(), t.blended_corners, model.structure.centres_m.size());
}

}  // namespace
}  // namespace ceilplan::testing
