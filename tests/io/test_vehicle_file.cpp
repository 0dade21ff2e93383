// Vehicle files: the built-in vehicle is the shipped quad.yaml, one reader gives both the shape
// and the energy model, and bad files fail with one line naming the key.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

namespace ceilplan::io {
namespace {

const std::filesystem::path kQuad = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/vehicles/quad.yaml";

TEST(VehicleFile, NoFileMeansTheBuiltInVehicle) {
  EXPECT_EQ(readVehicleOrDefault({}).name, mission::Vehicle::defaultQuad().name);
  EXPECT_EQ(readVehicleOrDefault(kQuad).name, readVehicle(kQuad).name);
  EXPECT_THROW(readVehicleOrDefault(testing::scratchDirectory("vehicle_file") / "missing.yaml"), InputError);
}

TEST(VehicleFile, TheBuiltInVehicleIsTheShippedQuad) {
  const mission::Vehicle file = readVehicle(kQuad);
  const mission::Vehicle built_in = mission::Vehicle::defaultQuad();
  EXPECT_EQ(file.name, built_in.name);
  const environment::VehicleGeometry &a = file.geometry, &b = built_in.geometry;
  ASSERT_EQ(a.rotor_positions_m.size(), b.rotor_positions_m.size());
  for (std::size_t k = 0; k < a.rotor_positions_m.size(); ++k)
    EXPECT_EQ(a.rotor_positions_m[k], b.rotor_positions_m[k]) << "rotor " << k;
  EXPECT_EQ(a.rotor_radius_m, b.rotor_radius_m);
  EXPECT_EQ(a.rotor_plane_height_m, b.rotor_plane_height_m);
  EXPECT_EQ(a.top_height_m, b.top_height_m);
  EXPECT_EQ(a.bottom_height_m, b.bottom_height_m);
  EXPECT_EQ(a.collision_radius_m, b.collision_radius_m);
  EXPECT_EQ(a.margin_m, b.margin_m);
  EXPECT_EQ(a.top_margin_m, b.top_margin_m);
  const energy::EnergyParameters &p = file.energy, &q = built_in.energy;
  EXPECT_EQ(p.airframe.mass_kg, q.airframe.mass_kg);
  EXPECT_EQ(p.airframe.rotor_count, q.airframe.rotor_count);
  EXPECT_EQ(p.airframe.rotor_radius_m, q.airframe.rotor_radius_m);
  EXPECT_EQ(p.airframe.adjacent_rotor_spacing_m, q.airframe.adjacent_rotor_spacing_m);
  EXPECT_EQ(p.airframe.opposite_rotor_spacing_m, q.airframe.opposite_rotor_spacing_m);
  EXPECT_EQ(p.airframe.max_speed_m_s, q.airframe.max_speed_m_s);
  EXPECT_EQ(p.reference_soc, q.reference_soc);
  EXPECT_EQ(p.rotor.hover_power_w, q.rotor.hover_power_w);
  EXPECT_EQ(p.rotor.motor_efficiency, q.rotor.motor_efficiency);
  EXPECT_EQ(p.rotor.tip_speed_m_s, q.rotor.tip_speed_m_s);
  EXPECT_EQ(p.rotor.drag_area_m2, q.rotor.drag_area_m2);
  EXPECT_EQ(p.rotor.descent_power_floor, q.rotor.descent_power_floor);
  EXPECT_EQ(p.ceiling.k1, q.ceiling.k1);
  EXPECT_EQ(p.ceiling.k2_m, q.ceiling.k2_m);
  EXPECT_EQ(p.ceiling.taper_start_radii, q.ceiling.taper_start_radii);
  EXPECT_EQ(p.ceiling.taper_end_radii, q.ceiling.taper_end_radii);
  EXPECT_EQ(p.ground.model, q.ground.model);
  EXPECT_EQ(p.ground.body_lift_factor, q.ground.body_lift_factor);
  EXPECT_EQ(p.pack.cell_count, q.pack.cell_count);
  EXPECT_EQ(p.pack.resistance_ohm, q.pack.resistance_ohm);
  EXPECT_EQ(p.pack.avionics_current_a, q.pack.avionics_current_a);
  // And both give the founding paper's free-air hover current.
  energy::FlightCondition hover;
  hover.soc = p.reference_soc;
  EXPECT_NEAR(energy::EnergyModel(p).currentA(energy::kNoSurface, 0.0, hover), 9.5, 1e-9);
}

// quad.yaml with one line replaced, written to the scratch directory.
std::string errorOfVariant(const std::string& name, const std::string& from, const std::string& to) {
  std::string text = testing::readWholeFile(kQuad);
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("'" + from + "' not in quad.yaml");
  text.replace(at, from.size(), to);
  const std::filesystem::path file = testing::scratchDirectory("vehicle_" + name) / "vehicle.yaml";
  std::ofstream(file) << text;
  try {
    readVehicle(file);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    return message;
  }
  return "no error";
}

TEST(VehicleFile, NumbersOutsideTheirPhysicalRangeAreRefusedBeforeAnyIndexing) {
  // A collision radius of 36 m once stalled map indexing for minutes.
  EXPECT_NE(errorOfVariant("huge_radius", "collision_radius_m: 0.36", "collision_radius_m: 36")
                .find("'airframe.collision_radius_m' must be in (0, 3] m, got 36"),
            std::string::npos);
  EXPECT_NE(errorOfVariant("nan_mass", "mass_kg: 1.4", "mass_kg: .nan").find("'mass_kg' must be a finite number"),
            std::string::npos);
  EXPECT_NE(errorOfVariant("rotors", "count: 4", "count: 40").find("'rotors.count' must be a whole number in [1, 16]"),
            std::string::npos);
  EXPECT_NE(errorOfVariant("efficiency", "motor_efficiency: 0.80", "motor_efficiency: 80")
                .find("'power.motor_efficiency' must be in (0, 1], got 80"),
            std::string::npos);
}

TEST(VehicleFile, AnUnknownKeyNamesTheNearestValidKey) {
  EXPECT_NE(errorOfVariant("typo", "margin_m: 0.10", "margn_m: 0.10")
                .find("unknown key 'clearance.margn_m'; did you mean 'margin_m'?"),
            std::string::npos);
  EXPECT_NE(errorOfVariant("typo_power", "tip_speed_m_s: 80.0", "tip_sped_m_s: 80.0")
                .find("unknown key 'power.tip_sped_m_s'; did you mean 'tip_speed_m_s'?"),
            std::string::npos);
}

// yaml-cpp reads the first document only and answers a repeated key with one of its values.
TEST(VehicleFile, ARepeatedKeyOrASecondDocumentIsRefused) {
  EXPECT_NE(errorOfVariant("twice", "mass_kg: 1.4", "mass_kg: 1.4\nmass_kg: 2.0").find("key 'mass_kg' is given twice"),
            std::string::npos);
  EXPECT_NE(errorOfVariant("twice_in_a_section", "margin_m: 0.10", "margin_m: 0.10\n  margin_m: 0.20")
                .find("key 'clearance.margin_m' is given twice"),
            std::string::npos);
  EXPECT_NE(errorOfVariant("second_document", "mass_kg: 1.4", "mass_kg: 1.4\n---\nmass_kg: 2.0")
                .find("holds 2 YAML documents (split by '---'); a vehicle file is one document"),
            std::string::npos);
}

TEST(VehicleFile, CalibratedVehicleOfTheBuiltInOneReadsBack) {
  const std::filesystem::path out = testing::scratchDirectory("vehicle_calibrated") / "calibrated.yaml";
  energy::EnergyParameters parameters = mission::Vehicle::defaultQuad().energy;
  parameters.rotor.hover_power_w *= 1.1;
  writeCalibratedVehicle(out, {}, parameters, "test");
  const mission::Vehicle read = readVehicle(out);
  EXPECT_EQ(read.energy.rotor.hover_power_w, parameters.rotor.hover_power_w);
  EXPECT_EQ(read.geometry.collision_radius_m, mission::Vehicle::defaultQuad().geometry.collision_radius_m);
}

TEST(VehicleFile, TheCalibrationBlockRoundTripsAndIsReadStrictly) {
  const std::filesystem::path dir = testing::scratchDirectory("vehicle_calibration_block");
  energy::FitUncertainty calibration;
  calibration.samples = 120;
  calibration.residual_rms_a = 0.049;
  calibration.residual_std_a = 0.05;
  calibration.parameters = {energy::FreeParameter::kHoverPowerW, energy::FreeParameter::kK1};
  calibration.covariance = {{0.25, -0.01}, {-0.01, 0.04}};
  calibration.standard_errors = {0.5, 0.2};
  writeCalibratedVehicle(dir / "calibrated.yaml", {}, mission::Vehicle::defaultQuad().energy, "test", calibration);
  const mission::Vehicle read = readVehicle(dir / "calibrated.yaml");
  ASSERT_TRUE(read.calibration.has_value());
  EXPECT_EQ(read.calibration->samples, 120);
  EXPECT_EQ(read.calibration->residual_std_a, 0.05);
  EXPECT_EQ(read.calibration->residual_rms_a, 0.049);
  EXPECT_EQ(read.calibration->parameters, calibration.parameters);
  EXPECT_EQ(read.calibration->covariance, calibration.covariance);
  EXPECT_EQ(read.calibration->standard_errors, calibration.standard_errors);
  // Calibrating a calibrated vehicle again replaces its block rather than keeping the old one.
  writeCalibratedVehicle(dir / "again.yaml", dir / "calibrated.yaml", read.energy, "test");
  EXPECT_FALSE(readVehicle(dir / "again.yaml").calibration.has_value());

  std::ifstream written(dir / "calibrated.yaml");
  const std::string text((std::istreambuf_iterator<char>(written)), std::istreambuf_iterator<char>());
  const auto refused = [&](const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    if (at == std::string::npos) return std::string("(no '" + from + "' in the file)");
    std::string variant = text;
    variant.replace(at, from.size(), to);
    const std::filesystem::path file = dir / "variant.yaml";
    std::ofstream(file) << variant;
    try {
      readVehicle(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(refused("[hover_power_w, k1]", "[hover_power_w, k9]").find("calibration.parameters[1]"), std::string::npos);
  EXPECT_NE(refused("[hover_power_w, k1]", "[k1, k1]").find("repeats k1"), std::string::npos);
  EXPECT_NE(refused("[-0.01, 0.04]", "[-0.02, 0.04]").find("must be symmetric"), std::string::npos);
  EXPECT_NE(refused("[0.25, -0.01]", "[-0.25, -0.01]").find("positive semidefinite"), std::string::npos);
  EXPECT_NE(refused("residual_std_a:", "residual_sd_a:").find("residual_sd_a"), std::string::npos);
  EXPECT_NE(refused("[-0.01, 0.04]", "[-0.01]").find("calibration.covariance[1]"), std::string::npos);
}

}  // namespace
}  // namespace ceilplan::io
