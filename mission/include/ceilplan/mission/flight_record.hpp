#pragma once
/// @file
/// The one flight record of a tour: per sortie, every sample from take-off to landing (time,
/// position, speed, gaps, clearance, current, SOC), legs flown at their real entry SOC and
/// dwells hovered at the SOC reached there, integrated by the same SocIntegrator the sortie
/// split used. The split's figures, path.csv, tour.json, the wear models and the duty
/// projection all read it.

#include "ceilplan/planner/path_evaluation.hpp"

#include <cstdint>
#include <vector>

namespace ceilplan::mission {

/// What the vehicle does at a sample: flying a leg, or hovering at a stop (a dwell).
enum class FlightPhase : std::uint8_t {
  Leg,   ///< flying a leg
  Dwell  ///< hovering at a stop
};

/// One sortie as flown, sample by sample, with its turnaround.
struct SortieRecord {
  std::vector<planner::PathSample> samples;  ///< t_s from this sortie's take-off
  std::vector<FlightPhase> phases;           ///< one per sample
  std::vector<int> steps;                    ///< per sample: the sortie leg it belongs to (a dwell: the leg into it)
  double takeoff_s = 0.0;                    ///< on the tour's clock: the sorties and the turnarounds between them
  double turnaround_s = 0.0;                 ///< landing to the next take-off (the recharge, or a pack swap)
  double recharge_s = 0.0;                   ///< back to the start SOC at the charge current (the pack's own cycle)

  double chargeAh() const;  ///< the trapezoid integral of the samples' current
  /// Take-off to landing, s.
  double flightS() const { return samples.empty() ? 0.0 : samples.back().t_s; }
  /// The lowest SOC of the samples.
  double lowestSoc() const;
};

/// What a tour flies, sortie by sortie (path.csv).
struct FlightRecord {
  std::vector<SortieRecord> sorties;  ///< in flying order
};

}  // namespace ceilplan::mission
