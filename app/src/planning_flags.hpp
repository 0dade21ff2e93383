#pragma once
// The flags plan, evaluate, compare and bench-planners share: map, vehicle, battery, objective,
// speeds and safety rules into mission::PlanningOptions, and the search flags into a
// planner::PlanRequest.

#include "map_options.hpp"
#include "output.hpp"

#include "ceilplan/io/provenance.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/planner/flight_planner.hpp"

#include <CLI/CLI.hpp>
#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace ceilplan::app {

struct PlanningFlags {
  std::string map;
  std::string vehicle;               // empty: the built-in vehicle (maps/vehicles/quad.yaml)
  std::string battery;               // empty: the paper's pack at 95 %
  mission::PlanningOptions options;  // its unknown-space policy comes from `unknown`
  UnknownSpaceFlags unknown;
};

// Registers --map, --vehicle, --battery, --objective, --unknown and the model flags on `command`.
// `with_objective` false leaves --objective out (commands that report every objective).
void addPlanningOptions(CLI::App* command, PlanningFlags& flags, bool with_objective = true);

// The outputs' provenance: the command line, the map, vehicle and battery files, the seed.
io::Provenance planningProvenance(const PlanningFlags& flags, std::optional<std::uint64_t> seed);

// The files the flags name (and --config), for io::OutputSet: no output may replace them.
std::vector<io::Input> planningInputs(const PlanningFlags& flags);

// The map, vehicle and battery the flags name, indexed with progress on the terminal.
std::unique_ptr<mission::PlanningContext> makePlanningContext(const PlanningFlags& flags);

// The search flags shared by plan, compare and bench-planners, with the library's defaults (as Python's).
struct SearchArguments {
  std::string planner;  // empty: the default
  double time_limit_s = planner::PlanRequest{}.time_limit_s;
  double band_fraction = planner::PlanRequest{}.band_fraction;
  bool no_refine = false;
  double lattice_spacing_m = planner::kQueryLatticeSpacing_m;  // the lattice planners' node spacing

  planner::PlanRequest request(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m) const;
  std::string plannerName() const;
  // "planner BITstar, seed 3, 5 s", or for a lattice planner its spacing (it has no seed or clock).
  std::string describe(std::uint32_t seed) const;
};
// The search flags, and --seed into the planning options' seed (the one seed setting).
void addSearchOptions(CLI::App* command, SearchArguments& arguments, PlanningFlags& planning);

// "x,y,z" in metres; throws ceilplan::InputError naming `flag`.
Eigen::Vector3d parsePoint(const std::string& text, const std::string& flag);

}  // namespace ceilplan::app
