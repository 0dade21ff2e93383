#include "ceilplan/io/vehicle_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/io/atomic_file.hpp"

#include "yaml_reader.hpp"

#include <yaml-cpp/yaml.h>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace ceilplan::io {
namespace {

using detail::FileKind;
using detail::Range;
using detail::Section;
using detail::YamlFile;

// Physical ranges of a multirotor's keys (docs/missions.md): wide enough for any airframe from
// a 3-inch racer to a heavy-lift octocopter, narrow enough that a slip of a decimal point, or a
// length in centimetres, is refused before a map is indexed with it.
const Range kLengthM = Range::closed(-2.0, 2.0, "m");
const Range kArmM = Range::above(0.0, 5.0, "m");

void readShape(const Section& root, environment::VehicleGeometry& shape, int& rotor_count) {
  const Section rotors = root.section("rotors");
  rotors.allowOnly({"count", "layout", "arm_length_m", "positions", "radius_m", "plane_height_m"});
  rotor_count = static_cast<int>(rotors.integer("count", 1, energy::EnergyModel::kMaxRotors));
  if (rotors.has("positions")) {
    if (rotors.has("layout") || rotors.has("arm_length_m"))
      rotors.fail("give 'rotors.positions' or 'rotors.layout' with 'rotors.arm_length_m', not both");
    const YAML::Node list = rotors.required("positions");
    if (!list.IsSequence() || list.size() != static_cast<std::size_t>(rotor_count))
      rotors.fail("'rotors.positions' must list one [x, y] per rotor (" + std::to_string(rotor_count) + ")");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string path = "rotors.positions[" + std::to_string(k) + "]";
      if (!list[k].IsSequence() || list[k].size() != 2) rotors.fail("'" + path + "' must be [x, y] in metres");
      shape.rotor_positions_m.emplace_back(rotors.numberAt(list[k][0], path + "[0]", Range::closed(-5.0, 5.0, "m")),
                                           rotors.numberAt(list[k][1], path + "[1]", Range::closed(-5.0, 5.0, "m")));
    }
  } else {
    const std::string layout = rotors.choice("layout", {"x", "plus"}, "x");
    shape.rotor_positions_m =
        environment::rotorPositions(layout == "x" ? environment::RotorLayout::X : environment::RotorLayout::Plus,
                                    rotor_count, rotors.number("arm_length_m", kArmM));
  }
  shape.rotor_radius_m = rotors.number("radius_m", Range::above(0.0, 2.0, "m"));
  shape.rotor_plane_height_m = rotors.number("plane_height_m", Range::closed(-1.0, 1.0, "m"));

  const Section airframe = root.section("airframe");
  airframe.allowOnly({"top_height_m", "bottom_height_m", "collision_radius_m"});
  shape.top_height_m = airframe.number("top_height_m", kLengthM);
  shape.bottom_height_m = airframe.number("bottom_height_m", kLengthM);
  shape.collision_radius_m = airframe.number("collision_radius_m", Range::above(0.0, 3.0, "m"));

  const Section clearance = root.section("clearance");
  clearance.allowOnly({"margin_m", "top_margin_m"});
  shape.margin_m = clearance.number("margin_m", Range::closed(0.0, 3.0, "m"));
  shape.top_margin_m = clearance.number("top_margin_m", Range::closed(0.0, 3.0, "m"));
}

energy::ThrustToPowerConvention convention(const std::string& word) {
  return word == "momentum" ? energy::ThrustToPowerConvention::kMomentumTheory
                            : energy::ThrustToPowerConvention::kConstantPower;
}

std::string conventionName(energy::ThrustToPowerConvention convention) {
  return convention == energy::ThrustToPowerConvention::kMomentumTheory ? "momentum" : "constant-power";
}

std::string groundModelName(energy::GroundEffectModel model) {
  return model == energy::GroundEffectModel::kCheesemanBennett ? "cheeseman-bennett" : "multirotor";
}

