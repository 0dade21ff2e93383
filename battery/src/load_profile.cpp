#include "ceilplan/battery/load_profile.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <cmath>
#include <stdexcept>

namespace ceilplan::battery {

std::string toString(Mode mode) {
  switch (mode) {
    case Mode::Discharge:
      return "discharge";
    case Mode::Idle:
      return "idle";
    case Mode::Charge:
      return "charge";
  }
  return "unknown";
}

Segment Segment::discharge(double current_a, double duration_s) {
  return Segment{Mode::Discharge, current_a, duration_s, std::nullopt};
}

Segment Segment::idle(double duration_s) { return Segment{Mode::Idle, 0.0, duration_s, std::nullopt}; }

Segment Segment::charge(double current_a, double max_duration_s, double until_soc) {
  return Segment{Mode::Charge, current_a, max_duration_s, until_soc};
}

double Segment::signedCurrentA() const {
  switch (mode) {
    case Mode::Discharge:
      return current_a;
    case Mode::Charge:
      return -current_a;
    case Mode::Idle:
      return 0.0;
  }
  return 0.0;
}

void Segment::validate() const {
  const std::string what = toString(mode) + " segment";
  if (!(std::isfinite(current_a) && current_a >= 0.0))
    throw ceilplan::InputError(what + ": current must be a finite number >= 0 A, got " + formatNumber(current_a));
  if (!(std::isfinite(duration_s) && duration_s >= 0.0))
    throw ceilplan::InputError(what + ": duration must be a finite number >= 0 s, got " + formatNumber(duration_s));
  if (mode == Mode::Charge && current_a == 0.0 && duration_s > 0.0)
    throw ceilplan::InputError(what +
                               ": charge current is 0 A, so the battery can never charge; set a charge current > 0");
  if (mode == Mode::Idle && current_a != 0.0) throw ceilplan::InputError(what + ": an idle segment carries no current");
  if (stop_soc && !(*stop_soc > 0.0 && *stop_soc <= 1.0))
    throw ceilplan::InputError(what + ": stop SOC must be in (0, 1], got " + formatNumber(*stop_soc));
}

}  // namespace ceilplan::battery
