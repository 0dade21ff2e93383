#pragma once
/// @file
/// SOC series read from CSV files and their rainflow cycles written as JSON and as a table: what
/// `ceilplan rainflow` reads, writes and prints (docs/ageing.md).

#include "ceilplan/battery/rainflow.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace ceilplan::io {

/// The SOC column `column` of a CSV (io::CsvColumns: other columns may hold anything, such as the
/// `mode` of `ceilplan duty --csv-dir`'s series). Each SOC must be a fraction in [0, 1], a t_s
/// column (if present) must not run backwards, and there must be at least 2 samples. Throws
/// ceilplan::InputError naming the file, line and column.
std::vector<double> readSocSeries(const std::filesystem::path& file, const std::string& column);

/// {"cycles": [{"range", "mean", "count", "start", "end"}, ...]}, keys in that order.
nlohmann::ordered_json rainflowJson(const std::vector<battery::RainflowCycle>& cycles);

/// A title naming the column, the file and its `samples`, one row per cycle (range, mean, count,
/// start, end) and the totals (battery::rainflowTotals). The names are echoed printable.
std::string rainflowText(const std::string& column, const std::filesystem::path& file, std::size_t samples,
                         const std::vector<battery::RainflowCycle>& cycles);

}  // namespace ceilplan::io
