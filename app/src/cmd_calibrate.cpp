// `ceilplan calibrate`: fit the energy model's free constants to measured currents.

#include "command_registry.hpp"
#include "output.hpp"
#include "ceilplan/core/printable_text.hpp"

#include "ceilplan/io/vehicle_file.hpp"

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/core/error.hpp"

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
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

std::string trimmed(const std::string& text) {
  const auto begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return {};
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream stream(line);
  std::string cell;
  while (std::getline(stream, cell, ',')) cells.push_back(trimmed(cell));
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// The CSV columns (docs/energy.md, "Calibration"); a column left out keeps the sample's default
// ("not varied").
const std::map<std::string, double energy::CalibrationSample::*>& columns() {
  static const std::map<std::string, double energy::CalibrationSample::*> known = {
      {"gap_m", &energy::CalibrationSample::ceiling_gap_m},
      {"coverage", &energy::CalibrationSample::coverage},
      {"ground_gap_m", &energy::CalibrationSample::ground_gap_m},
      {"speed_m_s", &energy::CalibrationSample::speed_m_s},
      {"climb_m_s", &energy::CalibrationSample::climb_m_s},
      {"soc", &energy::CalibrationSample::soc},
      {"current_a", &energy::CalibrationSample::current_a}};
  return known;
}

// Reads samples; '#' lines are comments. In the gap columns an empty cell or "none" means no surface.
std::vector<energy::CalibrationSample> readSamples(const std::string& path, double default_soc) {
  if (std::filesystem::is_directory(path))
    throw ceilplan::InputError("calibration data " + ceilplan::printableText(path, 256) + " is a directory; give a CSV file");
  std::ifstream in(path);
  if (!in) throw ceilplan::InputError("cannot read calibration data " + ceilplan::printableText(path, 256) + " (missing or unreadable)");
  std::vector<double energy::CalibrationSample::*> header;
  std::vector<std::string> names;
  std::vector<energy::CalibrationSample> samples;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    if (line_number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 byte-order mark
    const std::string content = trimmed(line);
    if (content.empty() || content[0] == '#') continue;
    const std::string where = ceilplan::printableText(path, 256) + " line " + std::to_string(line_number) + ": ";
    const std::vector<std::string> cells = splitCells(content);
    if (header.empty()) {
      for (const std::string& name : cells) {
        const auto known = columns().find(name);
        if (known == columns().end())
          throw ceilplan::InputError(where + "unknown column '" + ceilplan::printableText(name) +
                                      "' (known: gap_m, coverage, ground_gap_m, speed_m_s, climb_m_s, soc, current_a)");
        for (const std::string& seen : names)
          if (seen == name) throw ceilplan::InputError(where + "column " + ceilplan::printableText(name) + " appears twice");
        header.push_back(known->second);
        names.push_back(name);
      }
      bool has_current = false;
      for (const std::string& name : names) has_current |= name == "current_a";
      if (!has_current) throw ceilplan::InputError(where + "the header has no current_a column");
      continue;
    }
    if (cells.size() != header.size())
      throw ceilplan::InputError(where + std::to_string(cells.size()) + " cells, the header has " +
                                  std::to_string(header.size()));
    energy::CalibrationSample sample;
    sample.soc = default_soc;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const bool gap_column = names[c] == "gap_m" || names[c] == "ground_gap_m";
      if (gap_column && (cells[c].empty() || cells[c] == "none")) {
        sample.*header[c] = energy::kNoSurface;
        continue;
      }
      char* end = nullptr;
      errno = 0;
      const double value = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || *end != '\0' || errno == ERANGE || !std::isfinite(value))
        throw ceilplan::InputError(where + "column " + names[c] + ": '" + ceilplan::printableText(cells[c]) + "' is not a finite number");
      sample.*header[c] = value;
    }
    samples.push_back(sample);
  }
  if (samples.empty()) throw ceilplan::InputError("calibration data " + ceilplan::printableText(path, 256) + " holds no samples");
  return samples;
}

