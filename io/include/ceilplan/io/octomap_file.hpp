#pragma once
/// @file
/// Writing OctoMap files: the binary (.bt) format and OctoMap's full (.ot) format.

#include <octomap/OcTree.h>

#include <filesystem>
#include <ostream>

namespace ceilplan::io {

/// Writes `tree` as a .bt file (maximum-likelihood free/occupied) to `out`. OctoMap's own
/// header is written here because its writeBinary prints debug chatter on stderr in Debian's
/// build. Throws ceilplan::Error naming `file` (the final name of what `out` writes) if the
/// stream fails.
void writeOctoMapBinary(const octomap::OcTree& tree, std::ostream& out, const std::filesystem::path& file);

/// True for a file name ending in .bt or .ot, the two formats writeOctoMapFile writes.
bool isOctoMapFileName(const std::filesystem::path& file);

/// Writes `tree` to `file` atomically (io::writeAtomically): .bt as writeOctoMapBinary, .ot in
/// OctoMap's full format (occupancy probabilities kept). Throws ceilplan::InputError for another
/// extension and ceilplan::Error naming the file if writing fails.
void writeOctoMapFile(const std::filesystem::path& file, const octomap::OcTree& tree);

}  // namespace ceilplan::io
