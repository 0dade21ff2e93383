#pragma once
// CLI11 validators for numeric flags: CLI11's own PositiveNumber and Range let NaN through,
// Range prints its bounds with std::to_string ("0.010000"), and an unsigned flag takes "-1" as
// 18446744073709551615.

#include "ceilplan/core/format.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <limits>
#include <string>

namespace ceilplan::app {

// A number that `accepts`; otherwise "must be <requirement>, got <input>". `name` is the help's.
inline CLI::Validator numberWhere(std::function<bool(double)> accepts, const std::string& requirement,
                                  const std::string& name) {
  return CLI::Validator(
      [accepts, requirement](std::string& input) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(input, value)) return "'" + input + "' is not a number";
        return accepts(value) ? std::string() : "must be " + requirement + ", got " + input;
      },
      name);
}

// A finite number >= `minimum` (or > `minimum` when `strict`).
inline CLI::Validator finiteAtLeast(double minimum, bool strict = false) {
  const std::string bound = std::string(strict ? "> " : ">= ") + CLI::detail::to_string(minimum);
  return numberWhere([minimum, strict](double v) { return std::isfinite(v) && (strict ? v > minimum : v >= minimum); },
                     "a finite number " + bound, "NUMBER " + bound);
}
inline CLI::Validator positiveFinite() { return finiteAtLeast(0.0, true); }
inline CLI::Validator nonNegativeFinite() { return finiteAtLeast(0.0); }

// A finite number in [minimum, maximum].
inline CLI::Validator finiteRange(double minimum, double maximum) {
  const std::string range = "[" + formatNumber(minimum) + ", " + formatNumber(maximum) + "]";
  return numberWhere([minimum, maximum](double v) { return std::isfinite(v) && v >= minimum && v <= maximum; },
                     "a finite number in " + range, "NUMBER in " + range);
}

// A number strictly between `low` and `high`.
inline CLI::Validator finiteBetween(double low, double high) {
  const std::string range = "(" + formatNumber(low) + ", " + formatNumber(high) + ")";
  return numberWhere([low, high](double v) { return v > low && v < high; }, "a number in " + range,
                     "NUMBER in " + range);
}

// At most `maximum`; NaN is left to the finiteness check it is combined with.
inline CLI::Validator atMost(double maximum) {
  return numberWhere([maximum](double v) { return !(v > maximum); }, "at most " + formatNumber(maximum),
                     "<= " + formatNumber(maximum));
}

// A state of charge as a fraction in (0, 1].
inline CLI::Validator socFraction() {
  return numberWhere([](double v) { return v > 0.0 && v <= 1.0; }, "a state of charge in (0, 1]", "SOC in (0, 1]");
}

// Digits only: a whole number >= 0 that fits a 64-bit unsigned flag (CLI11 would clamp 2^64 to
// 2^64 - 1 without a word); the flag's own range checks follow.
inline CLI::Validator wholeNumber() {
  return CLI::Validator(
      [](std::string& input) -> std::string {
        if (input.empty() || !std::all_of(input.begin(), input.end(), [](unsigned char c) { return std::isdigit(c); }))
          return "must be a whole number >= 0, got '" + input + "'";
        errno = 0;
        std::strtoull(input.c_str(), nullptr, 10);
        if (errno == ERANGE)
          return "must be a whole number in [0, " + std::to_string(std::numeric_limits<std::uint64_t>::max()) +
                 "], got " + input;
        return {};
      },
      "WHOLE NUMBER");
}

}  // namespace ceilplan::app
