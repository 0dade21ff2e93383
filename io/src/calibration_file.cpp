#include "ceilplan/io/calibration_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/csv_columns.hpp"

#include <algorithm>
#include <sstream>
#include <string>
#include <utility>

namespace ceilplan::io {
namespace {

using Field = double energy::CalibrationSample::*;

// The columns, in the order the error message lists them.
const std::vector<std::pair<std::string, Field>>& columns() {
  static const std::vector<std::pair<std::string, Field>> known = {
      {"gap_m", &energy::CalibrationSample::ceiling_gap_m},       {"coverage", &energy::CalibrationSample::coverage},
      {"ground_gap_m", &energy::CalibrationSample::ground_gap_m}, {"speed_m_s", &energy::CalibrationSample::speed_m_s},
      {"climb_m_s", &energy::CalibrationSample::climb_m_s},       {"soc", &energy::CalibrationSample::soc},
      {"current_a", &energy::CalibrationSample::current_a}};
  return known;
}

}  // namespace

std::vector<energy::CalibrationSample> readCalibrationSamples(const std::filesystem::path& file, double default_soc) {
  std::vector<std::string> optional;
  std::string known;
  for (const auto& column : columns()) {
    if (column.first != "current_a") optional.push_back(column.first);
    known += (known.empty() ? "" : ", ") + column.first;
  }
  const CsvColumns table = CsvColumns::read(file, {"current_a"}, optional, {"gap_m", "ground_gap_m"});
  for (const std::string& name : table.columnNames())
    if (std::none_of(columns().begin(), columns().end(), [&](const auto& column) { return column.first == name; }))
      throw InputError(table.source() + ": unknown column '" + printableText(name) + "' (known: " + known + ")");
  if (table.rowCount() == 0) throw InputError("calibration data " + table.source() + " holds no samples");

  std::vector<energy::CalibrationSample> samples(table.rowCount());
  for (energy::CalibrationSample& sample : samples) sample.soc = default_soc;
  for (const auto& [name, field] : columns()) {
    if (!table.hasColumn(name)) continue;  // not varied: the sample's default
    const std::vector<double>& values = table.column(name);
    for (std::size_t row = 0; row < samples.size(); ++row) samples[row].*field = values[row];
  }
  return samples;
}

nlohmann::json calibrationReportJson(const std::filesystem::path& data, std::size_t samples,
                                     const energy::CalibrationResult& result) {
  nlohmann::json fitted = nlohmann::json::array();
  for (const energy::FittedParameter& f : result.fitted)
    fitted.push_back({{"parameter", energy::parameterName(f.parameter)},
                      {"value", f.value},
                      {"allowed_min", f.lower},
                      {"allowed_max", f.upper},
                      {"start", f.start},
                      {"at_bound", f.atBound()}});
  const energy::FitUncertainty& u = result.uncertainty;
  nlohmann::json uncertainty = {{"residual_std_a", u.residual_std_a}, {"residual_rms_a", u.residual_rms_a}};
  if (u.hasCovariance()) {
    nlohmann::json names = nlohmann::json::array();
    for (energy::FreeParameter parameter : u.parameters) names.push_back(energy::parameterName(parameter));
    uncertainty["parameters"] = names;
    uncertainty["standard_errors"] = u.standard_errors;
    uncertainty["covariance"] = u.covariance;
  } else {
    uncertainty["unavailable"] = u.unavailable;
  }
  return {{"data", data.string()},
          {"samples", samples},
          {"uncertainty", uncertainty},
          {"rmse_a", result.rmse_a},
          {"max_abs_error_a", result.max_abs_error_a},
          {"evaluations", result.evaluations},
          {"fitted", fitted}};
}

std::string calibratedVehicleComment(const std::filesystem::path& data, std::size_t samples,
                                     const energy::CalibrationResult& result, const Provenance& provenance) {
  std::string fitted;
  for (const energy::FittedParameter& f : result.fitted)
    fitted += (fitted.empty() ? "" : ", ") + energy::parameterName(f.parameter);
  std::ostringstream comment;
  comment << "Calibrated by `ceilplan calibrate` from " << data.string() << " (" << samples << " samples; fitted "
          << fitted << "; RMSE " << result.rmse_a << " A).\n"
          << provenance.line();
  return comment.str();
}

}  // namespace ceilplan::io
