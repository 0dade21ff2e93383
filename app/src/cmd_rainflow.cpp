// `ceilplan rainflow`: the rainflow cycles (ASTM E1049-85) of an SOC column in a CSV file.

#include "command_registry.hpp"
#include "csv_table.hpp"
#include "output.hpp"

#include "ceilplan/battery/rainflow.hpp"
#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace ceilplan::app {
namespace {

using battery::RainflowCycle;

constexpr const char* kTimeColumn = "t_s";

struct RainflowArguments {
  std::string csv_path;
  std::string column;
  std::string json_path;
};

// SOC must be a fraction, and time (if the file has it) must not run backwards.
void checkSeries(const CsvTable& table, const std::string& column) {
  const std::vector<double>& soc = table.column(column);
  for (std::size_t row = 0; row < soc.size(); ++row) {
    if (soc[row] < 0.0 || soc[row] > 1.0)
      throw std::runtime_error(table.source() + " line " + std::to_string(table.lineOfRow(row)) +
                               ", column '" + column + "': SOC " + formatNumber(soc[row]) +
                               " is outside [0, 1]; give SOC as a fraction");
  }
  if (!table.hasColumn(kTimeColumn)) return;
  const std::vector<double>& time_s = table.column(kTimeColumn);
  for (std::size_t row = 1; row < time_s.size(); ++row) {
    if (time_s[row] < time_s[row - 1])
      throw std::runtime_error(table.source() + " line " + std::to_string(table.lineOfRow(row)) +
                               ", column '" + kTimeColumn + "': time goes backwards (" +
                               formatNumber(time_s[row - 1]) + " s to " + formatNumber(time_s[row]) +
                               " s)");
  }
}

void printCycles(const RainflowArguments& args, std::size_t samples,
                 const std::vector<RainflowCycle>& cycles) {
  std::cout << "Rainflow cycles (ASTM E1049-85, residue as half cycles) of column '" << args.column
            << "' in " << args.csv_path << ", " << samples << " samples\n\n";
  std::cout << std::right << std::setw(10) << "range" << std::setw(10) << "mean" << std::setw(7)
            << "count" << std::setw(12) << "start" << std::setw(12) << "end" << '\n';
  double full = 0.0, half = 0.0, weighted_range = 0.0;
  std::cout << std::fixed;
  for (const RainflowCycle& c : cycles) {
    std::cout << std::setw(10) << std::setprecision(4) << c.range << std::setw(10) << c.mean
              << std::setw(7) << std::setprecision(1) << c.count << std::setw(12) << c.start
              << std::setw(12) << c.end << '\n';
    (c.count == 1.0 ? full : half) += 1.0;
    weighted_range += c.count * c.range;
  }
  std::cout << std::defaultfloat << std::setprecision(6) << '\n'
            << cycles.size() << " rows: " << full << " full and " << half << " half cycles, "
            << full + 0.5 * half << " cycles in all; sum of count x range " << weighted_range
            << '\n';
}

nlohmann::ordered_json toJson(const std::vector<RainflowCycle>& cycles) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RainflowCycle& c : cycles)
    list.push_back(
        {{"range", c.range}, {"mean", c.mean}, {"count", c.count}, {"start", c.start}, {"end", c.end}});
  nlohmann::ordered_json out;
  out["cycles"] = std::move(list);
  return out;
}

void runRainflow(const RainflowArguments& args) {
  const CsvTable table = CsvTable::read(args.csv_path);
  checkSeries(table, args.column);
  const std::vector<RainflowCycle> cycles = battery::countRainflowCycles(table.column(args.column));
  printCycles(args, table.rowCount(), cycles);
  if (!args.json_path.empty())
    writeTextAtomically(args.json_path,
                        [&](std::ostream& out) { out << toJson(cycles).dump(2) << '\n'; });
}

void addRainflowCommand(CLI::App& parent) {
  auto args = std::make_shared<RainflowArguments>();
  CLI::App* command = parent.add_subcommand(
      "rainflow", "Rainflow cycles (ASTM E1049-85) of an SOC column: depth, mean SOC, count, "
                  "and the 0-based data rows where each starts and ends");
  command->add_option("--csv", args->csv_path, "CSV file with a header row (a t_s column, if "
                                               "present, must not go backwards)")
      ->required();
  command->add_option("--column", args->column, "Column holding the SOC, as a fraction in [0, 1]")
      ->required();
  command->add_option("--json", args->json_path,
                      "Also write {\"cycles\": [{range, mean, count, start, end}, ...]} to this file");
  command->callback([args] { runRainflow(*args); });
}

const CommandRegistration registration{15, addRainflowCommand};

}  // namespace
}  // namespace ceilplan::app
