// Wind in the energy model: the forward-flight power sees the airspeed, |ground velocity - wind|
// (docs/models.md, "Wind").

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/energy/wind.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace ceilplan::energy;

namespace {

const EnergyModel& paperModel() {
  static const EnergyModel model(paperQuadParameters());
  return model;
}

FlightCondition moving(double speed_m_s, double headwind_m_s = 0.0, double crosswind_m_s = 0.0) {
  FlightCondition flight;
  flight.speed_m_s = speed_m_s;
  flight.headwind_m_s = headwind_m_s;
  flight.crosswind_m_s = crosswind_m_s;
  return flight;
}

}  // namespace

TEST(Wind, AHeadwindCostsWhatFlyingFasterInStillAirCosts) {
  for (const double speed_m_s : {0.0, 1.0, 2.5, 6.0})
    for (const double headwind_m_s : {0.5, 3.0, 8.0}) {
      const CurrentBreakdown windy = paperModel().breakdown(0.3, 1.0, moving(speed_m_s, headwind_m_s));
      const CurrentBreakdown still = paperModel().breakdown(0.3, 1.0, moving(speed_m_s + headwind_m_s));
      EXPECT_EQ(windy.current_a, still.current_a) << speed_m_s << " m/s into " << headwind_m_s << " m/s";
      EXPECT_EQ(windy.parasitic_w, still.parasitic_w);
    }
}

TEST(Wind, ATailwindCostsWhatFlyingSlowerInStillAirCosts) {
  EXPECT_EQ(paperModel().currentA(kNoSurface, 1.0, moving(5.0, -3.0)),
            paperModel().currentA(kNoSurface, 1.0, moving(2.0)));
  // Flying with the air: no airspeed, the hover's current.
  EXPECT_EQ(paperModel().currentA(kNoSurface, 1.0, moving(4.0, -4.0)),
            paperModel().currentA(kNoSurface, 1.0, moving(0.0)));
}

TEST(Wind, HoveringInWindIsForwardFlightAtTheWindsSpeed) {
  const double hover_in_wind_a = paperModel().currentA(kNoSurface, 1.0, moving(0.0, 8.0));
  EXPECT_EQ(hover_in_wind_a, paperModel().currentA(kNoSurface, 1.0, moving(8.0)));
  EXPECT_NE(hover_in_wind_a, paperModel().currentA(kNoSurface, 1.0, moving(0.0)));
}

TEST(Wind, ACrosswindAddsToTheAirspeedInQuadrature) {
  EXPECT_DOUBLE_EQ(moving(3.0, 1.0, 3.0).airspeedM_s(), std::hypot(4.0, 3.0));
  EXPECT_DOUBLE_EQ(paperModel().currentA(kNoSurface, 1.0, moving(3.0, 1.0, 3.0)),
                   paperModel().currentA(kNoSurface, 1.0, moving(5.0)));
}

TEST(Wind, StillAirIsTheGroundSpeedExactly) {
  for (const double speed_m_s : {0.0, 0.1, 1.8, 2.0, 14.999}) EXPECT_EQ(moving(speed_m_s).airspeedM_s(), speed_m_s);
}

TEST(Wind, AnAirspeedBeyondTheVehiclesLimitIsRefused) {
  const double max_m_s = paperModel().maxSpeedM_s();
  EXPECT_NO_THROW(paperModel().currentA(kNoSurface, 1.0, moving(2.0, max_m_s - 2.0)));
  try {
    paperModel().currentA(kNoSurface, 1.0, moving(2.0, max_m_s));
    FAIL() << "an airspeed beyond max_speed_m_s was answered";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("airspeed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("max_speed_m_s"), std::string::npos) << e.what();
  }
  EXPECT_THROW(paperModel().currentA(kNoSurface, 1.0, moving(2.0, std::nan(""))), ceilplan::InputError);
}

TEST(Wind, FromDegIsWhereTheWindComesFromClockwiseFromNorth) {
  const auto air = [](double from_deg) {
    Wind wind;
    wind.speed_m_s = 8.0;
    wind.from_deg = from_deg;
    return wind.airVelocityM_s();
  };
  EXPECT_NEAR(air(0.0).x(), 0.0, 1e-12);  // from the north: blows towards -y
  EXPECT_NEAR(air(0.0).y(), -8.0, 1e-12);
  EXPECT_NEAR(air(90.0).x(), -8.0, 1e-12);  // from the east: towards -x
  EXPECT_NEAR(air(90.0).y(), 0.0, 1e-12);
  EXPECT_NEAR(air(180.0).y(), 8.0, 1e-12);
  EXPECT_NEAR(air(270.0).x(), 8.0, 1e-12);
}

TEST(Wind, RelativeWindIsAHeadwindOnTheWayUpwindAndATailwindBack) {
  Wind wind;
  wind.speed_m_s = 8.0;
  wind.from_deg = 90.0;  // from +x
  const RelativeWind east = relativeWind(wind.airVelocityM_s(), Eigen::Vector2d::UnitX());
  const RelativeWind west = relativeWind(wind.airVelocityM_s(), -Eigen::Vector2d::UnitX());
  EXPECT_NEAR(east.headwind_m_s, 8.0, 1e-12);
  EXPECT_NEAR(west.headwind_m_s, -8.0, 1e-12);
  EXPECT_NEAR(relativeWind(wind.airVelocityM_s(), Eigen::Vector2d::UnitY()).crosswind_m_s, 8.0, 1e-12);
  const RelativeWind hovering = relativeWind(wind.airVelocityM_s(), Eigen::Vector2d::Zero());
  EXPECT_NEAR(hovering.headwind_m_s, 8.0, 1e-12);
  EXPECT_EQ(hovering.crosswind_m_s, 0.0);
  const RelativeWind calm = relativeWind(Wind{}.airVelocityM_s(), Eigen::Vector2d::UnitX());
  EXPECT_EQ(calm.headwind_m_s, 0.0);
  EXPECT_EQ(calm.crosswind_m_s, 0.0);
}

TEST(Wind, ValidateNamesTheBadField) {
  const auto refused = [](Wind wind, const std::string& field) {
    try {
      wind.validate();
      ADD_FAILURE() << field << " was accepted";
    } catch (const ceilplan::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  Wind wind;
  wind.speed_m_s = -1.0;
  refused(wind, "speed_m_s");
  wind = Wind{};
  wind.speed_m_s = std::nan("");
  refused(wind, "speed_m_s");
  wind = Wind{};
  wind.from_deg = 360.0;
  refused(wind, "from_deg");
  wind = Wind{};
  wind.gust_m_s = -0.5;
  refused(wind, "gust_m_s");
  wind = Wind{};
  wind.sheltered_fraction = 1.5;
  refused(wind, "sheltered_fraction");
  EXPECT_NO_THROW(Wind{}.validate());
}
