#pragma once
// JSON has no infinity: an infinite gap or clearance ("no surface") is written as null.

#include <nlohmann/json.hpp>

#include <cmath>

namespace ceilplan::io {

inline nlohmann::json finiteOrNull(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace ceilplan::io
