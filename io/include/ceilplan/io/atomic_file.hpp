#pragma once
/// @file
/// Output files appear whole or not at all: each is written under a temporary name beside its
/// final one, then renamed into place.

#include <filesystem>
#include <functional>
#include <ostream>

namespace ceilplan::io {

/// Calls `write` with a temporary path in the same directory, then renames it to `path`.
/// Checks `path` first (checkOutputs: ceilplan::InputError) and creates the parent
/// directory. On any other failure the temporary file is removed and the error (ceilplan::Error)
/// names `path` and the reason.
void writeAtomically(const std::filesystem::path& path,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

/// Same, for text produced on a stream.
void writeTextAtomically(const std::filesystem::path& path, const std::function<void(std::ostream& out)>& write);

}  // namespace ceilplan::io
