#include "yaml_config.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <sstream>

namespace ceilplan::app {
namespace {

std::string flagName(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

void collect(const YAML::Node& map, std::vector<std::string> parents,
             std::vector<CLI::ConfigItem>& items) {
  for (const auto& entry : map) {
    const std::string name = flagName(entry.first.as<std::string>());
    const YAML::Node& value = entry.second;
    if (value.IsMap()) {
      auto nested = parents;
      nested.push_back(name);
      collect(value, nested, items);
      continue;
    }
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
    for (const CLI::App* chosen : root_->get_subcommands()) parents.push_back(chosen->get_name());
    collect(root, parents, items);
  } catch (const YAML::Exception& e) {
    std::ostringstream message;
    message << "malformed YAML config at line " << e.mark.line + 1 << ", column "
            << e.mark.column + 1 << ": " << e.msg;
    throw CLI::ConversionError(message.str());
  }
  return items;
}

}  // namespace ceilplan::app
