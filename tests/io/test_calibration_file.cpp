// The measurements `ceilplan calibrate` reads and the fit report it writes and prints.

#include "ceilplan/io/calibration_file.hpp"
#include "ceilplan/io/report_text.hpp"

#include "ceilplan/core/error.hpp"

#include "input_error.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace ceilplan::io {
namespace {

std::filesystem::path dataFile(const std::string& name, const std::string& text) {
  const auto file = testing::scratchDirectory("calibration_file") / name;
  std::ofstream(file) << text;
  return file;
}

std::string errorOf(const std::string& text) {
  return testing::inputErrorOf([&] { readCalibrationSamples(dataFile("bad.csv", text), 0.65); });
}

TEST(CalibrationFile, ReadsTheNamedColumnsAndKeepsTheOthersDefault) {
  const auto samples = readCalibrationSamples(
      dataFile("data.csv", "# hover under a deck\ngap_m, ground_gap_m ,current_a\nnone,,9.5\n0.05,1.2,8.0\n"), 0.8);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_EQ(samples[0].ceiling_gap_m, energy::kNoSurface);  // "none": no surface
  EXPECT_EQ(samples[0].ground_gap_m, energy::kNoSurface);   // empty: no surface
  EXPECT_EQ(samples[0].current_a, 9.5);
  EXPECT_EQ(samples[1].ceiling_gap_m, 0.05);
  EXPECT_EQ(samples[1].ground_gap_m, 1.2);
  EXPECT_EQ(samples[1].current_a, 8.0);
  EXPECT_EQ(samples[1].soc, 0.8);  // no soc column: the vehicle's reference SOC
  EXPECT_EQ(samples[1].speed_m_s, energy::CalibrationSample{}.speed_m_s);
  EXPECT_EQ(samples[1].coverage, 1.0);
}

TEST(CalibrationFile, RefusesWhatItCannotReadInOneLine) {
  EXPECT_NE(errorOf("gap,current_a\n0.05,8\n").find("unknown column 'gap' (known: gap_m, coverage, "),
            std::string::npos);
  EXPECT_NE(errorOf("gap_m\n0.05\n").find("has no column 'current_a'"), std::string::npos);
  EXPECT_NE(
      errorOf("gap_m,current_a\nnone,9.5\n0.05,eight\n").find("line 3, column 'current_a': 'eight' is not a number"),
      std::string::npos);
  EXPECT_NE(errorOf("coverage,current_a\nnone,9.5\n").find("column 'coverage': 'none' is not a number"),
            std::string::npos);  // "none" only for the gaps
  EXPECT_NE(errorOf("gap_m,current_a\n").find("holds no samples"), std::string::npos);
  EXPECT_NE(errorOf("gap_m,current_a\n\x1b]0;x\x07,9\n").find("\\x1B]0;x\\x07"), std::string::npos);
  EXPECT_THROW(readCalibrationSamples(testing::scratchDirectory("calibration_file") / "missing.csv", 0.65), InputError);
}

// A fit of k1 (inside its range) and k2_m (at its upper bound) to 17 samples.
energy::CalibrationResult twoParameterFit() {
  energy::CalibrationResult result;
  result.rmse_a = 0.05;
  result.max_abs_error_a = 0.1;
  result.evaluations = 42;
  result.fitted = {{energy::FreeParameter::kK1, 2.0, 1.0, 4.0, 1.5}, {energy::FreeParameter::kK2M, 0.5, 0.1, 0.5, 0.2}};
  result.parameters.ceiling.k1 = 2.0;
  result.parameters.ceiling.k2_m = 0.5;
  result.uncertainty.samples = 17;
  result.uncertainty.residual_rms_a = 0.05;
  result.uncertainty.residual_std_a = 0.052;
  result.uncertainty.parameters = {energy::FreeParameter::kK1, energy::FreeParameter::kK2M};
  result.uncertainty.covariance = {{0.01, 0.0}, {0.0, 0.0025}};
  result.uncertainty.standard_errors = {0.1, 0.05};
  return result;
}

TEST(CalibrationFile, ReportNamesEachFittedParameterAndWhetherItHitItsBound) {
  const energy::CalibrationResult result = twoParameterFit();
  const nlohmann::json report = calibrationReportJson("data.csv", 17, result);
  EXPECT_EQ(report["data"], "data.csv");
  EXPECT_EQ(report["samples"].get<int>(), 17);
  EXPECT_EQ(report["evaluations"].get<int>(), 42);
  ASSERT_EQ(report["fitted"].size(), 2u);
  EXPECT_EQ(report["fitted"][0]["parameter"], "k1");
  EXPECT_EQ(report["fitted"][0]["allowed_max"].get<double>(), 4.0);
  EXPECT_FALSE(report["fitted"][0]["at_bound"].get<bool>());
  EXPECT_EQ(report["fitted"][1]["parameter"], "k2_m");
  EXPECT_TRUE(report["fitted"][1]["at_bound"].get<bool>());
  EXPECT_EQ(report["uncertainty"]["residual_std_a"].get<double>(), 0.052);
  EXPECT_EQ(report["uncertainty"]["parameters"][1], "k2_m");
  EXPECT_EQ(report["uncertainty"]["standard_errors"][1].get<double>(), 0.05);
  EXPECT_EQ(report["uncertainty"]["covariance"][0][0].get<double>(), 0.01);
  const Provenance provenance = Provenance::of("ceilplan calibrate --data data.csv");
  EXPECT_EQ(calibratedVehicleComment("data.csv", 17, result, provenance),
            "Calibrated by `ceilplan calibrate` from data.csv (17 samples; fitted k1, k2_m; RMSE 0.05 A).\n" +
                provenance.line());
}

TEST(CalibrationFile, TheTerminalTextListsEachParameterAndMarksThoseAtTheirBound) {
  EXPECT_EQ(calibrationText("quad", "data.csv", 17, twoParameterFit()),
            "vehicle     quad\n"
            "data        data.csv (17 samples)\n"
            "rmse_a      0.05000   (largest error 0.10000 A, 42 model evaluations)\n"
            "parameter                    fitted    allowed_min    allowed_max          start\n"
            "k1                                2              1              4            1.5\n"
            "k2_m                            0.5            0.1            0.5            0.2  (at its bound)\n"
            "residual    std 0.05200 A, RMS 0.05000 A (n - p = 15)\n"
            "parameter                 std_error       relative\n"
            "k1                              0.1             5%\n"
            "k2_m                           0.05            10%\n");
}

}  // namespace
}  // namespace ceilplan::io
