#include "ceilplan/mission/flight_mode.hpp"

#include "ceilplan/core/error.hpp"

namespace ceilplan::mission {

std::string flightModeName(FlightMode mode) { return mode == FlightMode::Ceiling ? "ceiling" : "free"; }

FlightMode flightModeFromName(const std::string& name) {
  if (name == "ceiling") return FlightMode::Ceiling;
  if (name == "free") return FlightMode::Free;
  throw InputError("unknown flight mode '" + name + "': choose ceiling or free");
}

std::vector<FlightMode> tourFlightModes(const std::string& name) {
  if (name == "both") return {FlightMode::Ceiling, FlightMode::Free};
  return {flightModeFromName(name)};
}

const std::vector<std::string>& flightModeNames() {
  static const std::vector<std::string> names{"ceiling", "free"};
  return names;
}

}  // namespace ceilplan::mission
