#pragma once
// PLY element counts checked against the data (private to the io module): Open3D reads as many
// vertices and faces as the header says and drops or runs out of the rest without a word.

#include <filesystem>

namespace ceilplan::io::detail {

// Throws ceilplan::InputError naming the file when an ascii PLY's data lines, or a binary PLY's
// bytes (when its elements have no list properties), differ from what the header's
// `element NAME COUNT` lines promise, or when the header is unreadable. Other files pass.
void checkPlyCounts(const std::filesystem::path& file);

}  // namespace ceilplan::io::detail
