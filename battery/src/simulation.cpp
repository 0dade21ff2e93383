#include "ceilplan/battery/simulation.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::battery {
namespace {

constexpr double kSecondsPerHour = 3600.0;

// The SOC at which a segment stops early, if any: a charge never passes soc_max.
std::optional<double> stopSoc(const Segment& segment, const Pack& pack) {
  if (segment.mode == Mode::Charge) return std::min(segment.stop_soc.value_or(pack.soc_max), pack.soc_max);
  if (segment.mode == Mode::Discharge) return segment.stop_soc;
  return std::nullopt;
}

}  // namespace

DepletionError::DepletionError(const std::string& message, double reached_soc, double floor_soc)
    : ceilplan::InfeasibleError(message), reached_soc_(reached_soc), floor_soc_(floor_soc) {}

DepletionError::DepletionError(double reached_soc, double floor_soc)
    : DepletionError("would take the battery to " + formatNumber(100.0 * reached_soc) + " % SOC, " +
                         formatNumber(100.0 * (floor_soc - reached_soc)) + " points below its " +
                         formatNumber(100.0 * floor_soc) + " % floor",
                     reached_soc, floor_soc) {}

Simulator::Simulator(const Pack& pack, double initial_soc, double step_s) : pack_(pack), step_s_(step_s) {
  pack_.validate();
  if (!(std::isfinite(step_s) && step_s >= 0.0))
    throw ceilplan::InputError("time step must be >= 0 s (0 = exact), got " + formatNumber(step_s));
  if (!(initial_soc > 0.0 && initial_soc <= 1.0))
    throw ceilplan::InputError("initial SOC must be in (0, 1], got " + formatNumber(initial_soc));
  state_.soc = initial_soc;
  state_.min_soc = initial_soc;
}

void Simulator::setStateOfHealth(double state_of_health) {
  if (!(state_of_health > 0.0 && state_of_health <= 1.0))
    throw ceilplan::InputError("state of health must be in (0, 1], got " + formatNumber(state_of_health));
  pack_.state_of_health = state_of_health;
}

// How far a segment gets in at most `max_time_s` from `soc`, stopping where its stop
// condition is met (time to the exact crossing; the caller rounds up to whole steps).
Simulator::Advance Simulator::plan(const Segment& segment, double soc, double max_time_s) const {
  const double direction = segment.mode == Mode::Charge ? 1.0 : (segment.mode == Mode::Discharge ? -1.0 : 0.0);
  const double soc_rate_per_s = direction * segment.current_a / (kSecondsPerHour * pack_.usableCapacityAh());
  const std::optional<double> stop = stopSoc(segment, pack_);
  if (stop && soc_rate_per_s != 0.0) {
    const double time_to_stop_s = std::max(0.0, (*stop - soc) / soc_rate_per_s);
    if (time_to_stop_s <= max_time_s) {
      if (time_to_stop_s == 0.0) return {0.0, soc, 0.0};  // already at or past the stop SOC
      return {time_to_stop_s, *stop, std::abs(*stop - soc) * pack_.usableCapacityAh()};
    }
  }
  const CoulombStep step = coulombStep(soc, -direction * segment.current_a, max_time_s, pack_.usableCapacityAh());
  return {max_time_s, step.soc_after, std::abs(step.charge_ah)};
}

void Simulator::enterMode(Mode mode) {
  if (interval_mode_ && *interval_mode_ != mode) closeModeInterval();
  interval_mode_ = mode;
}

void Simulator::closeModeInterval() {
  // dFEC = C_r (t2 - t1) / 2 with C_r the interval's mean |i| / C_nom (paper eq. 3-5).
  state_.fec += fullEquivalentCycles(interval_ah_, pack_.capacity_ah);
  interval_ah_ = 0.0;
  interval_mode_.reset();
}

void Simulator::apply(const Segment& segment, const Advance& advance) {
  state_.t_s += advance.time_s;
  state_.soc = advance.soc_after;
  state_.min_soc = std::min(state_.min_soc, state_.soc);
  state_.fec_continuous += fullEquivalentCycles(advance.charge_moved_ah, pack_.capacity_ah);
  state_.faded_pack_cycles += fullEquivalentCycles(advance.charge_moved_ah, pack_.usableCapacityAh());
  interval_ah_ += advance.charge_moved_ah;
  if (segment.mode == Mode::Discharge) state_.discharge_ah += advance.charge_moved_ah;
  if (segment.mode == Mode::Charge) state_.charge_ah += advance.charge_moved_ah;
}

Sample Simulator::sample(const Segment& segment) const {
  return Sample{state_.t_s, segment.signedCurrentA(), state_.soc, state_.fec, state_.fec_continuous, segment.mode};
}

double Simulator::run(const Segment& segment, std::vector<Sample>* record) {
  segment.validate();
  // Refuse a segment that would cross the floor before changing any state.
  const Advance whole = plan(segment, state_.soc, segment.duration_s);
  if (whole.soc_after < pack_.soc_min - 1e-12) {
    throw DepletionError(whole.soc_after, pack_.soc_min);
  }
  enterMode(segment.mode);
  if (record) record->push_back(sample(segment));
  const double start_s = state_.t_s;
  if (step_s_ == 0.0) {
    apply(segment, whole);
  } else {
    double remaining_s = segment.duration_s;
    while (remaining_s > 0.0) {
      const double step_s = std::min(step_s_, remaining_s);
      Advance step = plan(segment, state_.soc, step_s);
      if (step.time_s == 0.0) break;  // the stop condition held before this step began
      const bool stopped = step.time_s < step_s;
      step.time_s = step_s;  // a stop condition is only seen at the step's end
      apply(segment, step);
      remaining_s -= step_s;
      if (record) record->push_back(sample(segment));
      if (stopped) break;
    }
    if (record && record->back().t_s == start_s) record->push_back(sample(segment));
    return state_.t_s - start_s;
  }
  if (record) record->push_back(sample(segment));
  return state_.t_s - start_s;
}

BatteryState simulate(const Pack& pack, const LoadProfile& profile, double initial_soc, double step_s,
                      std::vector<Sample>* record) {
  Simulator simulator(pack, initial_soc, step_s);
  for (const Segment& segment : profile) simulator.run(segment, record);
  simulator.closeModeInterval();
  return simulator.state();
}

}  // namespace ceilplan::battery
