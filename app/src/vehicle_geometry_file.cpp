#include "ceilplan/core/error.hpp"

#include "vehicle_geometry_file.hpp"

#include <yaml-cpp/yaml.h>

#include <stdexcept>
#include <string>

namespace ceilplan::app {
namespace {

class VehicleReader {
 public:
  explicit VehicleReader(std::filesystem::path file) : file_(std::move(file)) {
    if (!std::filesystem::exists(file_)) fail("no such vehicle file");
    try {
      root_ = YAML::LoadFile(file_.string());
    } catch (const YAML::Exception& e) {
      fail("malformed YAML at line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
    }
    if (!root_.IsMap()) fail("a vehicle file must be a YAML map");
  }

  YAML::Node section(const std::string& key) const {
    const YAML::Node node = root_[key];
    if (!node || !node.IsMap()) fail("missing section '" + key + "'");
    return node;
  }

  template <typename T>
  T value(const YAML::Node& section, const std::string& path, const std::string& key) const {
    const YAML::Node node = section[key];
    if (!node) fail("missing key '" + path + "." + key + "'");
    try {
      return node.as<T>();
    } catch (const YAML::Exception&) {
      fail("key '" + path + "." + key + "' has the wrong type");
    }
  }

  const YAML::Node& root() const { return root_; }

  [[noreturn]] void fail(const std::string& problem) const {
    throw ceilplan::InputError(file_.string() + ": " + problem);
  }

 private:
  std::filesystem::path file_;
  YAML::Node root_;
};

}  // namespace

environment::VehicleGeometry readVehicleGeometry(const std::filesystem::path& file) {
  using environment::RotorLayout;
  const VehicleReader reader(file);
  environment::VehicleGeometry vehicle;
  vehicle.name = reader.root()["name"] ? reader.root()["name"].as<std::string>() : file.stem().string();

  const YAML::Node rotors = reader.section("rotors");
  if (rotors["positions"]) {
    const YAML::Node positions = rotors["positions"];
    if (!positions.IsSequence()) reader.fail("'rotors.positions' must be a list of [x, y] pairs");
    for (const YAML::Node& position : positions) {
      if (!position.IsSequence() || position.size() != 2) reader.fail("each of 'rotors.positions' must be [x, y]");
      vehicle.rotor_positions_m.emplace_back(position[0].as<double>(), position[1].as<double>());
    }
  } else {
    const auto layout = reader.value<std::string>(rotors, "rotors", "layout");
    if (layout != "x" && layout != "plus") reader.fail("'rotors.layout' must be x or plus, got '" + layout + "'");
    try {
      vehicle.rotor_positions_m =
          environment::rotorPositions(layout == "x" ? RotorLayout::X : RotorLayout::Plus,
                                      reader.value<int>(rotors, "rotors", "count"),
                                      reader.value<double>(rotors, "rotors", "arm_length_m"));
    } catch (const ceilplan::InputError& e) {
      reader.fail(e.what());
    }
  }
  if (rotors["count"] && reader.value<std::size_t>(rotors, "rotors", "count") != vehicle.rotor_positions_m.size())
    reader.fail("'rotors.count' disagrees with the number of 'rotors.positions'");
  vehicle.rotor_radius_m = reader.value<double>(rotors, "rotors", "radius_m");
  vehicle.rotor_plane_height_m = reader.value<double>(rotors, "rotors", "plane_height_m");

  const YAML::Node airframe = reader.section("airframe");
  vehicle.top_height_m = reader.value<double>(airframe, "airframe", "top_height_m");
  vehicle.bottom_height_m = reader.value<double>(airframe, "airframe", "bottom_height_m");
  vehicle.collision_radius_m = reader.value<double>(airframe, "airframe", "collision_radius_m");

  const YAML::Node clearance = reader.section("clearance");
  vehicle.margin_m = reader.value<double>(clearance, "clearance", "margin_m");
  vehicle.top_margin_m = reader.value<double>(clearance, "clearance", "top_margin_m");
  try {
    vehicle.validate();
  } catch (const ceilplan::InputError& e) {
    reader.fail(e.what());
  }
  return vehicle;
}

std::filesystem::path defaultVehicleFile() { return std::filesystem::path("maps") / "vehicles" / "quad.yaml"; }

}  // namespace ceilplan::app
