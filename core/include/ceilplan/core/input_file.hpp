#pragma once
/// @file
/// The one check every reader makes before it opens a user's input file (maps, mission, vehicle,
/// battery and --config files, CSVs, point clouds, meshes): a FIFO would block the reader for
/// ever, a device such as /dev/zero would never end, and a file larger than its reader's bound
/// would be read whole before failing.

#include <cstdint>
#include <filesystem>
#include <string>

namespace ceilplan {

/// The bound of readers that state none of their own (CSVs, point clouds, meshes): 4 GiB.
inline constexpr std::uintmax_t kMaxInputFileBytes = std::uintmax_t{4} << 30;

/// Checks that `file` exists, is a regular file (or a link to one), can be opened for reading
/// and holds at most `max_bytes`; returns its size in bytes. Otherwise throws
/// ceilplan::InputError "FILE: problem" in one line, `what` naming the kind of file expected
/// ("map file"), e.g. "FILE: is a FIFO (named pipe), not a map file; give a regular file".
std::uintmax_t requireInputFile(const std::filesystem::path& file, const std::string& what,
                                std::uintmax_t max_bytes = kMaxInputFileBytes);

/// The file's bytes, after requireInputFile's checks.
std::string readInputFile(const std::filesystem::path& file, const std::string& what,
                          std::uintmax_t max_bytes = kMaxInputFileBytes);

}  // namespace ceilplan
