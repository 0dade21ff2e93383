#pragma once
// OMPL's asymptotically optimal planners by name. "lattice" (LatticePlanner) is not an OMPL
// planner and is handled by FlightPlanner.

#include "ceilplan/core/error.hpp"

#include <ompl/base/Planner.h>

#include <string>
#include <vector>

namespace ceilplan::planner {

// The names accepted by --planner, the default first.
const std::vector<std::string>& plannerNames();
const std::string& defaultPlannerName();

// Throws ceilplan::InputError for an unknown name (or "lattice"), listing the known ones.
ompl::base::PlannerPtr makeOmplPlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si);

}  // namespace ceilplan::planner
