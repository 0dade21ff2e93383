#pragma once
// JSON numbers written straight into text, for files of many numbers (trajectory.json, the
// report's data) that are not first made a document.

#include <nlohmann/json.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <string>

namespace ceilplan::io {

/// Appends what jsonText writes for the number `value`: null where it is not finite, else
/// nlohmann's own shortest text that reads back as `value`.
inline void appendJsonNumber(std::string& text, double value) {
  if (!std::isfinite(value)) {
    text += "null";
    return;
  }
  std::array<char, 64> buffer{};
  text.append(buffer.data(), nlohmann::detail::to_chars(buffer.data(), buffer.data() + buffer.size(), value));
}

/// Appends what jsonText writes for the integer `value`.
inline void appendJsonNumber(std::string& text, long value) {
  std::array<char, 24> buffer{};
  text.append(buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr);
}

}  // namespace ceilplan::io
