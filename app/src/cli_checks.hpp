#pragma once
// CLI11 validators for numeric flags: CLI11's own PositiveNumber lets NaN through.

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace ceilplan::app {

// A finite number >= `minimum` (or > `minimum` when `strict`).
inline CLI::Validator finiteAtLeast(double minimum, bool strict = false) {
  const std::string description = std::string(strict ? "> " : ">= ") + CLI::detail::to_string(minimum);
  return CLI::Validator(
      [minimum, strict, description](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if (!std::isfinite(value) || value < minimum || (strict && value == minimum))
          return "must be a finite number " + description + ", got " + input;
        return {};
      },
      "NUMBER " + description);
}

inline CLI::Validator positiveFinite() { return finiteAtLeast(0.0, true); }
inline CLI::Validator nonNegativeFinite() { return finiteAtLeast(0.0); }

// A state of charge as a fraction in (0, 1].
inline CLI::Validator socFraction() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if (!(value > 0.0 && value <= 1.0)) return "must be a state of charge in (0, 1], got " + input;
        return {};
      },
      "SOC in (0, 1]");
}

}  // namespace ceilplan::app
