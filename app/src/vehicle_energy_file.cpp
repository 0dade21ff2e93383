#include "vehicle_energy_file.hpp"

#include "output.hpp"

#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/core/error.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace ceilplan::app {
namespace {

constexpr double kPi = 3.14159265358979323846;

class Reader {
 public:
  explicit Reader(std::string file) : file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw ceilplan::InputError("vehicle file " + file_ + ": " + message);
  }

  double number(const YAML::Node& node, const std::string& key) const {
    try {
      const double value = node.as<double>();
      if (!std::isfinite(value)) fail(key + " must be a finite number");
      return value;
    } catch (const YAML::Exception&) {
      fail(key + " must be a number");
    }
  }

  double number(const YAML::Node& map, const char* key, const std::string& prefix, double fallback) const {
    const YAML::Node node = map[key];
    return node ? number(node, prefix + key) : fallback;
  }

  std::string text(const YAML::Node& map, const char* key, const std::string& prefix, const std::string& fallback) const {
    const YAML::Node node = map[key];
    if (!node) return fallback;
    if (!node.IsScalar()) fail(prefix + key + " must be a word");
    return node.Scalar();
  }

  // Refuses keys a section does not know: a typo must not silently fall back to a default.
  void onlyKnownKeys(const YAML::Node& map, const std::string& prefix, const std::set<std::string>& known) const {
    if (!map) return;
    if (!map.IsMap()) fail(prefix + " must be a map");
    for (const auto& entry : map) {
      const std::string key = entry.first.as<std::string>();
      if (!known.count(key)) fail("unknown key " + prefix + "." + key);
    }
  }

 private:
  std::string file_;
};

// d (adjacent) and b (opposite) of the multirotor ground-effect form: the smallest and the
// largest distance between two rotor axes.
void setRotorSpacings(energy::VehicleGeometry& vehicle, const std::vector<std::pair<double, double>>& positions) {
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (std::size_t i = 0; i < positions.size(); ++i)
    for (std::size_t j = i + 1; j < positions.size(); ++j) {
      const double distance = std::hypot(positions[i].first - positions[j].first, positions[i].second - positions[j].second);
      smallest = std::min(smallest, distance);
      largest = std::max(largest, distance);
    }
  vehicle.adjacent_rotor_spacing_m = positions.size() > 1 ? smallest : 0.0;
  vehicle.opposite_rotor_spacing_m = largest;
}

void readGeometry(const Reader& reader, const YAML::Node& root, energy::VehicleGeometry& vehicle) {
  if (!root["mass_kg"]) reader.fail("mass_kg is missing");
  vehicle.mass_kg = reader.number(root["mass_kg"], "mass_kg");
  if (!(vehicle.mass_kg > 0.0)) reader.fail("mass_kg must be positive (got " + std::to_string(vehicle.mass_kg) + ")");
  const YAML::Node rotors = root["rotors"];
  if (!rotors || !rotors.IsMap() || !rotors["count"]) reader.fail("rotors.count is missing: a vehicle needs rotors");
  const double count = reader.number(rotors["count"], "rotors.count");
  if (count < 1 || count > energy::EnergyModel::kMaxRotors || count != std::floor(count))
    reader.fail("rotors.count must be a whole number from 1 to " + std::to_string(energy::EnergyModel::kMaxRotors) +
                " (got " + rotors["count"].Scalar() + ")");
  vehicle.rotor_count = static_cast<int>(count);
  if (!rotors["radius_m"]) reader.fail("rotors.radius_m is missing");
  vehicle.rotor_radius_m = reader.number(rotors["radius_m"], "rotors.radius_m");
  if (!(vehicle.rotor_radius_m > 0.0)) reader.fail("rotors.radius_m must be positive");

  std::vector<std::pair<double, double>> positions;
  if (const YAML::Node listed = rotors["positions"]) {
    if (!listed.IsSequence() || listed.size() != static_cast<std::size_t>(vehicle.rotor_count))
      reader.fail("rotors.positions must list one [x, y] per rotor (" + std::to_string(vehicle.rotor_count) + ")");
    for (const auto& xy : listed) {
      if (!xy.IsSequence() || xy.size() < 2) reader.fail("rotors.positions entries must be [x, y]");
      positions.emplace_back(reader.number(xy[0], "rotors.positions"), reader.number(xy[1], "rotors.positions"));
    }
  } else if (vehicle.rotor_count > 1) {
    if (!rotors["arm_length_m"]) reader.fail("rotors.arm_length_m (with layout) or rotors.positions is missing");
    const double arm_m = reader.number(rotors["arm_length_m"], "rotors.arm_length_m");
    if (!(arm_m > 0.0)) reader.fail("rotors.arm_length_m must be positive");
    const std::string layout = reader.text(rotors, "layout", "rotors.", "x");
    if (layout != "x" && layout != "plus") reader.fail("rotors.layout must be x or plus (got " + layout + ")");
    // A symmetric layout: x has a rotor at half a step from the forward axis, plus one on it.
    const double offset = layout == "x" ? kPi / vehicle.rotor_count : 0.0;
    for (int i = 0; i < vehicle.rotor_count; ++i) {
      const double angle = offset + 2.0 * kPi * i / vehicle.rotor_count;
      positions.emplace_back(arm_m * std::cos(angle), arm_m * std::sin(angle));
    }
  }
  setRotorSpacings(vehicle, positions);
}

