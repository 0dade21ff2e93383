#include "ceilplan/core/error.hpp"

#include "mission_file.hpp"
#include "ceilplan/core/format.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace ceilplan::app {
namespace {

// Reads keys of one mission file; every error is "FILE: ..." naming the key.
class MissionReader {
 public:
  explicit MissionReader(std::filesystem::path file) : file_(std::move(file)) {
    if (!std::filesystem::is_regular_file(file_)) fail("no such mission file");
    try {
      root_ = YAML::LoadFile(file_.string());
    } catch (const YAML::Exception& e) {
      fail("malformed YAML at line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
    }
    if (!root_.IsMap()) fail("a mission file must be a YAML map (docs/missions.md)");
  }

  const YAML::Node& root() const { return root_; }

  YAML::Node required(const YAML::Node& parent, const std::string& key, const std::string& path) const {
    const YAML::Node node = parent[key];
    if (!node) fail("missing key '" + path + "'");
    return node;
  }

  YAML::Node section(const std::string& key) const {
    const YAML::Node node = required(root_, key, key);
    if (!node.IsMap()) fail("'" + key + "' must be a map");
    return node;
  }

  template <typename T>
  T as(const YAML::Node& node, const std::string& path, const char* expected) const {
    try {
      return node.as<T>();
    } catch (const YAML::Exception&) {
      fail("'" + path + "' must be " + expected);
    }
  }

  double finite(const YAML::Node& node, const std::string& path) const {
    const double value = as<double>(node, path, "a number");
    if (!std::isfinite(value)) fail("'" + path + "' must be a finite number, got " + formatNumber(value));
    return value;
  }

  double positive(const YAML::Node& node, const std::string& path) const {
    const double value = finite(node, path);
    if (value <= 0.0) fail("'" + path + "' must be positive, got " + formatNumber(value));
    return value;
  }

  double soc(const YAML::Node& node, const std::string& path) const {
    const double value = finite(node, path);
    if (value < 0.0 || value > 1.0) fail("'" + path + "' must be a state of charge in [0, 1], got " + formatNumber(value));
    return value;
  }

  Eigen::Vector3d vector3(const YAML::Node& node, const std::string& path) const {
    if (!node.IsSequence() || node.size() != 3) fail("'" + path + "' must be [x, y, z] in metres");
    return {finite(node[0], path + "[0]"), finite(node[1], path + "[1]"), finite(node[2], path + "[2]")};
  }

  std::filesystem::path existingFile(const std::string& key) const {
    const auto name = as<std::string>(required(root_, key, key), key, "a file name");
    const std::filesystem::path path = file_.parent_path() / name;
    if (!std::filesystem::is_regular_file(path))
      fail("'" + key + "' names " + path.string() + ", which does not exist (paths are relative to the mission file)");
    return path;
  }

  [[noreturn]] void fail(const std::string& problem) const { throw ceilplan::InputError(file_.string() + ": " + problem); }

 private:
  std::filesystem::path file_;
  YAML::Node root_;
};

mission::SortieBattery readBattery(const MissionReader& reader) {
  const YAML::Node section = reader.section("battery");
  mission::SortieBattery battery;
  battery.pack.capacity_ah = reader.positive(reader.required(section, "capacity_ah", "battery.capacity_ah"), "battery.capacity_ah");
  battery.pack.charge_current_a =
      reader.positive(reader.required(section, "charge_current_a", "battery.charge_current_a"), "battery.charge_current_a");
  battery.start_soc = reader.soc(reader.required(section, "start_soc", "battery.start_soc"), "battery.start_soc");
  battery.reserve_soc = reader.soc(reader.required(section, "reserve_soc", "battery.reserve_soc"), "battery.reserve_soc");
  if (battery.reserve_soc >= battery.start_soc)
    reader.fail("'battery.reserve_soc' " + formatNumber(battery.reserve_soc) + " is not below 'battery.start_soc' " +
                formatNumber(battery.start_soc) + ": no sortie could fly");
  return battery;
}

mission::GeodeticOrigin readOrigin(const MissionReader& reader, const YAML::Node& node) {
  if (!node.IsMap()) reader.fail("'origin' must be {lat, lon, alt}");
  mission::GeodeticOrigin origin;
  origin.latitude_deg = reader.finite(reader.required(node, "lat", "origin.lat"), "origin.lat");
  origin.longitude_deg = reader.finite(reader.required(node, "lon", "origin.lon"), "origin.lon");
  origin.altitude_m = reader.finite(reader.required(node, "alt", "origin.alt"), "origin.alt");
  try {
    origin.validate();
  } catch (const ceilplan::InputError& e) {
    reader.fail(e.what());
  }
  return origin;
}

MissionSpeeds readSpeeds(const MissionReader& reader, const YAML::Node& node) {
  MissionSpeeds speeds;
  if (!node) return speeds;
  if (!node.IsMap()) reader.fail("'speeds' must be a map");
  const std::pair<const char*, double*> entries[] = {{"cruise_m_s", &speeds.cruise_m_s},
                                                     {"inspection_m_s", &speeds.inspection_m_s},
                                                     {"climb_m_s", &speeds.climb_m_s},
                                                     {"descent_m_s", &speeds.descent_m_s}};
  for (const auto& [key, value] : entries)
    if (node[key]) *value = reader.positive(node[key], std::string("speeds.") + key);
  return speeds;
}

std::vector<mission::InspectionTarget> readTargets(const MissionReader& reader) {
  const YAML::Node list = reader.required(reader.root(), "targets", "targets");
  if (!list.IsSequence() || list.size() == 0) reader.fail("'targets' must be a non-empty list");
  std::vector<mission::InspectionTarget> targets;
  std::set<std::string> names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node node = list[k];
    const std::string path = "targets[" + std::to_string(k) + "]";
    if (!node.IsMap()) reader.fail("'" + path + "' must be a map {name, point, dwell_s, standoff_m}");
    mission::InspectionTarget target;
    target.name = reader.as<std::string>(reader.required(node, "name", path + ".name"), path + ".name", "a string");
    if (target.name.empty()) reader.fail("'" + path + ".name' is empty");
    if (!names.insert(target.name).second) reader.fail("duplicate target name '" + target.name + "' at '" + path + "'");
    target.point_m = reader.vector3(reader.required(node, "point", path + ".point"), path + ".point");
    target.dwell_s = reader.finite(reader.required(node, "dwell_s", path + ".dwell_s"), path + ".dwell_s");
    if (target.dwell_s < 0.0) reader.fail("'" + path + ".dwell_s' must be non-negative, got " + formatNumber(target.dwell_s));
    const YAML::Node standoff = reader.required(node, "standoff_m", path + ".standoff_m");
    if (!standoff.IsSequence() || standoff.size() != 2) reader.fail("'" + path + ".standoff_m' must be [min, max] in metres");
    target.standoff_min_m = reader.finite(standoff[0], path + ".standoff_m[0]");
    target.standoff_max_m = reader.finite(standoff[1], path + ".standoff_m[1]");
    try {
      target.validate();
    } catch (const ceilplan::InputError& e) {
      reader.fail(std::string("'") + path + "': " + e.what());
    }
    targets.push_back(std::move(target));
  }
  return targets;
}

}  // namespace

const mission::GeodeticOrigin& MissionFile::requireOrigin() const {
  if (!origin)
    throw ceilplan::InputError(file.string() +
                                ": missing key 'origin' ({lat, lon, alt} of the map frame): needed to export to an autopilot");
  return *origin;
}

MissionFile readMissionFile(const std::filesystem::path& file) {
  const MissionReader reader(file);
  MissionFile mission;
  mission.file = file;
  mission.map = reader.existingFile("map");
  mission.vehicle = reader.existingFile("vehicle");
  mission.battery = readBattery(reader);
  mission.home_m = reader.vector3(reader.required(reader.root(), "home", "home"), "home");
  if (reader.root()["origin"]) mission.origin = readOrigin(reader, reader.root()["origin"]);
  mission.speeds = readSpeeds(reader, reader.root()["speeds"]);
  if (reader.root()["mode"]) mission.mode = reader.as<std::string>(reader.root()["mode"], "mode", "a string");
  if (reader.root()["seed"]) mission.seed = reader.as<std::uint64_t>(reader.root()["seed"], "seed", "a non-negative integer");
  mission.targets = readTargets(reader);
  return mission;
}

}  // namespace ceilplan::app