void readPower(const Section& root, energy::EnergyParameters& p) {
  p.airframe.max_speed_m_s = root.number("max_speed_m_s", Range::above(0.0, 50.0, "m/s"), p.airframe.max_speed_m_s);
  const std::optional<Section> power = root.optionalSection("power");
  if (!power) {
    p.rotor.hover_power_w = energy::hoverPowerForCurrentW(p, energy::kPaperFreeAirCurrentA, p.reference_soc);
    p.ceiling = energy::ceilingThroughAnchor(p, energy::kPaperCeilingGapM, energy::kPaperCeilingCurrentA,
                                             p.reference_soc, energy::kContactThrustRatio);
    return;
  }
  const Section& s = *power;
  s.allowOnly({"reference_soc", "hover_current_a", "hover_power_w", "motor_efficiency", "induced_power_correction",
               "tip_speed_m_s", "drag_area_m2", "air_density_kg_m3", "descent_power_floor", "thrust_to_power",
               "ceiling", "ground", "pack"});
  p.reference_soc = s.number("reference_soc", Range::closed(0.0, 1.0), p.reference_soc);
  energy::RotorPowerParameters& r = p.rotor;
  r.motor_efficiency = s.number("motor_efficiency", Range::above(0.0, 1.0), r.motor_efficiency);
  r.induced_power_correction =
      s.number("induced_power_correction", Range::closed(0.0, 1.0), r.induced_power_correction);
  r.tip_speed_m_s = s.number("tip_speed_m_s", Range::above(0.0, 340.0, "m/s"), r.tip_speed_m_s);
  r.drag_area_m2 = s.number("drag_area_m2", Range::closed(0.0, 10.0, "m^2"), r.drag_area_m2);
  r.air_density_kg_m3 = s.number("air_density_kg_m3", Range::closed(0.5, 1.5, "kg/m^3"), r.air_density_kg_m3);
  r.descent_power_floor = s.number("descent_power_floor", Range::closed(0.0, 1.0), r.descent_power_floor);
  r.convention = convention(s.choice("thrust_to_power", {"momentum", "constant-power"}, "momentum"));
  if (const std::optional<Section> ground = s.optionalSection("ground")) {
    ground->allowOnly({"model", "body_lift_factor", "min_gap_radii"});
    p.ground.model = ground->choice("model", {"cheeseman-bennett", "multirotor"}, "cheeseman-bennett") == "multirotor"
                         ? energy::GroundEffectModel::kMultirotor
                         : energy::GroundEffectModel::kCheesemanBennett;
    p.ground.body_lift_factor = ground->number("body_lift_factor", Range::closed(0.0, 10.0), p.ground.body_lift_factor);
    p.ground.min_gap_radii = ground->number("min_gap_radii", Range::above(0.0, 10.0), p.ground.min_gap_radii);
  }
  if (const std::optional<Section> pack = s.optionalSection("pack")) {
    pack->allowOnly({"cell_count", "resistance_ohm", "avionics_current_a"});
    p.pack.cell_count = static_cast<int>(pack->integer("cell_count", 1, 24, p.pack.cell_count));
    p.pack.resistance_ohm = pack->number("resistance_ohm", Range::closed(0.0, 1.0, "ohm"), p.pack.resistance_ohm);
    p.pack.avionics_current_a =
        pack->number("avionics_current_a", Range::closed(0.0, 100.0, "A"), p.pack.avionics_current_a);
  }

  // Hover power: given, or solved from a measured hover current at the reference SOC.
  if (s.has("hover_power_w") && s.has("hover_current_a"))
    s.fail("give 'power.hover_power_w' or 'power.hover_current_a', not both");
  if (s.has("hover_power_w")) {
    r.hover_power_w = s.number("hover_power_w", Range::above(0.0, 1e5, "W"));
  } else {
    const double current_a = s.number("hover_current_a", Range::above(0.0, 1000.0, "A"), energy::kPaperFreeAirCurrentA);
    r.hover_power_w = energy::hoverPowerForCurrentW(p, current_a, p.reference_soc);
  }

  // Ceiling: K1 and K2 given, or solved through an anchor measurement.
  energy::CeilingEffectParameters& c = p.ceiling;
  const std::optional<Section> ceiling = s.optionalSection("ceiling");
  if (ceiling) {
    ceiling->allowOnly({"k1", "k2_m", "anchor_gap_m", "anchor_current_a", "contact_thrust_ratio", "taper_start_radii",
                        "taper_end_radii"});
    c.taper_start_radii = ceiling->number("taper_start_radii", Range::above(0.0, 10.0), c.taper_start_radii);
    c.taper_end_radii = ceiling->number("taper_end_radii", Range::above(0.0, 10.0), c.taper_end_radii);
  }
  const bool explicit_constants = ceiling && (ceiling->has("k1") || ceiling->has("k2_m"));
  const bool anchored = ceiling && (ceiling->has("anchor_gap_m") || ceiling->has("anchor_current_a") ||
                                    ceiling->has("contact_thrust_ratio"));
  if (explicit_constants && anchored) s.fail("give 'power.ceiling' k1 and k2_m, or its anchor_* keys, not both");
  if (explicit_constants) {
    c.k1 = ceiling->number("k1", Range::above(0.0, 1e3));
    c.k2_m = ceiling->number("k2_m", Range::above(0.0, 10.0, "m"));
  } else {
    const auto anchor = [&](const char* key, const Range& range, double fallback) {
      return ceiling ? ceiling->number(key, range, fallback) : fallback;
    };
    c = energy::ceilingThroughAnchor(
        p, anchor("anchor_gap_m", Range::above(0.0, 1.0, "m"), energy::kPaperCeilingGapM),
        anchor("anchor_current_a", Range::above(0.0, 1000.0, "A"), energy::kPaperCeilingCurrentA), p.reference_soc,
        anchor("contact_thrust_ratio", Range::above(1.0, 10.0), energy::kContactThrustRatio));
  }
}

