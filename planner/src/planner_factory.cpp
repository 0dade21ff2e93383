#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/core/error.hpp"

#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <stdexcept>

namespace ceilplan::planner {

const std::vector<std::string>& plannerNames() {
  static const std::vector<std::string> names{"BITstar", "AITstar", "RRTstar", "InformedRRTstar",
                                              "PRMstar", "LazyPRMstar", "lattice"};
  return names;
}

const std::string& defaultPlannerName() { return plannerNames().front(); }

ompl::base::PlannerPtr makeOmplPlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si) {
  namespace og = ompl::geometric;
  if (name == "RRTstar") return std::make_shared<og::RRTstar>(si);
  // InformedRRTstar bounds cost-to-come with motionCostHeuristic (c_min x distance, admissible
  // for our objectives), never with the straight-line motion cost, so its pruning is safe here.
  if (name == "InformedRRTstar") return std::make_shared<og::InformedRRTstar>(si);
  if (name == "BITstar") return std::make_shared<og::BITstar>(si, "kBITstar");  // k-nearest BIT*, under its own name
  if (name == "AITstar") return std::make_shared<og::AITstar>(si);
  if (name == "PRMstar") return std::make_shared<og::PRMstar>(si);
  if (name == "LazyPRMstar") return std::make_shared<og::LazyPRMstar>(si);
  std::string known;
  for (const std::string& n : plannerNames()) known += (known.empty() ? "" : ", ") + n;
  throw ceilplan::InputError("unknown planner '" + name + "': choose one of " + known);
}

}  // namespace ceilplan::planner
