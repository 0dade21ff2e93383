#pragma once
/// @file
/// Strict reading of YAML fields: every key known ("did you mean"), every number finite and in
/// its physical range, every error a ceilplan::InputError naming the key by its full path
/// (e.g. 'surfaces[0].overlap.front'). The file name is the caller's to add.

#include "ceilplan/io/point_text.hpp"

#include "ceilplan/core/error.hpp"

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace ceilplan::io {

/// The key of `valid` nearest to `key` by edit distance (insertions, deletions, substitutions
/// and swaps of neighbouring letters, case-insensitive); ties go to the first listed.
std::string nearestKey(const std::string& key, const std::vector<std::string>& valid);

/// Throws "'PATH' must be a map" unless `node` is a map, then "unknown key 'PATH.key' (did you
/// mean 'nearest'?)" for its first key not in `valid`. `path` is the map's own path ("" for
/// the top level).
void requireKnownKeys(const YAML::Node& node, const std::vector<std::string>& valid, const std::string& path);

/// "parent.key" (or "key" at the top level).
std::string keyPath(const std::string& parent, const std::string& key);

/// The child `key` of map `parent`, or "missing key 'PATH'" (with `what` explaining it, if given).
YAML::Node requiredKey(const YAML::Node& parent, const std::string& key, const std::string& parent_path,
                       const std::string& what = "");

/// A finite number in [lo, hi]: "'PATH' must be a number" / "must lie in [lo, hi] UNIT, got X".
double numberIn(const YAML::Node& node, const std::string& path, double lo, double hi, const std::string& unit);
/// A whole number in [lo, hi].
long integerIn(const YAML::Node& node, const std::string& path, long lo, long hi, const std::string& unit);
/// A non-empty string.
std::string text(const YAML::Node& node, const std::string& path);
/// [x, y, z], each finite and within `limit` in absolute value.
Eigen::Vector3d point3(const YAML::Node& node, const std::string& path, double limit = kMaxPointCoordinate_m);
/// A list of exactly `count` numbers, each finite and in [lo, hi].
std::vector<double> numbers(const YAML::Node& node, const std::string& path, std::size_t count, double lo, double hi,
                            const std::string& unit);

}  // namespace ceilplan::io
