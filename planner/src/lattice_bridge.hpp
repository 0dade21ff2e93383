#pragma once
// Refinement where the coarse lattice misses a passage: between two regions the coarse lattice
// reaches (from the start, from the goal; or two parts of a roadmap), a search on a fine
// lattice (half a voxel: every voxel centre and face, where the middle of any gap between voxel
// faces lies) inside a box around the pairs of points closest to each other. When no pair is
// joined, the most open gap tried says where and why the way is blocked.

#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/planner/blockage.hpp"
#include "ceilplan/planner/safety_rules.hpp"

#include <ompl/base/PlannerTerminationCondition.h>
#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <vector>

namespace ceilplan::planner::detail {

struct BridgeOutcome {
  // From side_a[from] to side_b[to], turning points only; empty when none was found.
  std::vector<Eigen::Vector3d> waypoints;
  std::size_t from = 0, to = 0;
  std::optional<Blockage> blockage;  // without a bridge: the most open gap tried
};

// Pairs each point of one side with the nearest of the other and tries a few pairs, the most
// open straight way between them first (then the closest), at least a metre apart: a fine
// search within a metre (at least the vehicle's width) of the pair's straight way. Then, from
// the closest pair, the same fine search within 2, 4, 8, ... m of their way, until its box
// holds the map or 8 million nodes. `ptc` may stop it early (then neither a bridge nor a
// blockage).
BridgeOutcome findBridge(const SafetyRules& rules, const std::vector<Eigen::Vector3d>& side_a,
                         const std::vector<Eigen::Vector3d>& side_b,
                         const ompl::base::PlannerTerminationCondition& ptc);

// Why the straight way from `from_m` (valid) to `to_m` is blocked: its most open invalid state,
// the rule it breaks and the opening across the way there.
Blockage diagnoseBlockage(const SafetyRules& rules, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m);

// When no voxel that is not occupied joins the start to the goal, whatever the vehicle's size
// (one of them is walled in on every side, unknown voxels counted open): names that end in
// `blockage`, with the box of its pocket, since no gap between the two sides exists to name.
// Two floods, one from each end, step in turn: the first to run dry is the enclosed one.
void nameEnclosedEnd(Blockage& blockage, const environment::VoxelGrid& grid, const Eigen::Vector3d& start_m,
                     const Eigen::Vector3d& goal_m);

// Drops repeated points and the inner points of straight runs.
std::vector<Eigen::Vector3d> turningPoints(const std::vector<Eigen::Vector3d>& points);

}  // namespace ceilplan::planner::detail
