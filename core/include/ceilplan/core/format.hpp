#pragma once
/// @file
/// The one number formatter of ceilplan, for messages, tables and text outputs: never
/// std::to_string's "0.500000".

#include <Eigen/Core>

#include <string>

namespace ceilplan {

/// At most `significant` significant digits, no trailing zeros: "5.2", "0.009655", "1e-09", "nan", "inf".
std::string formatNumber(double value, int significant = 6);

/// Appends formatNumber(value, significant) to `text`, without a string of its own: what a
/// stream with that precision writes (printf's "%.*g"), for files of many numbers (path.csv).
void appendNumber(std::string& text, double value, int significant = 6);

/// Exactly `decimals` decimals: formatFixed(43.5, 2) == "43.50"; from 1e15 on, as formatNumber.
std::string formatFixed(double value, int decimals);

/// Appends formatFixed(value, decimals) to `text`, without a string of its own: for files of
/// many numbers (trajectories, path.csv).
void appendFixed(std::string& text, double value, int decimals);

/// "(x, y, z)" with `decimals` decimals each: formatPoint({1, 2, 3}) == "(1.00, 2.00, 3.00)".
std::string formatPoint(const Eigen::Vector3d& point, int decimals = 2);

}  // namespace ceilplan
