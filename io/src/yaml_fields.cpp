#include "ceilplan/io/yaml_fields.hpp"

#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace ceilplan::io {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

// Optimal string alignment distance (Levenshtein with transpositions of neighbours).
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

// Keys as the user wrote them, made printable (control bytes escaped).
std::string printable(const std::string& text) {
  std::string out;
  for (const unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      static const char* digits = "0123456789abcdef";
      out += "\\x";
      out += digits[c >> 4];
      out += digits[c & 15];
    }
  }
  return out;
}

}  // namespace

std::string nearestKey(const std::string& key, const std::vector<std::string>& valid) {
  std::string best;
  std::size_t best_distance = static_cast<std::size_t>(-1);
  const std::string wanted = lower(key);
  for (const std::string& candidate : valid) {
    const std::size_t distance = editDistance(wanted, lower(candidate));
    if (distance < best_distance) {
      best_distance = distance;
      best = candidate;
    }
  }
  return best;
}

std::string keyPath(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

void requireKnownKeys(const YAML::Node& node, const std::vector<std::string>& valid, const std::string& path) {
  if (!node.IsMap()) throw ceilplan::InputError("'" + path + "' must be a map");
  for (const auto& entry : node) {
    std::string key;
    try {
      key = entry.first.as<std::string>();
    } catch (const YAML::Exception&) {
      throw ceilplan::InputError("'" + path + "' has a key that is not a name");
    }
    if (std::find(valid.begin(), valid.end(), key) == valid.end())
      throw ceilplan::InputError("unknown key '" + printable(keyPath(path, key)) + "' (did you mean '" +
                                 keyPath(path, nearestKey(key, valid)) + "'?)");
  }
}

YAML::Node requiredKey(const YAML::Node& parent, const std::string& key, const std::string& parent_path,
                       const std::string& what) {
  const YAML::Node node = parent[key];
  if (!node)
    throw ceilplan::InputError("missing key '" + keyPath(parent_path, key) + "'" +
                               (what.empty() ? "" : " (" + what + ")"));
  return node;
}

double numberIn(const YAML::Node& node, const std::string& path, double lo, double hi, const std::string& unit) {
  double value = 0.0;
  if (!node.IsScalar()) throw ceilplan::InputError("'" + path + "' must be a number");
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    throw ceilplan::InputError("'" + path + "' must be a number, got '" + printable(node.Scalar()) + "'");
  }
  if (!std::isfinite(value))
    throw ceilplan::InputError("'" + path + "' must be a finite number, got " + formatNumber(value));
  if (value < lo || value > hi)
    throw ceilplan::InputError("'" + path + "' must lie in [" + formatNumber(lo) + ", " + formatNumber(hi) + "]" +
                               (unit.empty() ? "" : " " + unit) + ", got " + formatNumber(value));
  return value;
}

long integerIn(const YAML::Node& node, const std::string& path, long lo, long hi, const std::string& unit) {
  long value = 0;
  if (!node.IsScalar()) throw ceilplan::InputError("'" + path + "' must be a whole number");
  try {
    value = node.as<long>();
  } catch (const YAML::Exception&) {
    throw ceilplan::InputError("'" + path + "' must be a whole number, got '" + printable(node.Scalar()) + "'");
  }
  if (value < lo || value > hi)
    throw ceilplan::InputError("'" + path + "' must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]" +
                               (unit.empty() ? "" : " " + unit) + ", got " + std::to_string(value));
  return value;
}

std::string text(const YAML::Node& node, const std::string& path) {
  if (!node.IsScalar() || node.Scalar().empty())
    throw ceilplan::InputError("'" + path + "' must be a non-empty string");
  return node.Scalar();
}

Eigen::Vector3d point3(const YAML::Node& node, const std::string& path, double limit) {
  const std::vector<double> values = numbers(node, path, 3, -limit, limit, "m");
  return {values[0], values[1], values[2]};
}

std::vector<double> numbers(const YAML::Node& node, const std::string& path, std::size_t count, double lo, double hi,
                            const std::string& unit) {
  if (!node.IsSequence() || node.size() != count)
    throw ceilplan::InputError("'" + path + "' must be a list of " + std::to_string(count) + " numbers");
  std::vector<double> values;
  for (std::size_t k = 0; k < count; ++k)
    values.push_back(numberIn(node[k], path + "[" + std::to_string(k) + "]", lo, hi, unit));
  return values;
}

}  // namespace ceilplan::io
