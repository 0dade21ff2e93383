#include "yaml_config.hpp"

#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/core/spelling.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <sstream>
#include <string>

namespace ceilplan::app {
namespace {

std::string flagName(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

// The long flag names `command` takes (and the main app's, which subcommands fall through to).
std::vector<std::string> flagNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::App* app = &command; app != nullptr; app = app->get_parent())
    for (const CLI::Option* option : app->get_options())
      if (option->get_configurable())
        for (const std::string& name : option->get_lnames()) names.push_back(name);
  return names;
}

// Keys must be flags of the chosen command: CLI11 would ignore the others, and a typo
// (`planer: lattice`) would silently run the default.
void requireFlag(const std::string& name, const YAML::Node& key, const std::vector<std::string>& known,
                 const std::string& command) {
  if (std::find(known.begin(), known.end(), name) != known.end()) return;
  throw CLI::ConversionError("config file line " + std::to_string(key.Mark().line + 1) + ": unknown key '" +
                             ceilplan::printableText(name, 40) + "'" + (command.empty() ? "" : " for '" + command + "'") +
                             ceilplan::didYouMean(name, known));
}

void collect(const YAML::Node& map, const std::vector<std::string>& parents, const std::vector<std::string>& known,
             const std::string& command, std::vector<CLI::ConfigItem>& items) {
  for (const auto& entry : map) {
    if (!entry.first.IsScalar())
      throw CLI::ConversionError("config file line " + std::to_string(entry.first.Mark().line + 1) +
                                 ": a key must be a flag name");
    const std::string name = flagName(entry.first.Scalar());  // known (printable) once requireFlag passes
    const YAML::Node& value = entry.second;
    if (value.IsMap() && !command.empty() && name == command) {
      collect(value, parents, known, command, items);  // a section named after the chosen command
      continue;
    }
    requireFlag(name, entry.first, known, command);
    if (value.IsMap()) throw CLI::ConversionError("config key '" + name + "' holds a map; give a value or a list");
    CLI::ConfigItem item;
    item.parents = parents;
    item.name = name;
    if (value.IsSequence()) {
      for (const auto& element : value) {
        if (!element.IsScalar())
          throw CLI::ConversionError("config key '" + name + "' holds a nested list; use a flat list");
        item.inputs.push_back(element.Scalar());
      }
    } else if (value.IsScalar()) {
      item.inputs.push_back(value.Scalar());
    } else {
      throw CLI::ConversionError("config key '" + name + "' has no value");
    }
    items.push_back(std::move(item));
  }
}

}  // namespace

std::string YamlConfig::to_config(const CLI::App* app, bool default_also, bool, std::string) const {
  YAML::Emitter out;
  out << YAML::BeginMap;
  for (const CLI::Option* option : app->get_options()) {
    if (option->get_lnames().empty() || !option->get_configurable()) continue;
    std::vector<std::string> values = option->reduced_results();
    if (values.empty() && default_also && !option->get_default_str().empty())
      values.push_back(option->get_default_str());
    if (values.empty()) continue;
    out << YAML::Key << option->get_lnames().front() << YAML::Value;
    if (values.size() == 1) {
      out << values.front();
    } else {
      out << YAML::Flow << values;
    }
  }
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

std::vector<CLI::ConfigItem> YamlConfig::from_config(std::istream& input) const {
  std::vector<CLI::ConfigItem> items;
  try {
    const YAML::Node root = YAML::Load(input);
    if (root.IsNull()) return items;
    if (!root.IsMap())
      throw CLI::ConversionError("config file must be a YAML map of flag names to values");
    std::vector<std::string> parents;
    const CLI::App* command = root_;
    for (const CLI::App* chosen : root_->get_subcommands()) {
      parents.push_back(chosen->get_name());
      command = chosen;
    }
    collect(root, parents, flagNames(*command), command == root_ ? "" : command->get_name(), items);
  } catch (const YAML::Exception& e) {
    std::ostringstream message;
    message << "malformed YAML config at line " << e.mark.line + 1 << ", column "
            << e.mark.column + 1 << ": " << e.msg;
    throw CLI::ConversionError(message.str());
  }
  return items;
}

}  // namespace ceilplan::app
