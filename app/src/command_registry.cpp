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

CommandRegistration::CommandRegistration(int order, AddCommand add) {
  registry().emplace_back(order, std::move(add));
}

void addRegisteredCommands(CLI::App& parent) {
  auto& commands = registry();
  std::stable_sort(commands.begin(), commands.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& entry : commands) entry.second(parent);
}

}  // namespace ceilplan::app
