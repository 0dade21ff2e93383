#pragma once
// Writing OctoMap's binary (.bt) format.

#include <octomap/OcTree.h>

#include <ostream>

namespace ceilplan::io {

// Writes `tree` as a .bt file (maximum-likelihood free/occupied) to `out`. OctoMap's own
// header is written here because its writeBinary prints debug chatter on stderr in Debian's
// build. Throws ceilplan::Error if the stream fails.
void writeOctoMapBinary(const octomap::OcTree& tree, std::ostream& out);

}  // namespace ceilplan::io