// calibration: {samples, residual_rms_a, residual_std_a, parameters: [names], covariance: [[...]]},
// as writeCalibratedVehicle writes it; the covariance must be symmetric and positive semidefinite.
energy::FitUncertainty readCalibration(const Section& s) {
  s.allowOnly({"samples", "residual_rms_a", "residual_std_a", "parameters", "covariance"});
  energy::FitUncertainty u;
  u.samples = static_cast<int>(s.integer("samples", 2, 1000000000));
  u.residual_rms_a = s.number("residual_rms_a", Range::closed(0.0, 1000.0, "A"));
  u.residual_std_a = s.number("residual_std_a", Range::closed(0.0, 1000.0, "A"));
  if (s.has("parameters") != s.has("covariance"))
    s.fail("give 'calibration.parameters' and 'calibration.covariance' together (as ceilplan calibrate writes them)");
  if (!s.has("parameters")) return u;
  const YAML::Node names = s.required("parameters");
  if (!names.IsSequence() || names.size() == 0)
    s.fail("'calibration.parameters' must list the fitted parameters' names");
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::string path = "calibration.parameters[" + std::to_string(k) + "]";
    if (!names[k].IsScalar()) s.fail("'" + path + "' must be a parameter name");
    try {
      u.parameters.push_back(energy::parseFreeParameter(names[k].as<std::string>()));
    } catch (const InputError& e) {
      s.fail("'" + path + "': " + e.what());
    }
    for (std::size_t j = 0; j < k; ++j)
      if (u.parameters[j] == u.parameters[k])
        s.fail("'" + path + "' repeats " + energy::parameterName(u.parameters[k]));
  }
  const std::size_t p = u.parameters.size();
  const YAML::Node rows = s.required("covariance");
  if (!rows.IsSequence() || rows.size() != p)
    s.fail("'calibration.covariance' must have one row per parameter (" + std::to_string(p) + ")");
  Eigen::MatrixXd c(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
  for (std::size_t i = 0; i < p; ++i) {
    const std::vector<double> row =
        s.numbersAt(rows[i], "calibration.covariance[" + std::to_string(i) + "]", p, Range::finite());
    for (std::size_t j = 0; j < p; ++j) c(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = row[j];
    u.covariance.push_back(row);
  }
  const double scale = c.cwiseAbs().maxCoeff();
  if (!(c - c.transpose()).isZero(1e-9 * scale)) s.fail("'calibration.covariance' must be symmetric");
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(c);
  if (eigen.eigenvalues().minCoeff() < -1e-9 * scale)
    s.fail("'calibration.covariance' must be positive semidefinite (a covariance matrix)");
  for (std::size_t i = 0; i < p; ++i) u.standard_errors.push_back(std::sqrt(u.covariance[i][i]));
  return u;
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

YAML::Node flowPair(double a, double b) {
  YAML::Node pair(YAML::NodeType::Sequence);
  pair.SetStyle(YAML::EmitterStyle::Flow);
  pair.push_back(shortestNumber(a));
  pair.push_back(shortestNumber(b));
  return pair;
}

// The built-in vehicle as a complete vehicle file.
YAML::Node defaultVehicleDocument() {
  const mission::Vehicle v = mission::Vehicle::defaultQuad();
  YAML::Node document(YAML::NodeType::Map);
  document["name"] = v.name;
  document["mass_kg"] = shortestNumber(v.energy.airframe.mass_kg);
  document["rotors"]["count"] = static_cast<int>(v.geometry.rotor_positions_m.size());
  document["rotors"]["positions"] = YAML::Node(YAML::NodeType::Sequence);
  for (const Eigen::Vector2d& xy : v.geometry.rotor_positions_m)
    document["rotors"]["positions"].push_back(flowPair(xy.x(), xy.y()));
  document["rotors"]["radius_m"] = shortestNumber(v.geometry.rotor_radius_m);
  document["rotors"]["plane_height_m"] = shortestNumber(v.geometry.rotor_plane_height_m);
  document["airframe"]["top_height_m"] = shortestNumber(v.geometry.top_height_m);
  document["airframe"]["bottom_height_m"] = shortestNumber(v.geometry.bottom_height_m);
  document["airframe"]["collision_radius_m"] = shortestNumber(v.geometry.collision_radius_m);
  document["clearance"]["margin_m"] = shortestNumber(v.geometry.margin_m);
  document["clearance"]["top_margin_m"] = shortestNumber(v.geometry.top_margin_m);
  return document;
}

}  // namespace

mission::Vehicle readVehicleOrDefault(const std::filesystem::path& file) {
  return file.empty() ? mission::Vehicle::defaultQuad() : readVehicle(file);
}

mission::Vehicle readVehicle(const std::filesystem::path& file) {
  const YamlFile yaml(file, FileKind::Vehicle);
  const Section root(yaml, yaml.root(), "");
  root.allowOnly(
      {"name", "mass_kg", "rotors", "airframe", "clearance", "max_speed_m_s", "power", "limits", "calibration"});
  const std::string name = root.text("name", file.stem().string());
  try {
    environment::VehicleGeometry shape;
    int rotor_count = 0;
    readShape(root, shape, rotor_count);
    energy::EnergyParameters energy;
    energy.airframe.mass_kg = root.number("mass_kg", Range::above(0.0, 200.0, "kg"));
    // The energy model's rotors before its power constants are solved (they depend on them).
    energy.airframe.rotor_count = rotor_count;
    energy.airframe.rotor_radius_m = shape.rotor_radius_m;
    readPower(root, energy);
    mission::Vehicle vehicle = mission::Vehicle::assemble(name, std::move(shape), energy);
    if (const std::optional<Section> limits = root.optionalSection("limits")) {
      limits->allowOnly({"max_acceleration_m_s2", "max_jerk_m_s3", "max_yaw_rate_deg_s"});
      mission::MotionLimits& l = vehicle.limits;
      l.max_acceleration_m_s2 =
          limits->number("max_acceleration_m_s2", Range::above(0.0, 50.0, "m/s^2"), l.max_acceleration_m_s2);
      l.max_jerk_m_s3 = limits->number("max_jerk_m_s3", Range::above(0.0, 500.0, "m/s^3"), l.max_jerk_m_s3);
      l.max_yaw_rate_deg_s =
          limits->number("max_yaw_rate_deg_s", Range::above(0.0, 720.0, "deg/s"), l.max_yaw_rate_deg_s);
    }
    if (const std::optional<Section> calibration = root.optionalSection("calibration"))
      vehicle.calibration = readCalibration(*calibration);
    return vehicle;
  } catch (const InputError& e) {
    const std::string message = e.what();
    if (message.rfind(file.string() + ": ", 0) == 0) throw;
    yaml.fail(message);
  }
}

void writeCalibratedVehicle(const std::filesystem::path& out, const std::filesystem::path& source,
                            const energy::EnergyParameters& p, const std::string& comment,
                            const std::optional<energy::FitUncertainty>& calibration) {
  YAML::Node document;
  if (source.empty()) {
    document = defaultVehicleDocument();
  } else {
    readVehicle(source);  // the same checks as any other reader of the file
    document = YAML::LoadFile(source.string());
  }
  document["max_speed_m_s"] = shortestNumber(p.airframe.max_speed_m_s);
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
  document.remove("calibration");  // the source's describes other constants
  if (calibration) {
    YAML::Node block(YAML::NodeType::Map);
    block["samples"] = calibration->samples;
    block["residual_rms_a"] = shortestNumber(calibration->residual_rms_a);
    block["residual_std_a"] = shortestNumber(calibration->residual_std_a);
    if (calibration->hasCovariance()) {
      YAML::Node names(YAML::NodeType::Sequence);
      names.SetStyle(YAML::EmitterStyle::Flow);
      for (energy::FreeParameter parameter : calibration->parameters) names.push_back(energy::parameterName(parameter));
      block["parameters"] = names;
      for (const std::vector<double>& row : calibration->covariance) {
        YAML::Node line(YAML::NodeType::Sequence);
        line.SetStyle(YAML::EmitterStyle::Flow);
        for (double value : row) line.push_back(shortestNumber(value));
        block["covariance"].push_back(line);
      }
    }
    document["calibration"] = block;
  }
  writeTextAtomically(out, [&](std::ostream& stream) {
    YAML::Emitter emitter;
    emitter << YAML::Comment(comment) << YAML::Newline << document;
    stream << emitter.c_str() << '\n';
  });
}

}  // namespace ceilplan::io
