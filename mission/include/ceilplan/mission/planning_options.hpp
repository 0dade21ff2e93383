#pragma once
/// @file
/// Every setting of planning, once, for routes and tours alike (as Ceres has one Options): a
/// mission file's `speeds:`, `seed:` and `unknown:` keys fill a Mission's (io::readMission), the
/// command line and Python override single fields of it, PlanningContext keeps it (options()),
/// and planRoute and planTour read it there. docs/contributing.md, "Settings".

#include "ceilplan/energy/wind.hpp"
#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/unknown_space.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <cstdint>
#include <string>

namespace ceilplan::mission {

/// Every planning setting, in one place (docs/contributing.md, "Settings"): read from the mission
/// file into Mission::planning, overridden field by field by the CLI and Python, held by the
/// PlanningContext and recorded in each result.
struct PlanningOptions {
  std::string objective = "charge";  ///< planner::objectiveNames(); a tour's legs always minimise charge
  std::string ageing_model = "xu";   ///< of the ageing objective, and what a tour's sortie split minimises
  double ageing_dod = 0.0;           ///< 0: the route's own depth of discharge (straight-line estimate, at least 1 %)
  planner::FlightSpeeds speeds;      ///< mission key `speeds:`
  double min_ceiling_gap_m = 0.05;   ///< rotor plane to any ceiling, never less
  double standoff_m = 1.0;           ///< free mode: the conventional distance from every structure
  double temperature_c = 25.0;       ///< cell temperature for the ageing models (objective, sortie split, wear)
  std::uint32_t seed = 1;            ///< of every random choice (a tour's order, OMPL's); mission key `seed:`
  environment::EnvironmentOptions environment;  ///< how gaps and clearance are measured
  environment::UnknownSpace unknown;            ///< the map index's unknown-space policy; mission key `unknown:`
  energy::Wind wind;                            ///< the air the mission flies in (calm: still air); mission key `wind:`

  /// Throws ceilplan::InputError naming the first bad field.
  void validate() const;
};

}  // namespace ceilplan::mission
