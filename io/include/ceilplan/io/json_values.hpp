#pragma once
/// @file
/// JSON values and files. JSON has no infinity: an infinite gap or clearance ("no surface") is
/// written as null.

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <string>

namespace ceilplan::io {

/// `value` as JSON, or null when it is not finite (JSON has no NaN or infinity).
inline nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

/// The one way ceilplan turns JSON into text (indent -1: one line). Strings from the user (file
/// names, target names) may hold bytes that are not UTF-8, which nlohmann::json refuses to dump:
/// each such byte becomes U+FFFD, so an output is never lost to a name after the work is done.
std::string jsonText(const nlohmann::json& json, int indent = -1);
/// The same for an ordered JSON document.
std::string jsonText(const nlohmann::ordered_json& json, int indent = -1);

/// Writes `json` indented by 2, with a final newline, atomically (writeTextAtomically).
void writeJsonFile(const std::filesystem::path& file, const nlohmann::json& json);
/// The same for an ordered JSON document.
void writeJsonFile(const std::filesystem::path& file, const nlohmann::ordered_json& json);

}  // namespace ceilplan::io
