// The duty projection's options (compare's and tour's month): times up to a day, counts in
// range, each refused naming the field before any planning.

#include "ceilplan/mission/route_planning.hpp"

#include "input_error.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace ceilplan::mission {
namespace {

TEST(DutyOptions, TimesUpToADayAndCountsInRange) {
  EXPECT_EQ(testing::inputErrorOf([] { DutyOptions{}.validate(); }), "(no error)");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const struct {
    void (*change)(DutyOptions&);
    std::string says;
  } rows[] = {
      {[](DutyOptions& d) { d.flight_min = 1e308; },
       "duty: flight_min must be a finite number of minutes in [0, 1440] (a day), got 1e+308"},
      {[](DutyOptions& d) { d.flight_min = -1.0; }, "duty: flight_min must be a finite number of minutes in [0, 1440]"},
      {[](DutyOptions& d) { d.idle_min = std::numeric_limits<double>::infinity(); }, "duty: idle_min must be"},
      {[](DutyOptions& d) { d.charge_max_min = 0.0; },
       "duty: charge_max_min must be a finite number of minutes in (0, 1440]"},
      {[](DutyOptions& d) { d.missions_per_day = 0; }, "duty: missions_per_day must be in [1, 1000], got 0"},
      {[](DutyOptions& d) { d.days = 3651; }, "duty: days must be in [1, 3650], got 3651"},
  };
  for (const auto& row : rows) {
    DutyOptions duty;
    row.change(duty);
    EXPECT_EQ(testing::inputErrorOf([&] { duty.validate(); }).rfind(row.says, 0), 0u)
        << testing::inputErrorOf([&] { duty.validate(); });
  }
  DutyOptions duty;
  duty.idle_min = nan;
  EXPECT_NE(testing::inputErrorOf([&] { duty.validate(); }), "(no error)");
}

}  // namespace
}  // namespace ceilplan::mission
