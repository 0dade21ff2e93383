// `ceilplan rainflow`: the rainflow cycles (ASTM E1049-85) of an SOC column in a CSV file.

#include "command_registry.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/temporary_output.hpp"

#include "ceilplan/battery/rainflow.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
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

// SOC must be a fraction, time (if the file has it) must not run backwards, and a count needs
// at least two samples.
void checkSeries(const io::CsvColumns& table, const std::string& column) {
  const std::vector<double>& soc = table.column(column);
  for (std::size_t row = 0; row < soc.size(); ++row) {
    if (soc[row] < 0.0 || soc[row] > 1.0)
      throw InputError(table.source() + " line " + std::to_string(table.lineOfRow(row)) + ", column '" +
                       ceilplan::printableText(column) + "': SOC " + formatNumber(soc[row]) +
                       " is outside [0, 1]; give SOC as a fraction");
  }
  const std::vector<double> no_time;
  const std::vector<double>& time_s = table.hasColumn(kTimeColumn) ? table.column(kTimeColumn) : no_time;
  for (std::size_t row = 1; row < time_s.size(); ++row) {
    if (time_s[row] < time_s[row - 1])
      throw InputError(table.source() + " line " + std::to_string(table.lineOfRow(row)) + ", column '" +
                       kTimeColumn + "': time goes backwards (" + formatNumber(time_s[row - 1]) + " s to " +
                       formatNumber(time_s[row]) + " s)");
  }
  if (table.rowCount() < 2)
    throw InputError(table.source() + " has " + std::to_string(table.rowCount()) +
                     (table.rowCount() == 1 ? " data row" : " data rows") +
                     "; a rainflow count needs at least 2 samples of '" + ceilplan::printableText(column) + "'");
}

void printCycles(const RainflowArguments& args, std::size_t samples, const std::vector<RainflowCycle>& cycles) {
  std::cout << "Rainflow cycles (ASTM E1049-85, residue as half cycles) of column '" << ceilplan::printableText(args.column)
            << "' in " << ceilplan::printableText(args.csv_path, 256) << ", " << samples << " samples\n\n";
  std::cout << std::right << std::setw(10) << "range" << std::setw(10) << "mean" << std::setw(7) << "count"
            << std::setw(12) << "start" << std::setw(12) << "end" << '\n';
  double full = 0.0, half = 0.0, weighted_range = 0.0;
  for (const RainflowCycle& c : cycles) {
    std::cout << std::setw(10) << formatFixed(c.range, 4) << std::setw(10) << formatFixed(c.mean, 4) << std::setw(7)
              << formatFixed(c.count, 1) << std::setw(12) << c.start << std::setw(12) << c.end << '\n';
    (c.count == 1.0 ? full : half) += 1.0;
    weighted_range += c.count * c.range;
  }
  std::cout << '\n'
            << cycles.size() << " rows: " << formatNumber(full) << " full and " << formatNumber(half)
            << " half cycles, " << formatNumber(full + 0.5 * half) << " cycles in all; sum of count x range "
            << formatNumber(weighted_range) << '\n';
}

nlohmann::ordered_json toJson(const std::vector<RainflowCycle>& cycles) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RainflowCycle& c : cycles)
    list.push_back({{"range", c.range}, {"mean", c.mean}, {"count", c.count}, {"start", c.start}, {"end", c.end}});
  nlohmann::ordered_json out;
  out["cycles"] = std::move(list);
  return out;
}

void writeJson(const std::string& path, const std::vector<RainflowCycle>& cycles) {
  io::TemporaryOutput output(path);
  {
    std::ofstream out(output.path());
    if (!out) throw Error("cannot open " + ceilplan::printableText(path, 256) + " for writing; check the directory");
    out << toJson(cycles).dump(2) << '\n';
    if (!out.flush()) throw Error("failed while writing " + ceilplan::printableText(path, 256) + " (disk full?)");
  }
  output.commit();
}

void runRainflow(const RainflowArguments& args) {
  io::installSignalCleanup();  // idempotent; main() should call it first, before any thread starts
  if (!args.json_path.empty() && std::filesystem::is_directory(args.json_path))
    throw InputError("--json " + ceilplan::printableText(args.json_path, 256) + " is a directory; give a file name");
  if (!args.json_path.empty()) io::checkWritableFile(args.json_path);
  const io::CsvColumns table = io::CsvColumns::read(args.csv_path, {args.column}, {kTimeColumn});
  checkSeries(table, args.column);
  const std::vector<RainflowCycle> cycles = battery::countRainflowCycles(table.column(args.column));
  printCycles(args, table.rowCount(), cycles);
  if (!args.json_path.empty()) writeJson(args.json_path, cycles);
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
