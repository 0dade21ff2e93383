#pragma once
// Telling file kinds apart by extension before a reader runs (private to the io module).

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace ceilplan::io::detail {

inline std::string lowerExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension;
}

template <typename List>
bool listed(const List& extensions, const std::string& extension) {
  return std::find(std::begin(extensions), std::end(extensions), extension) != std::end(extensions);
}

template <typename List>
std::string joined(const List& extensions) {
  std::string text;
  for (const std::string extension : extensions) text += (text.empty() ? "" : ", ") + extension;
  return text;
}

}  // namespace ceilplan::io::detail