void runCalibrate(const CalibrateOptions& options) {
  checkWritableFile(options.out_path);  // before the fit
  if (!options.json_path.empty()) checkWritableFile(options.json_path);
  const mission::Vehicle vehicle =
      options.vehicle_path.empty() ? mission::Vehicle::defaultQuad() : io::readVehicle(options.vehicle_path);
  const auto samples = readSamples(options.data_path, vehicle.energy.reference_soc);
  std::vector<energy::FreeParameter> free;
  for (const std::string& name : options.fit) free.push_back(energy::parseFreeParameter(name));
  if (free.empty()) free = energy::identifiableParameters(vehicle.energy, samples);
  const energy::CalibrationResult result = energy::calibrate(vehicle.energy, samples, free);

  std::printf("vehicle     %s\n", vehicle.name.c_str());
  std::printf("data        %s (%zu samples)\n", options.data_path.c_str(), samples.size());
  std::printf("rmse_a      %.5f   (largest error %.5f A, %d model evaluations)\n", result.rmse_a,
              result.max_abs_error_a, result.evaluations);
  std::printf("%-20s %14s %14s %14s %14s\n", "parameter", "fitted", "allowed_min", "allowed_max", "start");
  nlohmann::json fitted = nlohmann::json::array();
  std::string summary;
  for (const energy::FittedParameter& f : result.fitted) {
    const std::string name = energy::parameterName(f.parameter);
    const bool at_bound = f.value <= f.lower * (1 + 1e-6) || f.value >= f.upper * (1 - 1e-6);
    std::printf("%-20s %14.6g %14.6g %14.6g %14.6g%s\n", name.c_str(), f.value, f.lower, f.upper, f.start,
                at_bound ? "  (at its bound)" : "");
    fitted.push_back({{"parameter", name}, {"value", f.value}, {"allowed_min", f.lower}, {"allowed_max", f.upper},
                      {"start", f.start}, {"at_bound", at_bound}});
    summary += (summary.empty() ? "" : ", ") + name;
  }
  std::ostringstream comment;
  comment << "Calibrated by `ceilplan calibrate` from " << options.data_path << " (" << samples.size()
          << " samples; fitted " << summary << "; RMSE " << result.rmse_a << " A).";
  io::writeCalibratedVehicle(options.out_path, options.vehicle_path, result.parameters, comment.str());
  std::printf("wrote %s\n", options.out_path.c_str());
  if (!options.json_path.empty()) {
    const nlohmann::json report = {{"data", options.data_path},        {"samples", samples.size()},
                                   {"rmse_a", result.rmse_a},          {"max_abs_error_a", result.max_abs_error_a},
                                   {"evaluations", result.evaluations}, {"fitted", fitted}};
    writeTextAtomically(options.json_path, [&](std::ostream& out) { out << report.dump(2) << '\n'; });
    std::printf("wrote %s\n", options.json_path.c_str());
  }
}

const CommandRegistration registration(31, [](CLI::App& parent) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* command = parent.add_subcommand(
      "calibrate", "Fit the energy model's free constants to measured currents (bounded least squares)");
  command->add_option("--data", options->data_path,
                      "CSV with current_a and any of gap_m, coverage, ground_gap_m, speed_m_s, climb_m_s, soc")
      ->required();
  command->add_option("--out", options->out_path, "vehicle YAML file to write with the fitted values")->required();
  command->add_option("--vehicle", options->vehicle_path,
                      "vehicle YAML file to start from; default: the built-in quadrotor");
  command->add_option("--fit", options->fit,
                      "parameters to fit (hover_power_w, k1, k2_m, motor_efficiency, drag_area_m2, "
                      "pack_resistance_ohm); default: those the data's varied columns identify")
      ->delimiter(',');
  command->add_option("--json", options->json_path, "also write the fit report as JSON to this file");
  command->callback([options] { runCalibrate(*options); });
});

}  // namespace
}  // namespace ceilplan::app
