#include "ceilplan/io/flag_file.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/input_file.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/core/spelling.hpp"

#include "yaml_reader.hpp"

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

// A flag and the line of the key that gave it.
struct Given {
  std::string flag;
  int line;
};

void collect(const YAML::Node& map, const std::vector<std::string>& known, const std::string& command,
             std::vector<FlagFileEntry>& entries, std::vector<Given>& given) {
  for (const auto& entry : map) {
    const int line = entry.first.Mark().line + 1;
    if (!entry.first.IsScalar())
      throw InputError("config file line " + std::to_string(line) + ": a key must be a flag name");
    const std::string name = flagName(entry.first.Scalar());  // known (printable) once requireFlag passes
    const YAML::Node& value = entry.second;
    if (value.IsMap() && !command.empty() && name == command) {
      collect(value, known, command, entries, given);  // a section named after the chosen command
      continue;
    }
    requireFlag(name, entry.first, known, command);
    // yaml-cpp keeps both of a repeated key, and CLI11 would let the last one win; 'time-limit-s' and
    // 'time_limit_s' are one flag. Either way one value would be dropped without a word.
    const auto earlier = std::find_if(given.begin(), given.end(), [&](const Given& g) { return g.flag == name; });
    if (earlier != given.end())
      throw InputError("config file line " + std::to_string(line) + ": '" + printableText(entry.first.Scalar(), 40) +
                       "' gives flag '" + name + "' again (first on line " + std::to_string(earlier->line) +
                       "); give each flag once, a list for a repeated flag");
    given.push_back({name, line});
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

void requireFlagFile(const std::filesystem::path& file) {
  requireInputFile(file, "config file", detail::kMaxYamlFileBytes);
}

std::vector<FlagFileEntry> readFlagFile(std::istream& input, const std::vector<std::string>& known_flags,
                                        const std::string& command) {
  std::vector<FlagFileEntry> entries;
  try {
    std::ostringstream text;
    text << input.rdbuf();
    const detail::YamlText loaded = detail::loadYamlText(text.str());
    // yaml-cpp's Load reads the first document only: a second one would be ignored silently.
    if (loaded.documents > 1)
      throw InputError("config file holds " + std::to_string(loaded.documents) +
                       " YAML documents (split by '---'); give one map of flag names to values");
    // Only a file of comments is empty: text that yaml-cpp reads as nothing is not a map.
    if (loaded.first.IsNull() && loaded.documents == 0) return entries;
    const YAML::Node& root = loaded.first;
    if (!root.IsMap()) throw InputError("config file must be a YAML map of flag names to values");
    std::vector<Given> given;
    collect(root, known_flags, command, entries, given);
  } catch (const YAML::Exception& e) {
    std::ostringstream message;
    message << "malformed YAML config at line " << e.mark.line + 1 << ", column " << e.mark.column + 1 << ": " << e.msg;
    throw InputError(message.str());
  }
  return entries;
}

}  // namespace ceilplan::io
