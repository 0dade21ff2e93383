#include "ceilplan/io/flag_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/core/spelling.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <sstream>

namespace ceilplan::io {
namespace {

std::string flagName(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

void requireFlag(const std::string& name, const YAML::Node& key, const std::vector<std::string>& known,
                 const std::string& command) {
  if (std::find(known.begin(), known.end(), name) != known.end()) return;
  throw InputError("config file line " + std::to_string(key.Mark().line + 1) + ": unknown key '" +
                   printableText(name, 40) + "'" + (command.empty() ? "" : " for '" + command + "'") +
                   didYouMean(name, known));
}

void collect(const YAML::Node& map, const std::vector<std::string>& known, const std::string& command,
             std::vector<FlagFileEntry>& entries) {
  for (const auto& entry : map) {
    if (!entry.first.IsScalar())
      throw InputError("config file line " + std::to_string(entry.first.Mark().line + 1) +
                       ": a key must be a flag name");
    const std::string name = flagName(entry.first.Scalar());  // known (printable) once requireFlag passes
    const YAML::Node& value = entry.second;
    if (value.IsMap() && !command.empty() && name == command) {
      collect(value, known, command, entries);  // a section named after the chosen command
      continue;
    }
    requireFlag(name, entry.first, known, command);
    if (value.IsMap()) throw InputError("config key '" + name + "' holds a map; give a value or a list");
    FlagFileEntry flag{name, {}};
    if (value.IsSequence()) {
      for (const auto& element : value) {
        if (!element.IsScalar()) throw InputError("config key '" + name + "' holds a nested list; use a flat list");
        flag.values.push_back(element.Scalar());
      }
    } else if (value.IsScalar()) {
      flag.values.push_back(value.Scalar());
    } else {
      throw InputError("config key '" + name + "' has no value");
    }
    entries.push_back(std::move(flag));
  }
}

}  // namespace

std::vector<FlagFileEntry> readFlagFile(std::istream& input, const std::vector<std::string>& known_flags,
                                        const std::string& command) {
  std::vector<FlagFileEntry> entries;
  try {
    const YAML::Node root = YAML::Load(input);
    if (root.IsNull()) return entries;
    if (!root.IsMap()) throw InputError("config file must be a YAML map of flag names to values");
    collect(root, known_flags, command, entries);
  } catch (const YAML::Exception& e) {
    std::ostringstream message;
    message << "malformed YAML config at line " << e.mark.line + 1 << ", column " << e.mark.column + 1 << ": " << e.msg;
    throw InputError(message.str());
  }
  return entries;
}

}  // namespace ceilplan::io
