#pragma once
/// @file
/// Everything ceilplan offers a program, in one header (target ceilplan::ceilplan).

/// @mainpage ceilplan's C++ API
/// Mission planning for multirotor UAVs inspecting structures from below. Start from
/// ceilplan::mission::PlanningContext (a map indexed once for a vehicle and a battery),
/// ceilplan::mission::planRoute and ceilplan::mission::checkRoute (single routes, results in
/// ceilplan::mission::RoutePlan and ceilplan::planner::PathEvaluation) and
/// ceilplan::mission::planTour (a mission's inspection tour, ceilplan::mission::TourResult);
/// ceilplan::io::readMission reads a mission file. Errors: ceilplan::Error and its subclasses.
/// The guide with complete programs, the link line and the threading rules is docs/cpp.md in the
/// source tree; `#include <ceilplan/ceilplan.hpp>` and link `ceilplan::ceilplan`.

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/version.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/duty_cycle.hpp"
#include "ceilplan/battery/duty_study.hpp"
#include "ceilplan/battery/lifetime.hpp"
#include "ceilplan/battery/rainflow.hpp"

#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/energy/wind.hpp"

#include "ceilplan/environment/environment.hpp"
#include "ceilplan/environment/occupancy_map.hpp"
#include "ceilplan/environment/position_probe.hpp"

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include "ceilplan/mission/coverage_plan.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/mission_proposal.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/route_planning.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/calibration_file.hpp"
#include "ceilplan/io/coverage_output.hpp"
#include "ceilplan/io/duty_study_files.hpp"
#include "ceilplan/io/json_values.hpp"
#include "ceilplan/io/map_import.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/octomap_file.hpp"
#include "ceilplan/io/plan_files.hpp"
#include "ceilplan/io/proposal_files.hpp"
#include "ceilplan/io/report_json.hpp"
#include "ceilplan/io/soc_series_file.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/io/vehicle_file.hpp"
