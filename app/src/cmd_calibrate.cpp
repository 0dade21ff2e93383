// `ceilplan calibrate`: fit the energy model's free constants to measured currents.

#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/io/calibration_file.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/report_text.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include <memory>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

struct CalibrateOptions {
  std::string data_path;
  std::string out_path;
  std::string vehicle_path;
  std::vector<std::string> fit;
  std::string json_path;
};

void runCalibrate(const CalibrateOptions& options) {
  // Checked and staged before the fit; the vehicle and the report appear together.
  io::OutputSet out({{"--out", options.out_path}, {"--json", options.json_path}},
                    commandInputs({{"--data", options.data_path}, {"--vehicle", options.vehicle_path}}));
  const mission::Vehicle vehicle = io::readVehicleOrDefault(options.vehicle_path);
  const auto samples = io::readCalibrationSamples(options.data_path, vehicle.energy.reference_soc);
  std::vector<energy::FreeParameter> free;
  for (const std::string& name : options.fit) free.push_back(energy::parseFreeParameter(name));
  if (free.empty()) free = energy::identifiableParameters(vehicle.energy, samples);
  const io::Provenance provenance =
      commandProvenance().input("data", options.data_path).input("vehicle", options.vehicle_path);
  const energy::CalibrationResult result = energy::calibrate(vehicle.energy, samples, free);

  print(io::calibrationText(vehicle.name, options.data_path, samples.size(), result));
  io::writeCalibratedVehicle(out.path("--out"), options.vehicle_path, result.parameters,
                             io::calibratedVehicleComment(options.data_path, samples.size(), result, provenance),
                             result.uncertainty);
  if (!options.json_path.empty())
    io::writeJsonFile(
        out.path("--json"),
        io::withProvenance(io::calibrationReportJson(options.data_path, samples.size(), result), provenance));
  out.commit();
  print("wrote " + options.out_path + "\n");
  if (!options.json_path.empty()) print("wrote " + options.json_path + "\n");
}

const CommandRegistration registration(31, [](CLI::App& parent) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* command = parent.add_subcommand(
      "calibrate", "Fit the energy model's free constants to measured currents (bounded least squares)");
  command
      ->add_option("--data", options->data_path,
                   "CSV with current_a and any of gap_m, coverage, ground_gap_m, speed_m_s, climb_m_s, soc")
      ->required();
  command->add_option("--out", options->out_path, "vehicle YAML file to write with the fitted values")->required();
  command->add_option("--vehicle", options->vehicle_path,
                      "vehicle YAML file to start from; default: the built-in quadrotor");
  command
      ->add_option("--fit", options->fit,
                   "parameters to fit (hover_power_w, k1, k2_m, motor_efficiency, drag_area_m2, "
                   "pack_resistance_ohm); default: those the data's varied columns identify")
      ->delimiter(',');
  command->add_option("--json", options->json_path, "also write the fit report as JSON to this file");
  command->callback([options] { runCalibrate(*options); });
});

}  // namespace
}  // namespace ceilplan::app
