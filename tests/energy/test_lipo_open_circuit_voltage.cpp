#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using ceilplan::energy::LipoOpenCircuitVoltage;

TEST(LipoOpenCircuitVoltage, HitsTheTablePointsOfReferenceSection6) {
  const LipoOpenCircuitVoltage ocv;
  EXPECT_DOUBLE_EQ(ocv.cellVoltageV(1.0), 4.173);
  EXPECT_DOUBLE_EQ(ocv.cellVoltageV(0.5), 3.742);
  EXPECT_DOUBLE_EQ(ocv.cellVoltageV(0.0769), 3.165);
  EXPECT_DOUBLE_EQ(ocv.cellVoltageV(0.02), 2.977);
}

TEST(LipoOpenCircuitVoltage, InterpolatesLinearlyBetweenPoints) {
  const LipoOpenCircuitVoltage ocv;
  EXPECT_NEAR(ocv.cellVoltageV((0.5 + 0.5385) / 2), (3.742 + 3.783) / 2, 1e-12);
}

TEST(LipoOpenCircuitVoltage, HoldsTheLowestPointBelowTwoPercent) {
  const LipoOpenCircuitVoltage ocv;
  EXPECT_DOUBLE_EQ(ocv.cellVoltageV(0.0), 2.977);
}

TEST(LipoOpenCircuitVoltage, NeverFallsWithRisingCharge) {
  const LipoOpenCircuitVoltage ocv;
  double previous = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double v = ocv.cellVoltageV(i / 1000.0);
    EXPECT_GE(v, previous);
    previous = v;
  }
}

TEST(LipoOpenCircuitVoltage, RefusesChargeOutsideZeroToOne) {
  const LipoOpenCircuitVoltage ocv;
  EXPECT_THROW(ocv.cellVoltageV(-0.01), ceilplan::InputError);
  EXPECT_THROW(ocv.cellVoltageV(1.01), ceilplan::InputError);
  EXPECT_THROW(ocv.cellVoltageV(std::nan("")), ceilplan::InputError);
}

TEST(LipoOpenCircuitVoltage, AsAFunctionOfSocItIsTheSameCheckedCurve) {
  const LipoOpenCircuitVoltage ocv;
  const auto cell_voltage_v = ceilplan::energy::lipoCellVoltageOfSoc();
  for (double soc : {0.0, 0.02, 0.5, 0.95, 1.0}) EXPECT_EQ(cell_voltage_v(soc), ocv.cellVoltageV(soc)) << soc;
  EXPECT_DOUBLE_EQ(cell_voltage_v(1.0), 4.173);
  EXPECT_THROW(cell_voltage_v(1.5), ceilplan::InputError);
}
