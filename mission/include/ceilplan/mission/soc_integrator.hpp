#pragma once
/// How every sortie's state of charge is integrated, by the sortie split and by the flight
/// record alike: battery::CoulombCounter, the explicit coulomb counting planner::evaluatePath
/// uses for a single path, each interval drawing the mean of the currents at its two ends, each
/// current computed at the SOC reached just before it.

#include "ceilplan/battery/pack.hpp"
#include "ceilplan/battery/simulation.hpp"

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace ceilplan::mission {

/// How a load turns into pack current at a state of charge: for a tour, the energy model's Rint
/// pack fed the propulsion power (W). Unset: the load is the current itself (A), whatever the SOC.
using CurrentAtSoc = std::function<double(double load, double soc)>;

/// Hovering is integrated in steps of at most this long.
inline constexpr double kHoverStepS = 1.0;

/// A point of a load profile; t_s from the profile's start.
struct LoadSample {
  double t_s = 0.0;   ///< from the profile's start
  double load = 0.0;  ///< what is drawn: a current (A) or a power (W), as CurrentAtSoc takes it
};

/// The state of charge of one pack through a sortie: the one SOC integration tours use (coulomb counting).
class SocIntegrator {
 public:
  /// From `start_soc`; `current_at_soc` (if set) turns a load into the current at the SOC reached.
  SocIntegrator(const battery::Pack& pack, double start_soc, CurrentAtSoc current_at_soc = {})
      : counter_(pack, start_soc), current_at_soc_(std::move(current_at_soc)) {}

  /// The current a load draws now.
  double currentFor(double load) const { return current_at_soc_ ? current_at_soc_(load, soc()) : load; }
  /// Moves on by `dt_s` drawing `current_a` (the interval's mean current).
  void advance(double dt_s, double current_a) { counter_.discharge(current_a, dt_s); }

  double soc() const { return counter_.soc(); }              ///< SOC now (fraction)
  double time_s() const { return counter_.time_s(); }        ///< time integrated, s
  double chargeAh() const { return counter_.chargeAh(); }    ///< charge drawn, Ah
  double lowestSoc() const { return counter_.lowestSoc(); }  ///< the lowest SOC so far

 private:
  battery::CoulombCounter counter_;  // the one SOC integration (battery/simulation.hpp)
  CurrentAtSoc current_at_soc_;
};

/// Called at each sample once the integrator has reached it, with the current drawn there.
using SampleVisitor = std::function<void(std::size_t sample, double current_a)>;

/// Flies a load profile (at least one sample, times increasing) from the integrator's state.
void flyProfile(SocIntegrator& flight, const std::vector<LoadSample>& profile, const SampleVisitor& visit = {});
/// `profile` in steps of at most `step_s` (an interval longer than that is a step of its own),
/// each drawing its mean load throughout: the integral of the load over the step (trapezoid rule,
/// as flyProfile draws it) over the step's length. Two samples per step, at its start and end; a
/// step's end and the next one's start share a time. Flown from any SOC it draws the profile's
/// charge but for how the current curves in the load within a step, and the SOC's fall within a
/// step, which flyProfile's intervals and a hover's steps (kHoverStepS) leave too. Profiles of
/// fewer than 3 samples come back as they are. Throws ceilplan::InputError for a step that is
/// not a positive number.
std::vector<LoadSample> stepProfile(const std::vector<LoadSample>& profile, double step_s);
/// Draws `load` for `duration_s` in steps of at most kHoverStepS; visit(k, current) for k = 0..steps.
void hover(SocIntegrator& flight, double load, double duration_s, const SampleVisitor& visit = {});
/// The number of steps hover() takes.
std::size_t hoverSteps(double duration_s);

}  // namespace ceilplan::mission
