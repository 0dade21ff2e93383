#pragma once
/// @file
/// The measurements `ceilplan calibrate` fits the energy model to, and its fit report
/// (docs/energy.md).

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/io/provenance.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// A CSV (io::CsvColumns: '#' comments, quoting) with a current_a column and any of gap_m,
/// coverage, ground_gap_m, speed_m_s, climb_m_s, soc. A column left out keeps the sample's
/// default ("not varied"), soc `default_soc`; in the gap columns an empty field or "none" means
/// no surface. Throws ceilplan::InputError naming the file (and line and column) for an unknown
/// column, a missing current_a, a field that is not a finite number, or no samples.
std::vector<energy::CalibrationSample> readCalibrationSamples(const std::filesystem::path& file, double default_soc);

/// {data, samples, rmse_a, max_abs_error_a, evaluations, fitted: [{parameter, value, allowed_min,
/// allowed_max, start, at_bound}]}.
nlohmann::json calibrationReportJson(const std::filesystem::path& data, std::size_t samples,
                                     const energy::CalibrationResult& result);

/// The comment heading the calibrated vehicle file (io::writeCalibratedVehicle): the data and its
/// samples, the parameters fitted and the RMSE; on a second line the provenance.
std::string calibratedVehicleComment(const std::filesystem::path& data, std::size_t samples,
                                     const energy::CalibrationResult& result, const Provenance& provenance);

}  // namespace ceilplan::io
