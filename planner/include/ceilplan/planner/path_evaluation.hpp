#pragma once
/// @file
/// The figures of a flown path under a cost model, with the state of charge integrated along it
/// by coulomb counting (battery::Simulator), so the current at each point sees the SOC reached
/// there. Used for every reported number: plans, `ceilplan evaluate`, comparisons.

#include "ceilplan/battery/pack.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace ceilplan::planner {

/// One integration step along a path under the full model.
struct PathSample {
  double t_s = 0.0;  ///< time from the path's start
  /// body centre
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double speed_m_s = 0.0;           ///< along the path
  double ceiling_gap_m = 0.0;       ///< rotor plane to the nearest ceiling, any rotor (+inf: none)
  double ground_gap_m = 0.0;        ///< rotor plane to the ground, area-weighted mean under the discs (+inf: none)
  double clearance_m = 0.0;         ///< body centre to the nearest obstacle surface
  double current_a = 0.0;           ///< pack current
  double power_w = 0.0;             ///< at the pack terminals
  double propulsion_power_w = 0.0;  ///< to the motors: independent of the SOC (the current is not)
  double soc = 0.0;                 ///< state of charge, 0..1
  bool assumed_free = false;        ///< the body overlaps unknown space the map's policy assumed free
};

/// A path's figures under the full model, with the state of charge integrated along it.
struct PathEvaluation {
  std::vector<PathSample> samples;    ///< every integration step; a waypoint appears once per segment it joins
  double length_m = 0.0;              ///< length flown
  double duration_s = 0.0;            ///< flight time
  double charge_ah = 0.0;             ///< charge drawn
  double energy_wh = 0.0;             ///< energy drawn at the pack terminals
  double fec = 0.0;                   ///< the discharge and the recharge that puts it back: 2 Q / (2 C_nom)
  double mean_current_a = 0.0;        ///< charge / duration
  double min_soc = 0.0;               ///< lowest state of charge
  double min_clearance_m = 0.0;       ///< smallest body-centre clearance
  double min_ceiling_gap_m = 0.0;     ///< smallest rotor-plane gap to a ceiling (+inf: none)
  double time_under_ceiling_s = 0.0;  ///< time with a rotor closer than the speed rule's gap (2 R) to a ceiling
  double assumed_free_m = 0.0;  ///< path length relying on the unknown-space policy (Environment::assumedFreeAlong)

  /// Length, duration and charge as MotionTotals.
  MotionTotals totals() const { return {length_m, duration_s, charge_ah}; }
};

/// Flown at the model's speeds, or no faster than `max_speed_m_s` along the path (a camera
/// shooting on the move: docs/coverage.md). A path whose waypoints all coincide (a tour's two
/// targets seen from the same place) is no flight: one sample, hovering there, and zero length,
/// time and charge. Throws ceilplan::InputError for fewer than 2 waypoints, a start SOC outside
/// (0, 1] or a speed cap that is not positive, ceilplan::InputError for a waypoint outside the
/// map, battery::DepletionError if the pack would run below its floor.
PathEvaluation evaluatePath(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                            const std::vector<Eigen::Vector3d>& waypoints_m,
                            double max_speed_m_s = std::numeric_limits<double>::infinity());

/// evaluatePath's totals without its samples, the same to the bit: length, duration, charge,
/// energy, FEC, mean current, lowest SOC and time under the ceiling. What needs each sample's
/// own lookups is left out: no samples, and min_clearance_m, min_ceiling_gap_m and assumed_free_m
/// are NaN. Far from structure no gap is looked up (FlightCostModel::conditionsAlong): the speed
/// and the current there are free air's either way. What a search ranks many paths by, most of
/// which it never flies. Throws as evaluatePath does.
PathEvaluation evaluatePathTotals(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                                  const std::vector<Eigen::Vector3d>& waypoints_m,
                                  double max_speed_m_s = std::numeric_limits<double>::infinity());

/// What a path draws at one of evaluatePath's samples: enough to integrate a pack's SOC along it
/// from any start.
struct PathDraw {
  double t_s = 0.0;                 ///< time from the path's start
  double propulsion_power_w = 0.0;  ///< to the motors: independent of the SOC
};

/// evaluatePathTotals, and in `draws` the time and propulsion power of each of evaluatePath's
/// samples, the same to the bit as those samples' own (without their clearance and gap lookups):
/// what a tour's split flies a long way home by. Throws as evaluatePath does.
PathEvaluation evaluatePathTotals(const FlightCostModel& model, const battery::Pack& pack, double start_soc,
                                  const std::vector<Eigen::Vector3d>& waypoints_m, double max_speed_m_s,
                                  std::vector<PathDraw>& draws);

}  // namespace ceilplan::planner
