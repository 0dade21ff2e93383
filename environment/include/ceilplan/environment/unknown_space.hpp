#pragma once
/// @file
/// What the planner may assume about the voxels a map does not know (docs/environment.md,
/// "Unknown space"). One policy for validity, clearance and the ceiling and ground gaps.

#include <optional>
#include <string>

namespace ceilplan::environment {

/// What a map's unknown voxels count as (docs/environment.md).
enum class UnknownPolicy {
  Occupied,  ///< unknown space is an obstacle (the safe default)
  Free,      ///< every unknown voxel inside the map's box is free air
  Fill,      ///< small unknown pockets inside known free space are free air; the rest is an obstacle
};

/// The unknown-space policy with its fill size: what every command takes as `--unknown`.
struct UnknownSpace {
  /// Fill's default: the under-scanned pockets of an indoor scan (up to about 2 m in geb079's
  /// corridor), not a room.
  static constexpr double kDefaultFillMax_m = 2.0;
  /// The largest fill a mission file takes (io/): far beyond any pocket, a slip of the exponent is refused.
  static constexpr double kMaxFill_m = 1000.0;

  UnknownPolicy policy = UnknownPolicy::Occupied;  ///< what unknown voxels count as
  /// Fill only: a connected unknown region counts as free air when it borders known free space,
  /// does not reach the box of the map's known voxels, and its size (the longest edge of its
  /// axis-aligned bounding box, between voxel faces) is at most this many metres.
  double fill_max_m = kDefaultFillMax_m;

  /// Throws ceilplan::InputError when fill_max_m is not in (0, kMaxFill_m].
  void validate() const;
  /// "occupied", "free", or "fill (pockets up to 1 m)".
  std::string describe() const;

  /// Equal policies (fill_max_m compared under fill only).
  bool operator==(const UnknownSpace& other) const {
    return policy == other.policy && (policy != UnknownPolicy::Fill || fill_max_m == other.fill_max_m);
  }
  /// Different policies.
  bool operator!=(const UnknownSpace& other) const { return !(*this == other); }
};

/// "occupied", "free", "fill"; unknownPolicyFromName throws ceilplan::InputError for any other
/// name, listing the valid ones.
UnknownPolicy unknownPolicyFromName(const std::string& name);
/// The policy's name: "occupied", "free" or "fill".
std::string unknownPolicyName(UnknownPolicy policy);

/// How a front end spells the policy and the fill size, for messages: the command line's
/// "--unknown" and "--unknown-fill-max-m", a mission file's "'unknown.policy'" and
/// "'unknown.fill_max_m'", Python's "unknown" and "unknown_fill_max_m".
struct UnknownSpaceKeys {
  std::string policy;    ///< the policy's name in messages
  std::string fill_max;  ///< the fill size's name in messages
};

/// The policy named `policy` with fill's largest pocket, `fill_max_m` when given: the one reading
/// of the setting, which the mission file, the command line and Python share. Throws
/// ceilplan::InputError for a name that is not a policy, a fill size without the fill policy, or
/// a fill size out of (0, kMaxFill_m].
UnknownSpace parseUnknownSpace(const std::string& policy, std::optional<double> fill_max_m,
                               const UnknownSpaceKeys& keys);

}  // namespace ceilplan::environment