energy::ThrustToPowerConvention parseConvention(const Reader& reader, const std::string& word) {
  if (word == "momentum") return energy::ThrustToPowerConvention::kMomentumTheory;
  if (word == "constant-power") return energy::ThrustToPowerConvention::kConstantPower;
  reader.fail("power.thrust_to_power must be momentum or constant-power (got " + word + ")");
}

energy::GroundEffectModel parseGroundModel(const Reader& reader, const std::string& word) {
  if (word == "cheeseman-bennett") return energy::GroundEffectModel::kCheesemanBennett;
  if (word == "multirotor") return energy::GroundEffectModel::kMultirotor;
  reader.fail("power.ground.model must be cheeseman-bennett or multirotor (got " + word + ")");
}

// The shortest decimal that reads back as the same double (yaml-cpp would always write 17 digits).
std::string shortestNumber(double value) {
  char text[32];
  for (int digits = 15; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

std::string conventionName(energy::ThrustToPowerConvention convention) {
  return convention == energy::ThrustToPowerConvention::kMomentumTheory ? "momentum" : "constant-power";
}

std::string groundModelName(energy::GroundEffectModel model) {
  return model == energy::GroundEffectModel::kCheesemanBennett ? "cheeseman-bennett" : "multirotor";
}

void readPower(const Reader& reader, const YAML::Node& root, energy::EnergyParameters& p) {
  const YAML::Node power = root["power"];
  reader.onlyKnownKeys(power, "power",
                       {"reference_soc", "hover_current_a", "hover_power_w", "motor_efficiency",
                        "induced_power_correction", "tip_speed_m_s", "drag_area_m2", "air_density_kg_m3",
                        "descent_power_floor", "thrust_to_power", "ceiling", "ground", "pack"});
  const YAML::Node empty;
  const YAML::Node section = power ? power : empty;
  const YAML::Node ceiling = section["ceiling"];
  const YAML::Node ground = section["ground"];
  const YAML::Node pack = section["pack"];
  reader.onlyKnownKeys(ceiling, "power.ceiling",
                       {"k1", "k2_m", "anchor_gap_m", "anchor_current_a", "contact_thrust_ratio", "taper_start_radii",
                        "taper_end_radii"});
  reader.onlyKnownKeys(ground, "power.ground", {"model", "body_lift_factor", "min_gap_radii"});
  reader.onlyKnownKeys(pack, "power.pack", {"cell_count", "resistance_ohm", "avionics_current_a"});

  p.vehicle.max_speed_m_s = reader.number(root, "max_speed_m_s", "", p.vehicle.max_speed_m_s);
  p.reference_soc = reader.number(section, "reference_soc", "power.", p.reference_soc);
  if (!(p.reference_soc >= 0.0 && p.reference_soc <= 1.0)) reader.fail("power.reference_soc must be in [0, 1]");
  auto& r = p.rotor;
  r.motor_efficiency = reader.number(section, "motor_efficiency", "power.", r.motor_efficiency);
  r.induced_power_correction = reader.number(section, "induced_power_correction", "power.", r.induced_power_correction);
  r.tip_speed_m_s = reader.number(section, "tip_speed_m_s", "power.", r.tip_speed_m_s);
  r.drag_area_m2 = reader.number(section, "drag_area_m2", "power.", r.drag_area_m2);
  r.air_density_kg_m3 = reader.number(section, "air_density_kg_m3", "power.", r.air_density_kg_m3);
  r.descent_power_floor = reader.number(section, "descent_power_floor", "power.", r.descent_power_floor);
  r.convention = parseConvention(reader, reader.text(section, "thrust_to_power", "power.", "momentum"));
  if (ground) {
    p.ground.model = parseGroundModel(reader, reader.text(ground, "model", "power.ground.", "cheeseman-bennett"));
    p.ground.body_lift_factor = reader.number(ground, "body_lift_factor", "power.ground.", p.ground.body_lift_factor);
    p.ground.min_gap_radii = reader.number(ground, "min_gap_radii", "power.ground.", p.ground.min_gap_radii);
  }
  if (pack) {
    const double cells = reader.number(pack, "cell_count", "power.pack.", p.pack.cell_count);
    if (cells != std::floor(cells)) reader.fail("power.pack.cell_count must be a whole number");
    p.pack.cell_count = static_cast<int>(cells);
    p.pack.resistance_ohm = reader.number(pack, "resistance_ohm", "power.pack.", p.pack.resistance_ohm);
    p.pack.avionics_current_a = reader.number(pack, "avionics_current_a", "power.pack.", p.pack.avionics_current_a);
  }

  // Hover power: given, or solved from a measured hover current at the reference SOC.
  if (section["hover_power_w"] && section["hover_current_a"])
    reader.fail("give power.hover_power_w or power.hover_current_a, not both");
  if (section["hover_power_w"]) {
    r.hover_power_w = reader.number(section["hover_power_w"], "power.hover_power_w");
  } else {
    const double current_a = reader.number(section, "hover_current_a", "power.", energy::kPaperFreeAirCurrentA);
    r.hover_power_w = energy::hoverPowerForCurrentW(p, current_a, p.reference_soc);
  }

  // Ceiling: K1 and K2 given, or solved through an anchor measurement.
  auto& c = p.ceiling;
  c.taper_start_radii = reader.number(ceiling, "taper_start_radii", "power.ceiling.", c.taper_start_radii);
  c.taper_end_radii = reader.number(ceiling, "taper_end_radii", "power.ceiling.", c.taper_end_radii);
  const bool explicit_constants = ceiling && (ceiling["k1"] || ceiling["k2_m"]);
  const bool anchored = ceiling && (ceiling["anchor_gap_m"] || ceiling["anchor_current_a"] || ceiling["contact_thrust_ratio"]);
  if (explicit_constants && anchored) reader.fail("give power.ceiling k1 and k2_m, or its anchor_* keys, not both");
  if (explicit_constants) {
    if (!ceiling["k1"] || !ceiling["k2_m"]) reader.fail("power.ceiling needs both k1 and k2_m");
    c.k1 = reader.number(ceiling["k1"], "power.ceiling.k1");
    c.k2_m = reader.number(ceiling["k2_m"], "power.ceiling.k2_m");
  } else {
    c = energy::ceilingThroughAnchor(
        p, reader.number(ceiling, "anchor_gap_m", "power.ceiling.", energy::kPaperCeilingGapM),
        reader.number(ceiling, "anchor_current_a", "power.ceiling.", energy::kPaperCeilingCurrentA), p.reference_soc,
        reader.number(ceiling, "contact_thrust_ratio", "power.ceiling.", energy::kContactThrustRatio));
  }
}

}  // namespace

VehicleEnergyFile readVehicleEnergyFile(const std::filesystem::path& path) {
  const Reader reader(path.string());
  VehicleEnergyFile vehicle;
  try {
    vehicle.document = YAML::LoadFile(path.string());
  } catch (const YAML::BadFile&) {
    reader.fail("cannot be read (missing or unreadable)");
  } catch (const YAML::Exception& e) {
    reader.fail("malformed YAML at line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (!vehicle.document.IsMap()) reader.fail("must be a YAML map");
  vehicle.name = reader.text(vehicle.document, "name", "", path.filename().string());
  try {
    readGeometry(reader, vehicle.document, vehicle.parameters.vehicle);
    readPower(reader, vehicle.document, vehicle.parameters);
    const energy::EnergyModel check(vehicle.parameters);  // every remaining rule
  } catch (const YAML::Exception& e) {
    reader.fail(e.msg);
  } catch (const ceilplan::InputError& e) {
    const std::string message = e.what();
    if (message.rfind("vehicle file ", 0) == 0) throw;
    reader.fail(message);
  }
  return vehicle;
}

VehicleEnergyFile builtInVehicle() {
  VehicleEnergyFile vehicle;
  vehicle.name = "built-in default (the founding paper's quadrotor, maps/vehicles/quad.yaml)";
  vehicle.parameters = energy::paperQuadParameters();
  return vehicle;
}

void writeVehicleEnergyFile(const std::filesystem::path& path, const VehicleEnergyFile& vehicle,
                            const energy::EnergyParameters& p, const std::string& comment) {
  const bool from_file = vehicle.document.IsMap();
  YAML::Node document = from_file ? YAML::Clone(vehicle.document) : YAML::Node(YAML::NodeType::Map);
  if (!from_file) {
    document["name"] = "quad-10in";
    document["mass_kg"] = shortestNumber(p.vehicle.mass_kg);
    document["rotors"]["count"] = p.vehicle.rotor_count;
    document["rotors"]["radius_m"] = shortestNumber(p.vehicle.rotor_radius_m);
    document["rotors"]["positions"] = YAML::Node(YAML::NodeType::Sequence);
    // The built-in quad's X layout, as positions so nothing depends on layout conventions.
    const double arm_m = p.vehicle.opposite_rotor_spacing_m / 2.0;
    for (int i = 0; i < p.vehicle.rotor_count; ++i) {
      const double angle = kPi / p.vehicle.rotor_count + 2.0 * kPi * i / p.vehicle.rotor_count;
      YAML::Node xy(YAML::NodeType::Sequence);
      xy.SetStyle(YAML::EmitterStyle::Flow);
      xy.push_back(shortestNumber(arm_m * std::cos(angle)));
      xy.push_back(shortestNumber(arm_m * std::sin(angle)));
      document["rotors"]["positions"].push_back(xy);
    }
  }
  document["max_speed_m_s"] = shortestNumber(p.vehicle.max_speed_m_s);
  YAML::Node power(YAML::NodeType::Map);
  power["reference_soc"] = shortestNumber(p.reference_soc);
  power["hover_power_w"] = shortestNumber(p.rotor.hover_power_w);
  power["motor_efficiency"] = shortestNumber(p.rotor.motor_efficiency);
  power["induced_power_correction"] = shortestNumber(p.rotor.induced_power_correction);
  power["tip_speed_m_s"] = shortestNumber(p.rotor.tip_speed_m_s);
  power["drag_area_m2"] = shortestNumber(p.rotor.drag_area_m2);
  power["air_density_kg_m3"] = shortestNumber(p.rotor.air_density_kg_m3);
  power["descent_power_floor"] = shortestNumber(p.rotor.descent_power_floor);
  power["thrust_to_power"] = conventionName(p.rotor.convention);
  power["ceiling"]["k1"] = shortestNumber(p.ceiling.k1);
  power["ceiling"]["k2_m"] = shortestNumber(p.ceiling.k2_m);
  power["ceiling"]["taper_start_radii"] = shortestNumber(p.ceiling.taper_start_radii);
  power["ceiling"]["taper_end_radii"] = shortestNumber(p.ceiling.taper_end_radii);
  power["ground"]["model"] = groundModelName(p.ground.model);
  power["ground"]["body_lift_factor"] = shortestNumber(p.ground.body_lift_factor);
  power["ground"]["min_gap_radii"] = shortestNumber(p.ground.min_gap_radii);
  power["pack"]["cell_count"] = p.pack.cell_count;
  power["pack"]["resistance_ohm"] = shortestNumber(p.pack.resistance_ohm);
  power["pack"]["avionics_current_a"] = shortestNumber(p.pack.avionics_current_a);
  document["power"] = power;

  writeTextAtomically(path, [&](std::ostream& out) {
    YAML::Emitter emitter;
    emitter << YAML::Comment(comment) << YAML::Newline << document;
    out << emitter.c_str() << '\n';
  });
}

}  // namespace ceilplan::app
