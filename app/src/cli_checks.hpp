#pragma once
// CLI11 validators for numeric flags: CLI11's own PositiveNumber and Range let NaN through,
// Range prints its bounds with std::to_string ("0.010000"), and an unsigned flag takes "-1" as
// 18446744073709551615.

#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>

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

// A finite number in [minimum, maximum].
inline CLI::Validator finiteRange(double minimum, double maximum) {
  const std::string range = "[" + formatNumber(minimum) + ", " + formatNumber(maximum) + "]";
  return CLI::Validator(
      [minimum, maximum, range](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        if (!(std::isfinite(value) && value >= minimum && value <= maximum))
          return "must be a finite number in " + range + ", got " + input;
        return {};
      },
      "NUMBER in " + range);
}

// Digits only: a whole number >= 0, for unsigned flags (their own range checks follow).
inline CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        if (input.empty() || !std::all_of(input.begin(), input.end(), [](unsigned char c) { return std::isdigit(c); }))
          return "must be a whole number >= 0, got '" + input + "'";
        return {};
      },
      "WHOLE NUMBER");
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
