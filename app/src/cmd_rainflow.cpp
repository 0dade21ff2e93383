// `ceilplan rainflow`: the rainflow cycles (ASTM E1049-85) of an SOC column in a CSV file.

#include "command_registry.hpp"

#include "ceilplan/battery/rainflow.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/soc_series_file.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

using battery::RainflowCycle;

struct RainflowArguments {
  std::string csv_path;
  std::string column;
  std::string json_path;
};

void printCycles(const RainflowArguments& args, std::size_t samples, const std::vector<RainflowCycle>& cycles) {
  std::cout << "Rainflow cycles (ASTM E1049-85, residue as half cycles) of column '" << ceilplan::printableText(args.column)
            << "' in " << ceilplan::printableText(args.csv_path, 256) << ", " << samples << " samples\n\n";
  std::cout << std::right << std::setw(10) << "range" << std::setw(10) << "mean" << std::setw(7) << "count"
            << std::setw(12) << "start" << std::setw(12) << "end" << '\n';
  for (const RainflowCycle& c : cycles)
    std::cout << std::setw(10) << formatFixed(c.range, 4) << std::setw(10) << formatFixed(c.mean, 4) << std::setw(7)
              << formatFixed(c.count, 1) << std::setw(12) << c.start << std::setw(12) << c.end << '\n';
  const battery::RainflowTotals totals = battery::rainflowTotals(cycles);
  std::cout << '\n'
            << cycles.size() << " rows: " << formatNumber(totals.full_cycles) << " full and "
            << formatNumber(totals.half_cycles) << " half cycles, " << formatNumber(totals.cycles)
            << " cycles in all; sum of count x range " << formatNumber(totals.count_weighted_range) << '\n';
}

void runRainflow(const RainflowArguments& args) {
  if (!args.json_path.empty() && std::filesystem::is_directory(args.json_path))
    throw InputError("--json " + ceilplan::printableText(args.json_path, 256) + " is a directory; give a file name");
  if (!args.json_path.empty()) io::checkWritableFile(args.json_path);
  const std::vector<double> soc = io::readSocSeries(args.csv_path, args.column);
  const std::vector<RainflowCycle> cycles = battery::countRainflowCycles(soc);
  printCycles(args, soc.size(), cycles);
  if (!args.json_path.empty()) io::writeJsonFile(args.json_path, io::rainflowJson(cycles));
}

void addRainflowCommand(CLI::App& parent) {
  auto args = std::make_shared<RainflowArguments>();
  CLI::App* command = parent.add_subcommand(
      "rainflow", "Rainflow cycles (ASTM E1049-85) of an SOC column: depth, mean SOC, count, "
                  "and the 0-based data rows where each starts and ends");
  command->add_option("--csv", args->csv_path,
                      "CSV file with a header row; other columns may hold anything (e.g. `ceilplan duty "
                      "--csv-dir`'s series); a t_s column, if present, must not go backwards")
      ->required();
  command->add_option("--column", args->column, "Column holding the SOC, as a fraction in [0, 1]")->required();
  command->add_option("--json", args->json_path,
                      "Also write {\"cycles\": [{range, mean, count, start, end}, ...]} to this file");
  command->callback([args] { runRainflow(*args); });
}

const CommandRegistration registration{15, addRainflowCommand};

}  // namespace
}  // namespace ceilplan::app
