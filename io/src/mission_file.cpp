#include "ceilplan/io/mission_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/input_file.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/dji_wpml.hpp"
#include "ceilplan/io/point_text.hpp"
#include "ceilplan/io/vehicle_file.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include "coverage_keys.hpp"
#include "yaml_reader.hpp"

#include <set>

namespace ceilplan::io {
namespace {

using detail::FileKind;
using detail::Range;
using detail::Section;
using detail::YamlFile;

const std::vector<std::string> kBatteryKeys{"capacity_ah",     "charge_current_a",  "cell_count",  "soc_min",
                                            "state_of_health", "start_soc",         "reserve_soc", "between_sorties",
                                            "swap_s",          "reserve_confidence"};
// Any place in a map: a kilometre either way (the index refuses maps too large to hold anyway).
const Range kCoordinateM = Range::closed(-kMaxPointCoordinate_m, kMaxPointCoordinate_m, "m");

// The vehicle a battery powers, as a message names it.
std::string vehicleSource(const mission::Vehicle& vehicle, const std::filesystem::path& vehicle_file) {
  return vehicle_file.empty() ? "the vehicle '" + printableText(vehicle.name, 80) + "'"
                              : printableText(vehicle_file.string(), 256);
}

// Reads a battery section; in a mission file the pack and SOC limits of a tour are required,
// a battery file may leave any of them at the founding paper's values. The energy model flies
// the vehicle's pack, so a cell count that is not the vehicle's is refused (absent, it is the
// vehicle's).
mission::BatterySpec readBatterySection(const Section& section, bool all_required, const mission::Vehicle& vehicle,
                                        const std::filesystem::path& vehicle_file) {
  section.allowOnly(kBatteryKeys);
  mission::BatterySpec spec;
  battery::Pack& pack = spec.pack;
  const auto number = [&](const char* key, const Range& range, double fallback, bool required) {
    return required ? section.number(key, range) : section.number(key, range, fallback);
  };
  pack.capacity_ah =
      number("capacity_ah", Range::closed(battery::Pack::kMinCapacity_ah, battery::Pack::kMaxCapacity_ah, "Ah"),
             pack.capacity_ah, all_required);
  pack.charge_current_a =
      number("charge_current_a", Range::above(0.0, 1000.0, "A"), pack.charge_current_a, all_required);
  const int vehicle_cells = vehicle.energy.pack.cell_count;
  pack.cell_count = static_cast<int>(section.integer("cell_count", 1, 24, vehicle_cells));
  if (pack.cell_count != vehicle_cells)
    section.fail(
        "'" + section.keyPath("cell_count") + "' is " + std::to_string(pack.cell_count) + " cells, but " +
        vehicleSource(vehicle, vehicle_file) + " has a " + std::to_string(vehicle_cells) +
        "-cell pack (power.pack.cell_count): give the vehicle of this battery, or the battery of this vehicle");
  pack.soc_min = section.number("soc_min", Range::below(0.0, 1.0), pack.soc_min);
  pack.state_of_health = section.number("state_of_health", Range::above(0.0, 1.0), pack.state_of_health);
  spec.start_soc = number("start_soc", Range::above(0.0, 1.0), spec.start_soc, all_required);
  spec.reserve_soc = number("reserve_soc", Range::closed(0.0, 1.0), spec.reserve_soc, all_required);
  if (section.choice("between_sorties", {"recharge", "swap"}, "recharge") == "swap")
    spec.between_sorties = mission::Turnaround::Swap;
  spec.swap_s = section.number("swap_s", Range::closed(0.0, 86400.0, "s"), spec.swap_s);
  if (section.has("reserve_confidence")) {
    spec.reserve_confidence = section.number("reserve_confidence", Range{0.0, 1.0, "", true, true});
    if (!vehicle.calibration)
      section.fail("'" + section.keyPath("reserve_confidence") + "' needs a calibrated vehicle, and " +
                   vehicleSource(vehicle, vehicle_file) +
                   " has no 'calibration:' block: fit it with ceilplan calibrate (docs/energy.md) or remove the key");
  }
  if (spec.reserve_soc >= spec.start_soc)
    section.fail("'" + section.keyPath("reserve_soc") + "' " + formatNumber(spec.reserve_soc) + " is not below '" +
                 section.keyPath("start_soc") + "' " + formatNumber(spec.start_soc) + ": no sortie could fly");
  try {
    spec.validate();
  } catch (const InputError& e) {
    section.fail(e.what());
  }
  spec.description = section.file().path().string();
  return spec;
}

mission::GeodeticOrigin readOrigin(const Section& node) {
  node.allowOnly({"lat", "lon", "alt"});
  mission::GeodeticOrigin origin;
  origin.latitude_deg = node.number("lat", Range::closed(-90.0, 90.0, "deg"));
  origin.longitude_deg = node.number("lon", Range::closed(-180.0, 180.0, "deg"));
  origin.altitude_m = node.number("alt", Range::closed(-500.0, 10000.0, "m"));
  return origin;
}

planner::FlightSpeeds readSpeeds(const Section& node, double max_speed_m_s) {
  node.allowOnly({"cruise_m_s", "inspection_m_s", "climb_m_s", "descent_m_s"});
  planner::FlightSpeeds speeds;
  const double min_m_s = planner::FlightSpeeds::kMinSpeed_m_s;
  const Range horizontal = Range::closed(min_m_s, max_speed_m_s, "m/s (the vehicle's max_speed_m_s)");
  const Range vertical =
      Range::closed(min_m_s, std::min(planner::FlightSpeeds::kMaxVerticalSpeed_m_s, max_speed_m_s), "m/s");
  speeds.cruise_m_s = node.number("cruise_m_s", horizontal, speeds.cruise_m_s);
  speeds.inspection_m_s = node.number("inspection_m_s", horizontal, speeds.inspection_m_s);
  speeds.climb_m_s = node.number("climb_m_s", vertical, speeds.climb_m_s);
  speeds.descent_m_s = node.number("descent_m_s", vertical, speeds.descent_m_s);
  // A mission file has no key for the slow zone under a ceiling: never faster than cruise.
  speeds.near_ceiling_m_s = std::min(speeds.near_ceiling_m_s, speeds.cruise_m_s);
  return speeds;
}

// The wind: calm unless given. Its speed plus the fastest horizontal speed must stay within the
// vehicle's max_speed_m_s, the fastest airspeed the energy model answers for.
energy::Wind readWind(const Section& node, const planner::FlightSpeeds& speeds, double max_speed_m_s) {
  node.allowOnly({"speed_m_s", "from_deg", "gust_m_s", "sheltered_fraction"});
  energy::Wind wind;
  wind.speed_m_s = node.number("speed_m_s", Range::closed(0.0, energy::Wind::kMaxSpeed_m_s, "m/s"));
  wind.from_deg = node.number("from_deg", Range::below(0.0, 360.0, "deg (where it blows from, clockwise from north)"));
  wind.gust_m_s = node.number("gust_m_s", Range::closed(0.0, energy::Wind::kMaxSpeed_m_s, "m/s"), wind.gust_m_s);
  wind.sheltered_fraction = node.number("sheltered_fraction", Range::closed(0.0, 1.0), wind.sheltered_fraction);
  try {
    planner::checkAirspeedLimit(wind, speeds, max_speed_m_s);
  } catch (const InputError& e) {
    node.fail(e.what());
  }
  return wind;
}

// Point targets: required unless the mission inspects surfaces or contact grids.
std::vector<mission::InspectionTarget> readTargets(const Section& root, bool required) {
  if (!root.has("targets")) {
    if (!required) return {};
    root.fail("missing key 'targets' (a mission inspects point targets, or surfaces and contact grids: " +
              docPage("missions.md") + ")");
  }
  const YAML::Node list = root.required("targets");
  if (!list.IsSequence() || list.size() == 0) root.fail("'targets' must be a non-empty list");
  std::vector<mission::InspectionTarget> targets;
  std::set<std::string> names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string path = "targets[" + std::to_string(k) + "]";
    if (!list[k].IsMap()) root.fail("'" + path + "' must be a map {name, point, dwell_s, standoff_m}");
    const Section node(root.file(), list[k], path);
    node.allowOnly({"name", "point", "dwell_s", "standoff_m"});
    mission::InspectionTarget target;
    target.name = node.text("name");
    if (target.name.empty()) node.fail("'" + path + ".name' is empty");
    if (!names.insert(target.name).second) node.fail("duplicate target name '" + target.name + "' at '" + path + "'");
    target.point_m = node.vector3("point", kCoordinateM);
    target.dwell_s = node.number("dwell_s", Range::closed(0.0, 3600.0, "s"));
    const std::vector<double> standoff =
        node.numbers("standoff_m", 2, Range::closed(0.0, mission::InspectionTarget::kMaxStandoff_m, "m"));
    target.standoff_min_m = standoff[0];
    target.standoff_max_m = standoff[1];
    try {
      target.validate();
    } catch (const InputError& e) {
      node.fail("'" + path + "': " + e.what());
    }
    targets.push_back(std::move(target));
  }
  return targets;
}

std::filesystem::path existingFile(const Section& root, const std::string& key) {
  std::filesystem::path path = root.file().path().parent_path() / root.text(key);
  std::error_code ec;
  const std::string named = "'" + key + "' names " + printableText(path.string(), 256);
  if (std::filesystem::is_directory(path, ec)) root.fail(named + ", which is a directory, not a file");
  if (!std::filesystem::exists(path, ec))
    root.fail(named + ", which does not exist (paths are relative to the mission file)");
  try {
    requireInputFile(path, "file");  // a FIFO or a device, which its reader would wait on or read without end
  } catch (const InputError& e) {
    root.fail("'" + key + "' names " + e.what());
  }
  return path;
}

environment::UnknownSpace readUnknownSpace(const Section& node) {
  node.allowOnly({"policy", "fill_max_m"});
  std::optional<double> fill_max_m;
  if (node.has("fill_max_m"))
    fill_max_m = node.number("fill_max_m", Range::above(0.0, environment::UnknownSpace::kMaxFill_m, "m"));
  try {
    return environment::parseUnknownSpace(node.text("policy", "occupied"), fill_max_m,
                                          {"'" + node.keyPath("policy") + "'", "'" + node.keyPath("fill_max_m") + "'"});
  } catch (const InputError& e) {
    node.fail(e.what());
  }
}

mission::DjiAircraft readDjiAircraft(const Section& dji) {
  dji.allowOnly({"drone", "payload", "payload_position", "gimbal_pitch_range_deg", "rth_height_m", "finish_action",
                 "rc_lost_action"});
  mission::DjiAircraft aircraft;
  aircraft.drone = dji.choice("drone", djiDroneNames(), aircraft.drone);
  aircraft.payload = dji.choice("payload", djiPayloadNames(), aircraft.payload);
  aircraft.payload_position = dji.choice("payload_position", {"main", "right", "upper"}, aircraft.payload_position);
  if (dji.has("gimbal_pitch_range_deg")) {
    const std::vector<double> range = dji.numbers("gimbal_pitch_range_deg", 2, Range::closed(-180.0, 180.0, "deg"));
    if (!(range[0] < range[1]))
      dji.fail("'" + dji.keyPath("gimbal_pitch_range_deg") + "' must be [min, max] with min < max");
    aircraft.gimbal_pitch_range_deg = std::array<double, 2>{range[0], range[1]};
  }
  aircraft.rth_height_m = dji.number("rth_height_m", Range::closed(2.0, 1500.0, "m"), aircraft.rth_height_m);
  aircraft.finish_action =
      dji.choice("finish_action", {"goHome", "autoLand", "noAction", "gotoFirstWaypoint"}, aircraft.finish_action);
  aircraft.rc_lost_action = dji.choice("rc_lost_action", {"goBack", "landing", "hover"}, aircraft.rc_lost_action);
  try {
    djiWpmlOptions(aircraft);  // the combination: a payload the drone carries, a mount it has
  } catch (const InputError& e) {
    dji.fail(e.what());
  }
  return aircraft;
}

}  // namespace

