// Flight modes by name, and the modes a tour flies ("both": ceiling, then free).

#include "ceilplan/mission/flight_mode.hpp"

#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

namespace ceilplan::mission {
namespace {

TEST(FlightMode, ATourFliesOneModeOrBothCeilingFirst) {
  EXPECT_EQ(tourFlightModes("ceiling"), std::vector<FlightMode>{FlightMode::Ceiling});
  EXPECT_EQ(tourFlightModes("free"), std::vector<FlightMode>{FlightMode::Free});
  EXPECT_EQ(tourFlightModes("both"), (std::vector<FlightMode>{FlightMode::Ceiling, FlightMode::Free}));
  try {
    tourFlightModes("Both");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "unknown flight mode 'Both': choose ceiling or free");
  }
}

}  // namespace
}  // namespace ceilplan::mission
