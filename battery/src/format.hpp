#pragma once
// Numbers in error messages: shortest readable form ("5.2", "nan", "-0.3"), not std::to_string's "5.200000".

#include <sstream>
#include <string>

namespace ceilplan::battery::detail {

inline std::string number(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace ceilplan::battery::detail
