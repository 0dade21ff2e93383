#pragma once
/// @file
/// Coulomb counting and full-equivalent-cycle (FEC) counting over a load profile
/// (Kocer et al. 2019, arXiv 1812.11707, eq. 3-8; docs/battery.md).

#include "ceilplan/battery/load_profile.hpp"
#include "ceilplan/battery/pack.hpp"

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace ceilplan::battery {

/// One recorded point of a simulation. `current_a` is signed (positive discharging) and holds
/// the current of the segment the point belongs to, so consecutive points draw the load steps.
struct Sample {
  double t_s = 0.0;             ///< time, s
  double current_a = 0.0;       ///< pack current, A, positive discharging
  double soc = 0.0;             ///< state of charge, 0..1
  double fec = 0.0;             ///< discrete update at mode changes (paper eq. 3-5)
  double fec_continuous = 0.0;  ///< running integral (paper eq. 6)
  Mode mode = Mode::Idle;       ///< the segment's mode
};

/// Where a Simulator stands: time, SOC, FEC and the charge moved so far.
struct BatteryState {
  double t_s = 0.0;             ///< time, s
  double soc = 1.0;             ///< state of charge, 0..1
  double min_soc = 1.0;         ///< lowest SOC so far
  double fec = 0.0;             ///< booked at each mode change (paper eq. 3-5)
  double fec_continuous = 0.0;  ///< FEC(t) = 1/(2 C_nom) * integral |i| dt (paper eq. 6)
  /// The same throughput counted against the usable capacity C_nom * SOH: sum |dSOC| / 2, the
  /// cycles of the faded pack. Equal to the FEC while SOH = 1; never call it FEC.
  double faded_pack_cycles = 0.0;
  double discharge_ah = 0.0;  ///< charge drawn so far, Ah
  double charge_ah = 0.0;     ///< charge put back so far, Ah
};

/// Full equivalent cycles of `throughput_ah` moved through a pack of `capacity_ah`, in either
/// direction: FEC = throughput / (2 C_nom) (paper eq. 3-6). A discharge and the equal recharge
/// that follows it move twice its charge. The one FEC formula: the Simulator, route evaluation
/// and tours all count with it.
inline double fullEquivalentCycles(double throughput_ah, double capacity_ah) {
  return throughput_ah / (2.0 * capacity_ah);
}

/// One step of coulomb counting (paper eq. 1): `current_a` (positive discharging) drawn for
/// `dt_s` from `soc` moves `charge_ah` and leaves `soc_after`, against the usable capacity.
struct CoulombStep {
  double charge_ah;  ///< charge moved, Ah (negative while charging)
  double soc_after;  ///< SOC after the step (fraction)
};
/// The step of `current_a` for `dt_s` from `soc` against `usable_capacity_ah` (CoulombStep).
inline CoulombStep coulombStep(double soc, double current_a, double dt_s, double usable_capacity_ah) {
  const double charge_ah = current_a * dt_s / 3600.0;
  return {charge_ah, soc - charge_ah / usable_capacity_ah};
}

/// Thrown when a segment would take the SOC below the pack's floor (soc_min).
class DepletionError : public ceilplan::InfeasibleError {
 public:
  /// "would take the battery to R % SOC, P points below its F % floor".
  DepletionError(double reached_soc, double floor_soc);
  /// With its own `message`.
  DepletionError(const std::string& message, double reached_soc, double floor_soc);
  double reachedSoc() const { return reached_soc_; }  ///< the SOC the segment would have reached
  /// The pack's SOC floor (soc_min).
  double floorSoc() const { return floor_soc_; }

 private:
  double reached_soc_;
  double floor_soc_;
};

/// Integrates SOC and FEC segment by segment.
///
/// Exact scheme (step_s = 0): each constant-current segment in closed form, a stop condition
/// solved for the exact time it is met.
/// Fixed-step scheme (step_s > 0): the paper's scheme. A stop condition is checked at step ends,
/// so a charge that reaches its target inside a step ends with that step (the paper's 43.5 and
/// 40.5 min); the SOC stops at the target, so charge throughput and FEC match the exact scheme.
class Simulator {
 public:
  /// A simulator of `pack` at `initial_soc`, exact (step_s 0) or at fixed steps of `step_s`.
  Simulator(const Pack& pack, double initial_soc, double step_s = 0.0);

  /// Runs one segment from the current state and returns how long it lasted. Appends the
  /// segment's start point, its step points (fixed step) and its end point to `record`.
  /// Throws DepletionError (state unchanged) if the segment would cross the SOC floor.
  double run(const Segment& segment, std::vector<Sample>* record = nullptr);

  /// Books the open mode interval into the discrete FEC; call once a profile has ended.
  void closeModeInterval();

  /// Capacity fade: later segments see usable capacity C_nom * SOH (paper eq. 7).
  void setStateOfHealth(double state_of_health);

  /// Where the simulation stands.
  const BatteryState& state() const { return state_; }
  /// The pack simulated.
  const Pack& pack() const { return pack_; }
  /// The fixed step, s (0: exact).
  double stepS() const { return step_s_; }

 private:
  struct Advance {
    double time_s;
    double soc_after;
    double charge_moved_ah;
  };
  Advance plan(const Segment& segment, double soc, double max_time_s) const;
  void apply(const Segment& segment, const Advance& advance);
  void enterMode(Mode mode);
  Sample sample(const Segment& segment) const;

  Pack pack_;
  double step_s_;
  BatteryState state_;
  std::optional<Mode> interval_mode_;
  double interval_ah_ = 0.0;
};

/// Explicit coulomb counting of a discharge in steps of any length, each drawing the current the
/// caller computed for it (the mean of its ends' currents, each at the SOC reached before it):
/// how route evaluation (planner::evaluatePath) and tours (mission::SocIntegrator) integrate the
/// state of charge, by coulombStep.
class CoulombCounter {
 public:
  /// Counts from `start_soc` against `pack`'s usable capacity and floor.
  CoulombCounter(const Pack& pack, double start_soc)
      : usable_capacity_ah_(pack.usableCapacityAh()),
        floor_soc_(pack.soc_min),
        soc_(start_soc),
        lowest_soc_(start_soc) {}

  /// Moves on by `dt_s` drawing `current_a`.
  void discharge(double current_a, double dt_s) {
    const CoulombStep step = coulombStep(soc_, current_a, dt_s, usable_capacity_ah_);
    charge_ah_ += step.charge_ah;
    soc_ = step.soc_after;
    time_s_ += dt_s;
    lowest_soc_ = std::min(lowest_soc_, soc_);
  }
  /// Throws DepletionError once the SOC is below the pack's floor.
  void requireAboveFloor() const {
    if (soc_ < floor_soc_ - 1e-12) throw DepletionError(soc_, floor_soc_);
  }

  double soc() const { return soc_; }               ///< SOC now (fraction)
  double time_s() const { return time_s_; }         ///< time counted, s
  double chargeAh() const { return charge_ah_; }    ///< charge drawn, Ah
  double lowestSoc() const { return lowest_soc_; }  ///< the lowest SOC so far

 private:
  double usable_capacity_ah_;
  double floor_soc_;
  double soc_;
  double time_s_ = 0.0;
  double charge_ah_ = 0.0;
  double lowest_soc_;
};

/// Runs a whole profile from `initial_soc` and closes the last mode interval.
BatteryState simulate(const Pack& pack, const LoadProfile& profile, double initial_soc, double step_s = 0.0,
                      std::vector<Sample>* record = nullptr);

}  // namespace ceilplan::battery
