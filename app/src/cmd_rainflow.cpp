// `ceilplan rainflow`: the rainflow cycles (ASTM E1049-85) of an SOC column in a CSV file.

#include "command_registry.hpp"
#include "output.hpp"

#include "ceilplan/battery/rainflow.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/soc_series_file.hpp"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::app {
namespace {

struct RainflowArguments {
  std::string csv_path;
  std::string column;
  std::string json_path;
};

void runRainflow(const RainflowArguments& args) {
  if (!args.json_path.empty() && std::filesystem::is_directory(args.json_path))
    throw InputError("--json " + ceilplan::printableText(args.json_path, 256) + " is a directory; give a file name");
  io::OutputSet out({{"--json", args.json_path}}, commandInputs({{"--csv", args.csv_path}}));
  const std::vector<double> soc = io::readSocSeries(args.csv_path, args.column);
  const io::Provenance provenance = commandProvenance().input("series", args.csv_path);
  const std::vector<battery::RainflowCycle> cycles = battery::countRainflowCycles(soc);
  print(io::rainflowText(args.column, args.csv_path, soc.size(), cycles));
  if (!args.json_path.empty())
    io::writeJsonFile(out.path("--json"), io::withProvenance(io::rainflowJson(cycles), provenance));
  out.commit();
}

void addRainflowCommand(CLI::App& parent) {
  auto args = std::make_shared<RainflowArguments>();
  CLI::App* command = parent.add_subcommand("rainflow",
                                            "Rainflow cycles (ASTM E1049-85) of an SOC column: depth, mean SOC, count, "
                                            "and the 0-based data rows where each starts and ends");
  command
      ->add_option("--csv", args->csv_path,
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