mission::Mission readMission(const std::filesystem::path& file) {
  const YamlFile yaml(file, FileKind::Mission);
  const Section root(yaml, yaml.root(), "");
  std::vector<std::string> keys{"map",  "vehicle", "battery", "home",       "origin", "speeds", "mode",
                                "seed", "unknown", "wind",    "trajectory", "dji",    "targets"};
  keys.insert(keys.end(), detail::coverageKeyNames().begin(), detail::coverageKeyNames().end());
  root.allowOnly(keys);
  mission::Mission mission;
  mission.file = file;
  mission.map_file = existingFile(root, "map");
  mission.vehicle_file = existingFile(root, "vehicle");
  mission.vehicle = readVehicle(mission.vehicle_file);
  mission.battery = readBatterySection(root.section("battery"), true, mission.vehicle, mission.vehicle_file);
  mission.home_m = root.vector3("home", kCoordinateM);
  if (const std::optional<Section> origin = root.optionalSection("origin")) mission.origin = readOrigin(*origin);
  if (const std::optional<Section> speeds = root.optionalSection("speeds"))
    mission.planning.speeds = readSpeeds(*speeds, mission.vehicle.energy.airframe.max_speed_m_s);
  mission.mode = root.choice("mode", {"ceiling", "free", "both"}, "");
  mission.planning.seed = static_cast<std::uint32_t>(root.integer("seed", 1, 4294967295LL, mission.planning.seed));
  if (const std::optional<Section> unknown = root.optionalSection("unknown"))
    mission.planning.unknown = readUnknownSpace(*unknown);
  if (const std::optional<Section> wind = root.optionalSection("wind"))
    mission.planning.wind = readWind(*wind, mission.planning.speeds, mission.vehicle.energy.airframe.max_speed_m_s);
  if (const std::optional<Section> trajectory = root.optionalSection("trajectory")) {
    trajectory->allowOnly({"rate_hz", "corner_tolerance_m", "stop_turn_deg", "frame"});
    mission::TrajectoryOptions& t = mission.trajectory;
    t.rate_hz = trajectory->number("rate_hz", Range::closed(1.0, 1000.0, "Hz"), t.rate_hz);
    t.corner_tolerance_m = trajectory->number("corner_tolerance_m", Range::closed(0.0, 5.0, "m"), t.corner_tolerance_m);
    t.stop_turn_deg = trajectory->number("stop_turn_deg", Range::closed(0.0, 90.0, "deg"), t.stop_turn_deg);
    mission.trajectory_ned = trajectory->choice("frame", {"enu", "ned"}, "enu") == "ned";
  }
  if (const std::optional<Section> dji = root.optionalSection("dji")) mission.dji = readDjiAircraft(*dji);
  detail::CoverageKeys coverage = detail::readCoverageKeys(root);
  mission.camera = std::move(coverage.camera);
  mission.surfaces = std::move(coverage.surfaces);
  mission.contact_grids = std::move(coverage.contact_grids);
  mission.targets = readTargets(root, !mission.isCoverage());
  // Contact points are named "<grid>_<k>" and photos "<surface>_photo<k>": point targets keep clear.
  std::vector<std::string> prefixes;
  for (const mission::ContactGrid& grid : mission.contact_grids) prefixes.push_back(grid.name + "_");
  for (const mission::CoverageRegion& surface : mission.surfaces) prefixes.push_back(surface.name + "_photo");
  for (const mission::InspectionTarget& target : mission.targets)
    for (const std::string& prefix : prefixes)
      if (target.name.rfind(prefix, 0) == 0)
        root.fail("target '" + target.name + "' may clash with the stops named '" + prefix +
                  "N' a coverage tour makes: rename it");
  return mission;
}

mission::BatterySpec readBatteryOrDefault(const std::filesystem::path& file, const mission::Vehicle& vehicle,
                                          const std::filesystem::path& vehicle_file) {
  if (!file.empty()) return readBattery(file, vehicle, vehicle_file);
  mission::BatterySpec paper;
  paper.pack.cell_count = vehicle.energy.pack.cell_count;
  return paper;
}

mission::BatterySpec readBattery(const std::filesystem::path& file, const mission::Vehicle& vehicle,
                                 const std::filesystem::path& vehicle_file) {
  const YamlFile yaml(file, FileKind::Battery);
  const Section root(yaml, yaml.root(), "");
  // A mission file serves as a battery file: its other keys are the mission reader's to check.
  if (root.has("battery") && (root.has("targets") || root.has("surfaces") || root.has("contact_grid")))
    return readBatterySection(root.section("battery"), true, vehicle, vehicle_file);
  return readBatterySection(root, false, vehicle, vehicle_file);
}

}  // namespace ceilplan::io
