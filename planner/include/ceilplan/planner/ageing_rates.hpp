#pragma once
/// @file
/// An ageing model linearised for planning: capacity lost per ampere-hour discharged (with its
/// recharge) at the route's depth of discharge, plus calendar loss per second of flight. Both are
/// measured by feeding the model synthetic histories, so any battery::AgeingModel works.

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/battery/pack.hpp"
#include "ceilplan/core/error.hpp"

#include <string>

namespace ceilplan::planner {

/// An ageing model's capacity loss per ampere-hour and per second at one depth of discharge (measureAgeingRates).
struct AgeingRates {
  std::string model;                ///< the ageing model's name
  double depth_of_discharge = 0.0;  ///< the depth of discharge the rates were measured at, 0..1
  double loss_per_ah = 0.0;         ///< fraction of nominal capacity per Ah discharged (and recharged)
  double loss_per_s = 0.0;          ///< calendar part, fraction per second (0 for cycle-only models)
};

/// Cycle: from `start_soc` down by `depth_of_discharge` at `discharge_current_a`, then back at the
/// pack's charge current; calendar: resting at `start_soc` for one day. loss_per_ah = (cycle loss
/// - calendar loss over the cycle's duration) / Ah discharged; loss_per_s = one day's calendar
/// loss / 86400 s. Throws ceilplan::InputError on a depth outside (0, start_soc - soc_min].
AgeingRates measureAgeingRates(const std::string& model_name, const battery::AgeingModelOptions& options,
                               const battery::Pack& pack, double start_soc, double depth_of_discharge,
                               double discharge_current_a);

}  // namespace ceilplan::planner
