#include "yaml_config.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/flag_file.hpp"

#include <string>

namespace ceilplan::app {
namespace {

// The long flag names `command` takes (and the main app's, which subcommands fall through to).
std::vector<std::string> flagNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* app = &command; app != nullptr; app = app->get_parent())
    for (const CLI::Option* option : app->get_options())
      if (option->get_configurable())
        for (const std::string& name : option->get_lnames()) names.push_back(name);
  return names;
}

}  // namespace

CLI::Validator configFileCheck() {
  return CLI::Validator(
      [](std::string& file) -> std::string {
        try {
          io::requireFlagFile(file);
        } catch (const InputError& e) {
          return e.what();
        }
        return {};
      },
      "FILE");
}

// ceilplan offers no flag that writes a config file (CLI11's config_to_str): nothing to format.
std::string YamlConfig::to_config(const CLI::App*, bool, bool, std::string) const { return {}; }

std::vector<CLI::ConfigItem> YamlConfig::from_config(std::istream& input) const {
  std::vector<std::string> parents;
  const CLI::App* command = root_;
  for (const CLI::App* chosen : root_->get_subcommands()) {
    parents.push_back(chosen->get_name());
    command = chosen;
  }
  const std::string command_name = command == root_ ? "" : command->get_name();
  std::vector<CLI::ConfigItem> items;
  try {
    for (io::FlagFileEntry& entry : io::readFlagFile(input, flagNames(*command), command_name)) {
      CLI::ConfigItem item;
      item.parents = parents;
      item.name = std::move(entry.flag);
      item.inputs = std::move(entry.values);
      items.push_back(std::move(item));
    }
  } catch (const InputError& e) {
    throw CLI::ConversionError(e.what());  // a usage error, as CLI11's own
  }
  return items;
}

}  // namespace ceilplan::app
