#include "yaml_reader.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/input_file.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/core/printable_text.hpp"
#include "ceilplan/core/spelling.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace ceilplan::io::detail {
namespace {

// Keys that only a file of one kind has at its top level.
const std::vector<std::string>& signatureKeys(FileKind kind) {
  static const std::vector<std::string> mission{"map", "targets", "home", "surfaces", "contact_grid"};
  static const std::vector<std::string> vehicle{"rotors", "airframe", "clearance", "power", "mass_kg"};
  static const std::vector<std::string> battery{"capacity_ah", "charge_current_a", "state_of_health", "soc_min"};
  switch (kind) {
    case FileKind::Mission:
      return mission;
    case FileKind::Vehicle:
      return vehicle;
    case FileKind::Battery:
      return battery;
  }
  return mission;
}

// What a scalar says, for messages: escaped and cut (printableText), so a message never echoes
// terminal escapes or binary junk.
std::string shown(const YAML::Node& node) {
  if (!node.IsScalar()) return node.IsSequence() ? "a list" : node.IsMap() ? "a map" : "nothing";
  return "'" + printableText(node.Scalar(), 40) + "'";
}

}  // namespace

Range Range::finite(std::string unit) {
  return closed(std::numeric_limits<double>::lowest(), std::numeric_limits<double>::max(), std::move(unit));
}

bool Range::bounded() const {
  return min > std::numeric_limits<double>::lowest() || max < std::numeric_limits<double>::max();
}

bool Range::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (min_open ? value <= min : value < min) return false;
  if (max_open ? value >= max : value > max) return false;
  return true;
}

std::string Range::describe() const {
  return std::string(min_open ? "(" : "[") + formatNumber(min) + ", " + formatNumber(max) + (max_open ? ")" : "]") +
         (unit.empty() ? "" : " " + unit);
}

std::string kindName(FileKind kind) {
  switch (kind) {
    case FileKind::Mission:
      return "mission file";
    case FileKind::Vehicle:
      return "vehicle file";
    case FileKind::Battery:
      return "battery file";
  }
  return "file";
}

YamlText loadYamlText(const std::string& text) {
  YamlText loaded;
  loaded.first = YAML::Load(text);
  bool content = false, ended = false;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto marker = [&](const char* word) {
      return line.rfind(word, 0) == 0 && (line.size() == 3 || line[3] == ' ' || line[3] == '\t');
    };
    if (marker("---")) {
      if (content || ended || loaded.documents == 0) ++loaded.documents;
      content = ended = false;
      continue;
    }
    if (marker("...")) {
      ended = true;
      content = false;
      continue;
    }
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#' || (line[0] == '%' && !content)) continue;
    if (!content && (loaded.documents == 0 || ended)) ++loaded.documents;
    content = true;
    ended = false;
  }
  return loaded;
}

YamlFile::YamlFile(const std::filesystem::path& file, FileKind kind) : path_(file), kind_(kind) {
  // An empty file leaves `text` empty: refused below, as not a map.
  const std::string text = readInputFile(file, kindName(kind), kMaxYamlFileBytes);
  // A map or a program given by mistake: say so, rather than quote the parser on its bytes.
  if (text.find('\0') != std::string::npos) fail("holds binary data, not YAML text; is it a " + kindName(kind) + "?");
  YamlText loaded;
  try {
    loaded = loadYamlText(text);
  } catch (const YAML::Exception& e) {
    fail("malformed YAML at line " + std::to_string(e.mark.line + 1) + ": " + printableText(e.msg));
  }
  // yaml-cpp's Load reads the first document only: a second one would be ignored silently.
  if (loaded.documents > 1)
    fail("holds " + std::to_string(loaded.documents) + " YAML documents (split by '---'); a " + kindName(kind) +
         " is one document");
  root_ = loaded.first;
  if (!root_.IsMap()) fail("a " + kindName(kind) + " must be a YAML map of keys (" + docPage("missions.md") + ")");
}

void YamlFile::fail(const std::string& problem) const { throw InputError(path_.string() + ": " + problem); }

Section::Section(const YamlFile& file, const YAML::Node& node, std::string path)
    : file_(&file), node_(node), path_(std::move(path)) {
  if (!node_.IsMap()) fail("'" + path_ + "' must be a map of keys");
  // yaml-cpp keeps a repeated key and answers with its first value: refuse it, as a typo.
  std::vector<std::string> keys;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar())
      fail("'" + (path_.empty() ? std::string("the top level") : path_) + "' has a key that is not text");
    const std::string& key = entry.first.Scalar();
    if (std::find(keys.begin(), keys.end(), key) != keys.end())
      fail("key '" + keyPath(printableText(key, 40)) + "' is given twice");
    keys.push_back(key);
  }
}

