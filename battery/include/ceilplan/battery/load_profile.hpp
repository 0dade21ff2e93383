#pragma once

#include "ceilplan/core/error.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::battery {

enum class Mode {
  Discharge,  ///< drawing current from the pack
  Idle,       ///< no current
  Charge      ///< putting charge back
};

std::string toString(Mode mode);

/// One constant-current piece of a load profile. It lasts `duration_s`, or less when its stop
/// condition is met first: a charge stops once SOC >= stop_soc, a discharge once SOC <= stop_soc.
/// `current_a` is a magnitude (>= 0); the mode gives the direction.
struct Segment {
  Mode mode = Mode::Idle;          ///< discharge, idle or charge
  double current_a = 0.0;          ///< current magnitude, A (>= 0)
  double duration_s = 0.0;         ///< longest duration, s
  std::optional<double> stop_soc;  ///< SOC at which the segment ends early; none: it runs its duration

  /// Discharge at `current_a` for `duration_s`.
  static Segment discharge(double current_a, double duration_s);
  /// Rest (no current) for `duration_s`.
  static Segment idle(double duration_s);
  /// Charge at `current_a` until SOC >= `until_soc`, for at most `max_duration_s`.
  static Segment charge(double current_a, double max_duration_s, double until_soc);

  /// Signed pack current: positive while discharging, negative while charging.
  double signedCurrentA() const;

  /// Throws ceilplan::InputError naming the problem (negative or NaN current or duration,
  /// a charge with zero current, a stop SOC outside (0, 1]).
  void validate() const;
};

using LoadProfile = std::vector<Segment>;

}  // namespace ceilplan::battery
