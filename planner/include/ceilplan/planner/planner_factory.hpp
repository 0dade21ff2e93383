#pragma once
/// @file
/// Every planner by name, OMPL's and ceilplan's: one factory, so each runs under the same
/// objectives and validity checker, and can be benchmarked with ompl::tools::Benchmark.

#include "ceilplan/planner/lattice_settings.hpp"

#include <ompl/base/Planner.h>

#include <string>
#include <vector>

namespace ceilplan::planner {

/// The kinds of planner the factory makes.
enum class PlannerKind {
  Sampling,  ///< OMPL's anytime planners: random, seeded once per process (seedOmpl), stopped by the clock
  Lattice,   ///< ceilplan's lattice A* (LatticePlanner): deterministic, one query at a time
  Roadmap,   ///< ceilplan's lattice roadmap (LatticeRoadmap): deterministic, many queries on one roadmap
};

/// A planner the factory knows: its name, kind and one line about it.
struct PlannerInfo {
  std::string name;     ///< the name the factory takes (e.g. "BITstar", "lattice", "roadmap")
  PlannerKind kind;     ///< sampling, lattice or roadmap
  std::string summary;  ///< one line, for help texts

  /// Gives the same route every run (the lattice planners).
  bool deterministic() const { return kind != PlannerKind::Sampling; }
  /// Answers many queries from one build (the roadmap).
  bool multiQuery() const { return kind == PlannerKind::Roadmap; }
};

/// Every planner, the default for single queries first.
const std::vector<PlannerInfo>& plannerCatalogue();
/// Their names, in the same order.
const std::vector<std::string>& plannerNames();
/// Throws ceilplan::InputError for an unknown name, listing the known ones.
const PlannerInfo& plannerInfo(const std::string& name);

const std::string& defaultPlannerName();      ///< single queries (BIT*, docs/planner.md "Quality of the planners")
const std::string& defaultTourPlannerName();  ///< a tour's legs: the roadmap
const std::string& referencePlannerName();    ///< the quality reference: the lattice A*
const std::string& fallbackPlannerName();     ///< for a pair the roadmap cannot join: BIT*

/// A new planner; `lattice` configures the lattice planners (OMPL's ignore it). Throws
/// ceilplan::InputError for an unknown name.
ompl::base::PlannerPtr makePlanner(const std::string& name, const ompl::base::SpaceInformationPtr& si,
                                   const LatticeSettings& lattice = {});

}  // namespace ceilplan::planner
