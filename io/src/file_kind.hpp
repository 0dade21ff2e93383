#pragma once
// Telling file kinds apart by extension before a reader runs (private to the io module).

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/input_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace ceilplan::io::detail {

inline std::string lowerExtension(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
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

// Refuses (ceilplan::InputError naming the file) an extension of the other kind, one not in
// `accepted`, or a file that ceilplan::requireInputFile refuses; returns the lower-case extension.
// `kind` and `other_kind` name the kinds in messages ("mesh", "point-cloud").
template <typename List, typename OtherList>
std::string requireReadableFileOfKind(const std::filesystem::path& file, const List& accepted,
                                      const OtherList& other_kind_only, const std::string& kind,
                                      const std::string& other_kind) {
  const std::string name = file.string();
  const std::string extension = lowerExtension(file);
  if (listed(other_kind_only, extension))
    throw ceilplan::InputError(name + ": " + extension + " is a " + other_kind + " format, not a " + kind);
  if (!listed(accepted, extension))
    throw ceilplan::InputError(name + ": unknown " + kind + " format '" + extension + "' (read: " + joined(accepted) +
                               ")");
  requireInputFile(file, kind + " file");
  return extension;
}

}  // namespace ceilplan::io::detail
