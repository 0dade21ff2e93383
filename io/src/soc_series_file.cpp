#include "ceilplan/io/soc_series_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/csv_columns.hpp"

#include <iomanip>
#include <sstream>

namespace ceilplan::io {
namespace {

constexpr const char* kTimeColumn = "t_s";

}  // namespace

std::vector<double> readSocSeries(const std::filesystem::path& file, const std::string& column) {
  const CsvColumns table = CsvColumns::read(file, {column}, {kTimeColumn});
  const std::vector<double>& soc = table.column(column);
  for (std::size_t row = 0; row < soc.size(); ++row) {
    if (soc[row] < 0.0 || soc[row] > 1.0)
      throw InputError(table.source() + " line " + std::to_string(table.lineOfRow(row)) + ", column '" +
                       printableText(column) + "': SOC " + formatNumber(soc[row]) +
                       " is outside [0, 1]; give SOC as a fraction");
  }
  const std::vector<double> no_time;
  const std::vector<double>& time_s = table.hasColumn(kTimeColumn) ? table.column(kTimeColumn) : no_time;
  for (std::size_t row = 1; row < time_s.size(); ++row) {
    if (time_s[row] < time_s[row - 1])
      throw InputError(table.source() + " line " + std::to_string(table.lineOfRow(row)) + ", column '" + kTimeColumn +
                       "': time goes backwards (" + formatNumber(time_s[row - 1]) + " s to " +
                       formatNumber(time_s[row]) + " s)");
  }
  if (table.rowCount() < 2)
    throw InputError(table.source() + " has " + std::to_string(table.rowCount()) +
                     (table.rowCount() == 1 ? " data row" : " data rows") +
                     "; a rainflow count needs at least 2 samples of '" + printableText(column) + "'");
  return soc;
}

nlohmann::ordered_json rainflowJson(const std::vector<battery::RainflowCycle>& cycles) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const battery::RainflowCycle& c : cycles)
    list.push_back({{"range", c.range}, {"mean", c.mean}, {"count", c.count}, {"start", c.start}, {"end", c.end}});
  nlohmann::ordered_json out;
  out["cycles"] = std::move(list);
  return out;
}

std::string rainflowText(const std::string& column, const std::filesystem::path& file, std::size_t samples,
                         const std::vector<battery::RainflowCycle>& cycles) {
  std::ostringstream out;
  out << "Rainflow cycles (ASTM E1049-85, residue as half cycles) of column '" << printableText(column) << "' in "
      << printableText(file.string(), 256) << ", " << samples << " samples\n\n";
  out << std::right << std::setw(10) << "range" << std::setw(10) << "mean" << std::setw(7) << "count" << std::setw(12)
      << "start" << std::setw(12) << "end" << '\n';
  for (const battery::RainflowCycle& c : cycles)
    out << std::setw(10) << formatFixed(c.range, 4) << std::setw(10) << formatFixed(c.mean, 4) << std::setw(7)
        << formatFixed(c.count, 1) << std::setw(12) << c.start << std::setw(12) << c.end << '\n';
  const battery::RainflowTotals totals = battery::rainflowTotals(cycles);
  out << '\n'
      << cycles.size() << " rows: " << formatNumber(totals.full_cycles) << " full and "
      << formatNumber(totals.half_cycles) << " half cycles, " << formatNumber(totals.cycles)
      << " cycles in all; sum of count x range " << formatNumber(totals.count_weighted_range) << '\n';
  return out.str();
}

}  // namespace ceilplan::io
