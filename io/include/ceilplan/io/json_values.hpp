#pragma once
// JSON values and files. JSON has no infinity: an infinite gap or clearance ("no surface") is
// written as null.

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

namespace ceilplan::io {

inline nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

// Writes `json` indented by 2, with a final newline, atomically (writeTextAtomically).
void writeJsonFile(const std::filesystem::path& file, const nlohmann::json& json);
void writeJsonFile(const std::filesystem::path& file, const nlohmann::ordered_json& json);

}  // namespace ceilplan::io
