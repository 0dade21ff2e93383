// `ceilplan tour` end to end on a small analytic scene: a hall whose right part has a deck
// (a slab 3 m up) and a pier, four targets, home on the left. Each test writes the map and a
// mission file, runs the real executable and reads what it wrote.

#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/vehicle_file.hpp"
#include "run_command.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace ceilplan {
namespace {

using testing::readWholeFile;
using testing::runCeilplan;
using testing::scratchDirectory;

const std::filesystem::path kVehicle = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/vehicles/quad.yaml";

bool occupied(double x, double y, double z, bool closet) {
  if (z < 0.2) return true;               // floor
  if (x >= 2.0 && z >= 3.0) return true;  // deck slab, 3 m up, over x >= 2
  // A closed closet under the deck: walls round x [6.6, 8.4), y [2.2, 4.0), the hall's edge beyond.
  if (closet && y >= 2.0 && ((x >= 6.4 && x < 6.6) || (x >= 8.4 && x < 8.6) || (y < 2.2 && x >= 6.4 && x < 8.6)))
    return true;
  return x >= 4.2 && x < 5.8 && y >= -0.8 && y < 0.8;  // pier under the deck
}

// The hall at 0.1 m: x [-1, 9), y [-4, 4), z [0, 3.4); every voxel known.
void writeHall(const std::filesystem::path& file, bool closet) {
  const double resolution = 0.1;
  octomap::OcTree tree(resolution);
  for (double z = 0.05; z < 3.4; z += resolution)
    for (double y = -3.95; y < 4.0; y += resolution)
      for (double x = -0.95; x < 9.0; x += resolution) {
        const bool occ = occupied(x, y, z, closet);
        tree.setNodeValue(octomap::point3d(x, y, z),
                          occ ? tree.getClampingThresMaxLog() : tree.getClampingThresMinLog(), true);
      }
  tree.updateInnerOccupancy();
  tree.prune();
  ASSERT_TRUE(tree.writeBinary(file.string()));
}

struct MissionText {
  std::string battery = "{capacity_ah: 5.2, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 10.4}";
  std::string origin = "origin: {lat: 52.218, lon: 0.0923, alt: 12.0}\n";
  std::string extra_targets;
  bool closet = false;  // the hall with a closed closet under the deck
};

// DIR/hall.bt and DIR/mission.yaml.
std::filesystem::path writeMission(const std::filesystem::path& dir, const MissionText& text = {}) {
  writeHall(dir / "hall.bt", text.closet);
  std::ofstream out(dir / "mission.yaml");
  out << "map: hall.bt\nvehicle: " << kVehicle.string() << "\nbattery: " << text.battery << "\nhome: [0.0, 0.0, 0.5]\n"
      << text.origin << "seed: 3\ntargets:\n"
      << "  - {name: deck_a, point: [3.0, -1.5, 3.0], dwell_s: 10, standoff_m: [0.3, 1.5]}\n"
      << "  - {name: deck_b, point: [7.0, 1.5, 3.0], dwell_s: 12, standoff_m: [0.3, 1.5]}\n"
      << "  - {name: deck_c, point: [8.0, -2.0, 3.0], dwell_s: 8, standoff_m: [0.3, 1.5]}\n"
      << "  - {name: pier_face, point: [5.0, -0.8, 1.5], dwell_s: 15, standoff_m: [0.3, 1.5]}\n"
      << text.extra_targets;
  return dir / "mission.yaml";
}

nlohmann::json readJson(const std::filesystem::path& file) { return nlohmann::json::parse(readWholeFile(file)); }

std::vector<Eigen::Vector3d> points(const nlohmann::json& list) {
  std::vector<Eigen::Vector3d> result;
  for (const auto& p : list) result.emplace_back(p[0].get<double>(), p[1].get<double>(), p[2].get<double>());
  return result;
}

// The default leg planner (the roadmap), with nothing but the workers set.
const std::string kFast = " --workers 2";

// What one run of both modes wrote, checked by the specifications below (one run: planning is
// the slow part, and ctest runs every test in its own process).
struct BothModesRun {
  std::filesystem::path dir;  // the tour is in DIR/out
  std::filesystem::path map;
  std::size_t targets = 0;  // in the mission
  testing::CommandResult result;
};

void visitsEveryTargetWithItsDwellAboveTheReserve(const BothModesRun& run) {
  SCOPED_TRACE("VisitsEveryTargetWithItsDwellAboveTheReserve");
  for (const std::string mode : {"ceiling", "free"}) {
    const nlohmann::json tour = readJson(run.dir / "out" / mode / "tour.json");
    EXPECT_EQ(tour["mode"], mode);
    EXPECT_EQ(tour["targets_total"], run.targets);
    EXPECT_EQ(tour["targets_visited"], run.targets);
    ASSERT_EQ(tour["targets"].size(), run.targets);
    std::map<std::string, int> visits;
    for (const auto& sortie : tour["sorties"]) {
      EXPECT_GE(sortie["min_soc"].get<double>(), tour["reserve_soc"].get<double>()) << mode;
      EXPECT_FALSE(sortie["reason"].get<std::string>().empty());
      for (const auto& name : sortie["targets"]) ++visits[name.get<std::string>()];
    }
    for (const auto& target : tour["targets"]) EXPECT_EQ(visits[target["name"]], 1) << mode << target["name"];
    EXPECT_GE(tour["min_soc"].get<double>(), tour["reserve_soc"].get<double>());
    for (const char* key : {"fec", "xu", "woehler", "schmalstieg"})
      EXPECT_GT(tour["wear"][key]["cycle_wear"], 0.0) << key;

    // path.csv hovers at each viewpoint for the target's dwell.
    std::map<std::string, double> dwell_of;
    for (const auto& target : tour["targets"]) dwell_of[target["name"]] = target["dwell_s"];
    const io::CsvColumns csv =
        io::CsvColumns::read(run.dir / "out" / mode / "path.csv", {"t_s", "x", "y", "z", "speed_m_s"});
    EXPECT_EQ(csv.columnNames(),
              (std::vector<std::string>{"t_s", "x", "y", "z", "speed_m_s", "ceiling_gap_m", "current_a", "soc",
                                        "sortie", "ground_gap_m", "phase", "assumed_free"}));
    const auto& t = csv.column("t_s");
    const auto& speed = csv.column("speed_m_s");
    for (const auto& target : tour["targets"]) {
      const Eigen::Vector3d viewpoint = points(nlohmann::json::array({target["viewpoint"]}))[0];
      double hovered_s = 0.0;
      for (std::size_t k = 1; k < csv.rowCount(); ++k)
        if (speed[k] == 0.0 && speed[k - 1] == 0.0 &&
            (Eigen::Vector3d(csv.column("x")[k], csv.column("y")[k], csv.column("z")[k]) - viewpoint).norm() < 1e-6)
          hovered_s += t[k] - t[k - 1];
      EXPECT_NEAR(hovered_s, target["dwell_s"].get<double>(), 1e-6) << mode << " " << target["name"];
    }
  }
}

void everyLegPassesTheDenseRecheck(const BothModesRun& run) {
  SCOPED_TRACE("EveryLegPassesTheDenseRecheck");
  const environment::OccupancyMap map = environment::OccupancyMap::load(run.map);
  const environment::Environment environment(map, io::readVehicle(kVehicle).geometry);
  const planner::SafetyRules rules(environment, 0.05);
  int legs = 0;
  for (const std::string mode : {"ceiling", "free"}) {
    const nlohmann::json tour = readJson(run.dir / "out" / mode / "tour.json");
    for (const auto& sortie : tour["sorties"])
      for (const auto& leg : sortie["legs"]) {
        const auto violation = rules.checkPathDensely(points(leg["waypoints"]));
        EXPECT_FALSE(violation) << mode << " " << leg["from"] << " -> " << leg["to"] << ": " << *violation;
        ++legs;
      }
  }
  EXPECT_GE(legs, 10);
}

void ceilingModeWearsLessThanFreeModeUnderEveryModel(const BothModesRun& run) {
  SCOPED_TRACE("CeilingModeWearsLessThanFreeModeUnderEveryModel");
  const nlohmann::json comparison = readJson(run.dir / "out" / "comparison.json");
  for (const char* model : {"fec", "xu", "woehler", "schmalstieg"}) {
    EXPECT_LT(comparison["ceiling"]["wear"][model]["cycle_wear"].get<double>(),
              comparison["free"]["wear"][model]["cycle_wear"].get<double>())
        << model;
    EXPECT_GT(comparison["reduction_pct"][std::string("wear_") + model].get<double>(), 0.0) << model;
  }
  EXPECT_NE(run.result.out.find("reduction %"), std::string::npos) << run.result.out;
  EXPECT_TRUE(std::filesystem::exists(run.dir / "out" / "comparison.txt"));
}

void planFileIsCompleteAndReproducesTheRouteWithinACentimetre(const BothModesRun& run) {
  SCOPED_TRACE("PlanFileIsCompleteAndReproducesTheRouteWithinACentimetre");
  const nlohmann::json tour = readJson(run.dir / "out" / "ceiling" / "tour.json");
  ASSERT_EQ(tour["sorties"].size(), 1u);
  const nlohmann::json plan = readJson(run.dir / "out" / "ceiling" / "mission.plan");
  for (const char* key : {"fileType", "version", "groundStation", "mission", "geoFence", "rallyPoints"})
    EXPECT_TRUE(plan.contains(key)) << key;
  EXPECT_EQ(plan["fileType"], "Plan");
  const nlohmann::json& mission = plan["mission"];
  for (const char* key :
       {"version", "firmwareType", "vehicleType", "cruiseSpeed", "hoverSpeed", "plannedHomePosition", "items"})
    EXPECT_TRUE(mission.contains(key)) << key;

  // The route as the tour flies it: each leg's waypoints after its first, a hold at each target.
  std::vector<Eigen::Vector3d> route;
  std::vector<double> holds;
  std::map<std::string, double> dwell_of;
  for (const auto& target : tour["targets"]) dwell_of[target["name"]] = target["dwell_s"];
  for (const auto& leg : tour["sorties"][0]["legs"]) {
    const std::vector<Eigen::Vector3d> waypoints = points(leg["waypoints"]);
    for (std::size_t i = 1; i < waypoints.size(); ++i) {
      route.push_back(waypoints[i]);
      holds.push_back(0.0);
    }
    if (leg["to"] != "home") holds.back() = dwell_of[leg["to"]];
  }
  // Back home, the last waypoint is above it at the landing height, from where NAV_LAND descends.
  ASSERT_TRUE(tour["sorties"][0]["landing_height_m"].is_number());
  route.back().z() += tour["sorties"][0]["landing_height_m"].get<double>();
  EXPECT_EQ(mission["items"].back()["command"], io::mav::kNavLand);
  EXPECT_EQ(mission["items"].front()["command"], io::mav::kNavTakeoff);
  const mission::GeodeticOrigin origin{52.218, 0.0923, 12.0};  // the hall mission's and maps/bridge.yaml's
  const double home_amsl_m = mission["plannedHomePosition"][2].get<double>();
  // Every item is complete; the waypoints (NAV_WAYPOINT) are the route, and each target's
  // viewpoint is followed by a photo (IMAGE_START_CAPTURE) after its hold.
  std::vector<nlohmann::json> items;
  int photos = 0;
  for (const nlohmann::json& item : mission["items"]) {
    for (const char* key : {"type", "command", "frame", "autoContinue", "doJumpId", "params"})
      ASSERT_TRUE(item.contains(key)) << key;
    if (item["command"] == io::mav::kNavWaypoint) items.push_back(item);
    photos += item["command"] == io::mav::kImageStartCapture;
  }
  EXPECT_EQ(photos, static_cast<int>(tour["targets"].size()));
  ASSERT_EQ(items.size(), route.size());
  for (std::size_t k = 0; k < items.size(); ++k) {
    const nlohmann::json& item = items[k];
    EXPECT_EQ(item["frame"], 3);
    ASSERT_EQ(item["params"].size(), 7u);
    const auto& params = item["params"];
    EXPECT_NEAR(params[0].get<double>(), holds[k], 1e-9) << k;
    const Eigen::Vector3d local =
        io::toLocal(origin, {params[4].get<double>(), params[5].get<double>(), params[6].get<double>() + home_amsl_m});
    EXPECT_LT((local - route[k]).norm(), 0.01) << k;
  }
  const std::string wpl = readWholeFile(run.dir / "out" / "ceiling" / "mission.waypoints");
  EXPECT_EQ(wpl.rfind("QGC WPL 110\n", 0), 0u);
}

void checkBothModes(const BothModesRun& run) {
  visitsEveryTargetWithItsDwellAboveTheReserve(run);
  everyLegPassesTheDenseRecheck(run);
  ceilingModeWearsLessThanFreeModeUnderEveryModel(run);
  planFileIsCompleteAndReproducesTheRouteWithinACentimetre(run);
}

TEST(TourCommand, BothModesOnTheHall) {
  const std::filesystem::path dir = scratchDirectory("tour_both");
  BothModesRun run{dir, dir / "hall.bt", 4, {}};
  const std::filesystem::path mission = writeMission(run.dir);
  run.result =
      runCeilplan("tour --mission " + mission.string() + " --mode both --out " + (run.dir / "out").string() + kFast);
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  checkBothModes(run);
}

// The project's claim (docs/tours.md): on the shipped bridge, ceiling mode wears the pack less than free mode
// under every ageing model, and the comparison says by how much.
TEST(TourCommand, BothModesOnTheShippedBridge) {
  const std::filesystem::path maps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";
  BothModesRun run{scratchDirectory("tour_bridge"), maps / "bridge.bt", 13, {}};
  run.result = runCeilplan("tour --mission " + (maps / "bridge.yaml").string() + " --mode both --out " +
                           (run.dir / "out").string());
  ASSERT_EQ(run.result.exit_code, 0) << run.result.err;
  checkBothModes(run);
  for (const char* line : {"fec: capacity loss [%]", "xu: capacity loss [%]", "woehler: capacity loss [%]",
                           "schmalstieg: capacity loss [%]"})
    EXPECT_NE(run.result.out.find(line), std::string::npos) << line;
}

// Bad input: one clear line naming the problem, a non-zero exit, no tour written.
void expectFailure(const std::string& name, const MissionText& text, const std::string& flags, int exit_code,
                   const std::string& expected) {
  const std::filesystem::path dir = scratchDirectory("tour_bad_" + name);
  const std::filesystem::path mission = writeMission(dir, text);
  const testing::CommandResult result =
      runCeilplan("tour --mission " + mission.string() + " --out " + (dir / "out").string() + kFast + flags);
  EXPECT_EQ(result.exit_code, exit_code) << name << ": " << result.err;
  EXPECT_NE(result.err.find(expected), std::string::npos) << name << ": " << result.err;
  EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << name << ": " << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out" / "tour.json")) << name;
}

TEST(TourCommand, TargetInsideAnObstacleIsNamed) {
  MissionText text;
  text.extra_targets = "  - {name: buried, point: [5.0, 0.0, 1.5], dwell_s: 5, standoff_m: [0.3, 0.6]}\n";
  expectFailure("buried", text, "", 2, "target 'buried'");
}

TEST(TourCommand, ReserveAboveStartSocIsRejected) {
  MissionText text;
  text.battery = "{capacity_ah: 5.2, start_soc: 0.5, reserve_soc: 0.6, charge_current_a: 10.4}";
  expectFailure("reserve", text, "", 2, "reserve");
}

TEST(TourCommand, TargetNoSortieCanReachAndReturnFromIsNamed) {
  MissionText text;
  text.battery = "{capacity_ah: 0.6, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 1.2}";
  text.extra_targets = "  - {name: long_look, point: [7.0, -1.0, 3.0], dwell_s: 200, standoff_m: [0.3, 1.5]}\n";
  expectFailure("long_look", text, " --mode ceiling", 3, "long_look");
}

TEST(TourCommand, TargetWithAViewpointButNoWayInIsNamedWithExitCode3) {
  MissionText text;
  text.closet = true;
  text.extra_targets = "  - {name: closet_ceiling, point: [7.5, 3.1, 3.0], dwell_s: 5, standoff_m: [0.3, 1.5]}\n";
  expectFailure("closet", text, " --mode ceiling", 3, "closet_ceiling");
}

TEST(TourCommand, RoadmapToursAreReproducibleWhateverTheThreadCount) {
  const std::filesystem::path dir = scratchDirectory("tour_reproducible");
  const std::filesystem::path mission = writeMission(dir);
  for (const char* workers : {"1", "2"}) {
    const testing::CommandResult result = runCeilplan("tour --mission " + mission.string() + " --mode both --workers " +
                                                      workers + " --out " + (dir / workers).string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  // Everything but the provenance's command line, which names the thread count and the directory.
  for (const char* file : {"ceiling/tour.json", "free/tour.json", "comparison.json"}) {
    nlohmann::json one = readJson(dir / "1" / file), two = readJson(dir / "2" / file);
    EXPECT_NE(one["provenance"]["command"], two["provenance"]["command"]);
    one["provenance"].erase("command");
    two["provenance"].erase("command");
    EXPECT_EQ(one, two) << file;
  }
  const auto withoutComment = [](const std::string& text) { return text.substr(text.find('\n') + 1); };
  EXPECT_EQ(withoutComment(readWholeFile(dir / "1" / "ceiling/path.csv")),
            withoutComment(readWholeFile(dir / "2" / "ceiling/path.csv")));
}

TEST(TourCommand, PairwisePlannersStillPlanEveryLeg) {
  const std::filesystem::path dir = scratchDirectory("tour_pairwise");
  const std::filesystem::path mission = writeMission(dir);
  const testing::CommandResult result = runCeilplan("tour --mission " + mission.string() +
                                                    " --mode ceiling --planner lattice --lattice-spacing-m 0.4 "
                                                    "--time-limit-s 20 --out " +
                                                    (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json tour = readJson(dir / "out" / "tour.json");
  EXPECT_EQ(tour["planner"], "lattice");
  EXPECT_EQ(tour["targets_visited"], 4);
}

// A scan without a coordinate reference still tours: every local-frame output is written, and
// one line names the geodetic exports skipped (tour.json records them).
TEST(TourCommand, MissionWithoutAnOriginWritesItsLocalOutputsAndNamesTheSkippedExports) {
  const std::filesystem::path dir = scratchDirectory("tour_no_origin");
  MissionText text;
  text.origin = "";
  const std::filesystem::path mission = writeMission(dir, text);
  const testing::CommandResult result =
      runCeilplan("tour --mission " + mission.string() + " --mode ceiling --out " + (dir / "out").string() + kFast);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* file :
       {"tour.json", "path.csv", "trajectory.csv", "trajectory.json", "report.html", "map_top.csv", "map_side.csv"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / "out" / file)) << file;
  const std::vector<std::string> skipped = {"mission.plan", "mission.waypoints", "mission.kmz", "routes.kml",
                                            "routes.geojson"};
  for (const std::string& file : skipped) EXPECT_FALSE(std::filesystem::exists(dir / "out" / file)) << file;
  EXPECT_EQ(readJson(dir / "out" / "tour.json")["targets_visited"], 4);

  std::vector<std::string> lines;
  std::istringstream out(result.out);
  for (std::string line; std::getline(out, line);)
    if (line.find("geodetic exports skipped") != std::string::npos) lines.push_back(line);
  ASSERT_EQ(lines.size(), 1u) << result.out;
  EXPECT_EQ(lines[0],
            "geodetic exports skipped (mission.plan, mission.waypoints, mission.kmz, routes.kml, "
            "routes.geojson): " +
                mission.string() +
                " has no 'origin:' ({lat, lon, alt} of the map frame); every local-frame output was written");
  const nlohmann::json recorded = readJson(dir / "out" / "tour.json")["geodetic_exports_skipped"];
  EXPECT_EQ(recorded["files"].get<std::vector<std::string>>(), skipped);
  EXPECT_NE(recorded["reason"].get<std::string>().find("no 'origin:'"), std::string::npos);

  // --no-export keeps its meaning: no geodetic file, whatever the mission has.
  const testing::CommandResult quiet = runCeilplan(
      "tour --mission " + mission.string() + " --mode ceiling --no-export --out " + (dir / "quiet").string() + kFast);
  ASSERT_EQ(quiet.exit_code, 0) << quiet.err;
  EXPECT_NE(quiet.out.find("no autopilot files (--no-export)"), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("geodetic exports skipped"), std::string::npos) << quiet.out;
}

}  // namespace
}  // namespace ceilplan
