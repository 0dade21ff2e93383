#pragma once
/// @file
/// An OctoMap occupancy tree loaded from a .bt or .ot file, checked before OctoMap parses it,
/// so a damaged file gives one clear error instead of a crash or a half-read tree.

#include "ceilplan/core/error.hpp"

#include <octomap/OcTree.h>

#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <string>

namespace ceilplan::environment {

/// An OctoMap occupancy tree as loaded, with its name for messages.
class OccupancyMap {
 public:
  /// Reads a .bt (binary) or .ot (full) OctoMap file; the format is taken from the file's
  /// first line, not its name. Other occupancy trees (ColorOcTree, OcTreeStamped) are converted
  /// to their occupancy: the same nodes and log-odds, without colours or stamps. Throws
  /// ceilplan::InputError naming the file and the problem: missing, unreadable, not an OctoMap,
  /// truncated or corrupt, a .ot of a tree type ceilplan cannot read, or a map with no known voxel.
  /// A directory, FIFO or device is refused before it is opened, and a file larger than
  /// kMaxFileBytes before it is read.
  static OccupancyMap load(const std::filesystem::path& file);

  /// The largest map file read: ceilplan indexes at most VoxelGrid::kMaxVoxels voxels at about
  /// 5 bytes each (2 GB), and a larger file is not a map it could index.
  static constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{2} << 30;

  /// Same, from bytes already in memory; `name` appears in error messages.
  static OccupancyMap read(std::istream& in, const std::string& name);

  /// Wraps a tree built in memory (tests, scene generation). Throws if it has no known voxel.
  OccupancyMap(std::unique_ptr<octomap::OcTree> tree, std::string name);

  /// The OctoMap tree.
  const octomap::OcTree& tree() const { return *tree_; }
  /// Voxel size, m.
  double resolution_m() const { return tree_->getResolution(); }
  /// The map's name (its file) for messages.
  const std::string& name() const { return name_; }

 private:
  static OccupancyMap parse(const std::string& bytes, const std::string& name);

  std::shared_ptr<const octomap::OcTree> tree_;
  std::string name_;
};

}  // namespace ceilplan::environment
