#include "ceilplan/planner/planner_factory.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/lattice_planner.hpp"
#include "ceilplan/planner/lattice_roadmap.hpp"

#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/prm/LazyPRMstar.h>
#include <ompl/geometric/planners/prm/PRMstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTstar.h>

#include <algorithm>

namespace ceilplan::planner {
namespace {

namespace ob = ompl::base;
namespace og = ompl::geometric;

struct Entry {
  PlannerInfo info;
  ob::PlannerPtr (*make)(const ob::SpaceInformationPtr& si, const LatticeSettings& lattice);
};

template <typename OmplPlanner>
ob::PlannerPtr omplPlanner(const ob::SpaceInformationPtr& si, const LatticeSettings&) {
  return std::make_shared<OmplPlanner>(si);
}

// The one list of planners, the default for single queries first.
const std::vector<Entry>& entries() {
  static const std::vector<Entry> list{
      // k-nearest BIT*, logged under its own name.
      {{"BITstar", PlannerKind::Sampling, "Batch Informed Trees (k-nearest), the default"},
       [](const ob::SpaceInformationPtr& si, const LatticeSettings&) -> ob::PlannerPtr {
         return std::make_shared<og::BITstar>(si, "kBITstar");
       }},
      {{"AITstar", PlannerKind::Sampling, "Adaptively Informed Trees"}, &omplPlanner<og::AITstar>},
      {{"RRTstar", PlannerKind::Sampling, "optimal RRT"}, &omplPlanner<og::RRTstar>},
      // InformedRRTstar bounds cost-to-come with motionCostHeuristic (c_min x distance,
      // admissible for our objectives), never with the straight-line motion cost, so its
      // pruning is safe here.
      {{"InformedRRTstar", PlannerKind::Sampling, "RRT* with informed sampling"}, &omplPlanner<og::InformedRRTstar>},
      {{"PRMstar", PlannerKind::Sampling, "optimal probabilistic roadmap"}, &omplPlanner<og::PRMstar>},
      {{"LazyPRMstar", PlannerKind::Sampling, "PRM* checking edges lazily"}, &omplPlanner<og::LazyPRMstar>},
      {{"lattice", PlannerKind::Lattice, "A* over a lattice of voxel centres: deterministic, optimal on its lattice"},
       [](const ob::SpaceInformationPtr& si, const LatticeSettings& lattice) -> ob::PlannerPtr {
         return std::make_shared<LatticePlanner>(si, lattice);
       }},
      {{"roadmap", PlannerKind::Roadmap, "the lattice built once, searched per query: deterministic, multi-query"},
       [](const ob::SpaceInformationPtr& si, const LatticeSettings& lattice) -> ob::PlannerPtr {
         return std::make_shared<LatticeRoadmap>(si, lattice);
       }},
  };
  return list;
}

const Entry& entryOf(const std::string& name) {
  const std::vector<Entry>& list = entries();
  const auto found = std::find_if(list.begin(), list.end(), [&](const Entry& e) { return e.info.name == name; });
  if (found != list.end()) return *found;
  std::string known;
  for (const Entry& e : list) known += (known.empty() ? "" : ", ") + e.info.name;
  throw ceilplan::InputError("unknown planner '" + name + "': choose one of " + known);
}

const std::string& firstOfKind(PlannerKind kind) {
  for (const Entry& e : entries())
    if (e.info.kind == kind) return e.info.name;
  throw ceilplan::Error("no planner of the requested kind");  // unreachable: the list has every kind
}

}  // namespace

const std::vector<PlannerInfo>& plannerCatalogue() {
  static const std::vector<PlannerInfo> catalogue = [] {
    std::vector<PlannerInfo> result;
    for (const Entry& e : entries()) result.push_back(e.info);
    return result;
  }();
  return catalogue;
}

const std::vector<std::string>& plannerNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> result;
    for (const Entry& e : entries()) result.push_back(e.info.name);
    return result;
  }();
  return names;
}

const PlannerInfo& plannerInfo(const std::string& name) { return entryOf(name).info; }

const std::string& defaultPlannerName() { return entries().front().info.name; }
const std::string& defaultTourPlannerName() { return firstOfKind(PlannerKind::Roadmap); }
const std::string& referencePlannerName() { return firstOfKind(PlannerKind::Lattice); }
const std::string& fallbackPlannerName() { return defaultPlannerName(); }

ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si,
                                   const LatticeSettings& lattice) {
  return entryOf(name).make(si, lattice);
}

}  // namespace ceilplan::planner
