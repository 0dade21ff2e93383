#pragma once
/// @file
/// The two ways ceilplan plans the same work: hugging ceilings where that saves charge, or as a
/// conventional planner would fly it (proximity effects ignored, a standoff kept from structure).

#include <string>
#include <vector>

namespace ceilplan::mission {

/// Ceiling: hug the structure's underside where it saves charge. Free: the conventional flight, a standoff from every
/// structure and no proximity effects.
enum class FlightMode {
  Ceiling,  ///< hug the underside of the structure where it saves charge
  Free      ///< conventional flight: a standoff from every structure, free-air current
};

/// "ceiling", "free".
std::string flightModeName(FlightMode mode);
/// Throws ceilplan::InputError for any other name, listing both.
FlightMode flightModeFromName(const std::string& name);
/// "ceiling", "free".
const std::vector<std::string>& flightModeNames();
/// What a tour flies for "ceiling" or "free", or "both": ceiling mode, then free mode, to compare
/// them. Throws as flightModeFromName for any other name.
std::vector<FlightMode> tourFlightModes(const std::string& name);

}  // namespace ceilplan::mission
