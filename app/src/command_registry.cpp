#include "command_registry.hpp"

#include <algorithm>
#include <utility>
#include <vector>

namespace ceilplan::app {
namespace {

std::vector<std::pair<int, AddCommand>>& registry() {
  static std::vector<std::pair<int, AddCommand>> commands;  // function-local: safe static init order
  return commands;
}

}  // namespace

CommandRegistration::CommandRegistration(int order, AddCommand add) { registry().emplace_back(order, std::move(add)); }

void addRegisteredCommands(CLI::App& parent) {
  auto& commands = registry();
  std::stable_sort(commands.begin(), commands.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& entry : commands) entry.second(parent);
  // Subcommands pass `--config` (see yaml_config.hpp) and `--version` up to the main app.
  for (CLI::App* command : parent.get_subcommands({})) {
    command->fallthrough();
    command->footer("Every flag can also come from a YAML file: ceilplan " + command->get_name() +
                    " --config FILE.yaml, keys = long flag names (flags given here win).");
  }
}

}  // namespace ceilplan::app
