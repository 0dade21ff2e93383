#pragma once
// Subcommands register themselves from their own file, so adding one touches no shared list.

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace ceilplan::app {

using AddCommand = std::function<void(CLI::App& parent)>;

// Registers a subcommand; `order` fixes its place in `ceilplan --help`.
struct CommandRegistration {
  CommandRegistration(int order, AddCommand add);
};

// Adds every registered subcommand to `parent`, in order.
void addRegisteredCommands(CLI::App& parent);

}  // namespace ceilplan::app
