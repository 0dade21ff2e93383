#pragma once
/// @file
/// The deterministic reference, as an OMPL planner ("lattice"): A* over a lattice of voxel
/// centres (LatticeSettings::spacing_m apart, 26-connected) with exactly the problem's objective
/// (a FlightObjective; lattice motions sample the cost model's step lattice, whose map conditions are
/// cached) and the admissible, consistent heuristic c_min x distance, under the space's
/// validity checker (FlightStateValidityChecker). Optimal over the lattice; the quality oracle.
/// Start and goal join the lattice nodes within sqrt(3) spacings.
///
/// Where the lattice misses a passage, it refines: between the regions the start and the goal
/// reach on the lattice it searches a fine lattice (half a voxel) around their closest points,
/// and plans again with that passage as one more edge (the route is then the cheapest through
/// it). When there is none, blockage() says where and by which rule the way is blocked.

#include "ceilplan/planner/lattice_planner_base.hpp"

#include <cstddef>

namespace ceilplan::planner {

/// ceilplan's lattice A*: the cheapest path over a lattice of valid nodes, deterministic, one query at a time (planner
/// name "lattice").
class LatticePlanner : public LatticePlannerBase {
 public:
  /// Throws ceilplan::InputError for bad settings.
  explicit LatticePlanner(const ompl::base::SpaceInformationPtr& si, LatticeSettings settings = {});

  /// Needs a FlightObjective, a FlightStateValidityChecker and a GoalState. EXACT_SOLUTION with
  /// the cheapest lattice path; TIMEOUT when `ptc` or the expansion limit stopped the search;
  /// ABORT when no path exists on the lattice and its refinement (then blockage() is set).
  ompl::base::PlannerStatus solve(const ompl::base::PlannerTerminationCondition& ptc) override;
  using ompl::base::Planner::solve;
  /// OMPL: forgets the last search.
  void clear() override;
  /// OMPL: the last path found, as planner data.
  void getPlannerData(ompl::base::PlannerData& data) const override;

  /// Nodes the last search expanded.
  std::size_t expansions() const { return expansions_; }

 private:
  std::size_t expansions_ = 0;
};

}  // namespace ceilplan::planner
