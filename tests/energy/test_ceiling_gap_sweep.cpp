// The current against the ceiling gap (energy::ceilingGapSweep, `ceilplan current --sweep`).

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/ceiling_gap_sweep.hpp"
#include "ceilplan/energy/paper_quad.hpp"

#include <gtest/gtest.h>

namespace ceilplan::energy {
namespace {

TEST(CeilingGapSweep, RunsFromTouchingTheCeilingToThreeRadiiAndTheCurrentRisesWithTheGap) {
  const EnergyModel model(paperQuadParameters());
  const FlightCondition hover;
  const std::vector<GapPoint> sweep = ceilingGapSweep(model, 1.0, hover);
  ASSERT_EQ(sweep.size(), 61u);
  EXPECT_EQ(sweep.front().gap_m, 0.0);
  EXPECT_DOUBLE_EQ(sweep.back().gap_m, 3.0 * model.rotorRadiusM());
  for (std::size_t i = 0; i < sweep.size(); ++i) {
    EXPECT_EQ(sweep[i].breakdown.current_a, model.currentA(sweep[i].gap_m, 1.0, hover)) << i;
    if (i > 0) {
      EXPECT_GE(sweep[i].breakdown.current_a, sweep[i - 1].breakdown.current_a) << i;
    }
  }
  EXPECT_LT(sweep.front().breakdown.current_a, sweep.back().breakdown.current_a);  // the ceiling effect
  EXPECT_EQ(ceilingGapSweep(model, 1.0, hover, 1.0, 4).size(), 5u);
}

TEST(CeilingGapSweep, RefusesAnEmptySweepAndBadInput) {
  const EnergyModel model(paperQuadParameters());
  EXPECT_THROW(ceilingGapSweep(model, 1.0, {}, 0.0), InputError);
  EXPECT_THROW(ceilingGapSweep(model, 1.0, {}, 3.0, 0), InputError);
  EXPECT_THROW(ceilingGapSweep(model, 1.5, {}), InputError);  // coverage outside [0, 1]
}

}  // namespace
}  // namespace ceilplan::energy