std::string Section::keyPath(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

void Section::allowOnly(const std::vector<std::string>& known) const {
  std::vector<std::string> unknown;
  for (const auto& entry : node_) {
    const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
    if (std::find(known.begin(), known.end(), key) == known.end()) unknown.push_back(key);
  }
  if (unknown.empty()) return;
  if (path_.empty()) {
    for (FileKind other : {FileKind::Mission, FileKind::Vehicle, FileKind::Battery}) {
      if (other == file_->kind()) continue;
      const auto& signature = signatureKeys(other);
      const auto matches = std::count_if(unknown.begin(), unknown.end(), [&](const std::string& key) {
        return std::find(signature.begin(), signature.end(), key) != signature.end();
      });
      if (matches >= 2)
        fail("this is a " + kindName(other) + ", not a " + kindName(file_->kind()) + " (it has '" + unknown[0] +
             "'); give it where a " + kindName(other) + " is expected");
    }
  }
  fail("unknown key '" + keyPath(printableText(unknown.front(), 40)) + "'" + didYouMean(unknown.front(), known));
}

Section Section::section(const std::string& key) const {
  const YAML::Node node = required(key);
  if (!node.IsMap()) fail("'" + keyPath(key) + "' must be a map of keys");
  return Section(*file_, node, keyPath(key));
}

std::optional<Section> Section::optionalSection(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return section(key);
}

YAML::Node Section::required(const std::string& key) const {
  const YAML::Node node = node_[key];
  if (!node) fail("missing key '" + keyPath(key) + "'");
  return node;
}

double Section::numberAt(const YAML::Node& node, const std::string& path, const Range& range) const {
  const std::string within = range.bounded() ? " in " + range.describe() : "";
  double value = 0.0;
  if (!node.IsScalar()) fail("'" + path + "' must be a number" + within + ", got " + shown(node));
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    fail("'" + path + "' must be a number" + within + ", got " + shown(node));
  }
  if (!range.contains(value))
    fail("'" + path + "' must be " + (std::isfinite(value) ? "in " + range.describe() : "a finite number" + within) +
         ", got " + formatNumber(value));
  return value;
}

std::vector<double> Section::numbersAt(const YAML::Node& node, const std::string& path, std::size_t count,
                                       const Range& range) const {
  if (!node.IsSequence() || node.size() != count)
    fail("'" + path + "' must be a list of " + std::to_string(count) + " numbers, got " + shown(node));
  std::vector<double> values;
  for (std::size_t k = 0; k < count; ++k)
    values.push_back(numberAt(node[k], path + "[" + std::to_string(k) + "]", range));
  return values;
}

std::string Section::choiceAt(const YAML::Node& node, const std::string& path,
                              const std::vector<std::string>& choices) const {
  if (node.IsScalar() && std::find(choices.begin(), choices.end(), node.Scalar()) != choices.end())
    return node.Scalar();
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
  fail("'" + path + "' must be one of " + list + ", got " + shown(node) +
       (node.IsScalar() ? didYouMean(node.Scalar(), choices) : ""));
}

double Section::number(const std::string& key, const Range& range) const {
  return numberAt(required(key), keyPath(key), range);
}

double Section::number(const std::string& key, const Range& range, double fallback) const {
  return has(key) ? number(key, range) : fallback;
}

long long Section::integer(const std::string& key, long long min, long long max) const {
  const YAML::Node node = required(key);
  const std::string what = "'" + keyPath(key) + "' must be a whole number in [" + std::to_string(min) + ", " +
                           std::to_string(max) + "], got " + shown(node);
  if (!node.IsScalar()) fail(what);
  long long value = 0;
  try {
    value = node.as<long long>();
  } catch (const YAML::Exception&) {
    fail(what);
  }
  if (value < min || value > max) fail(what);
  return value;
}

long long Section::integer(const std::string& key, long long min, long long max, long long fallback) const {
  return has(key) ? integer(key, min, max) : fallback;
}

std::string Section::text(const std::string& key) const {
  const YAML::Node node = required(key);
  if (!node.IsScalar()) fail("'" + keyPath(key) + "' must be text, got " + shown(node));
  return node.Scalar();
}

std::string Section::text(const std::string& key, const std::string& fallback) const {
  return has(key) ? text(key) : fallback;
}

std::string Section::choice(const std::string& key, const std::vector<std::string>& choices,
                            const std::string& fallback) const {
  if (!has(key)) return fallback;
  text(key);  // a list or a map is "must be text"
  return choiceAt(node_[key], keyPath(key), choices);
}

YAML::Node Section::required(const std::string& key, const std::string& hint) const {
  const YAML::Node node = node_[key];
  if (!node) fail("missing key '" + keyPath(key) + "' (" + hint + ")");
  return node;
}

std::vector<double> Section::numbers(const std::string& key, std::size_t count, const Range& range) const {
  return numbersAt(required(key), keyPath(key), count, range);
}

Eigen::Vector3d Section::vector3(const std::string& key, const Range& range) const {
  const YAML::Node node = required(key);
  if (!node.IsSequence() || node.size() != 3)
    fail("'" + keyPath(key) + "' must be [x, y, z] in metres, got " + shown(node));
  const std::vector<double> xyz = numbers(key, 3, range);
  return {xyz[0], xyz[1], xyz[2]};
}

}  // namespace ceilplan::io::detail
