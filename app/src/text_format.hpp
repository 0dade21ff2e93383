#pragma once
// Numbers in tables and messages.

#include <iomanip>
#include <sstream>
#include <string>

namespace ceilplan::app {

// At most `significant` significant digits, no trailing zeros: "5.2", "0.009655", "nan".
inline std::string shortNumber(double value, int significant = 6) {
  std::ostringstream text;
  text << std::setprecision(significant) << value;
  return text.str();
}

// Exactly `decimals` decimals: fixed(43.5, 2) == "43.50".
inline std::string fixed(double value, int decimals) {
  std::ostringstream text;
  text << std::fixed << std::setprecision(decimals) << value;
  return text.str();
}

}  // namespace ceilplan::app
