// The ageing models against values derived from their published constants and hand-computed
// cases (docs/ageing.md).
#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace cb = ceilplan::battery;

namespace {

constexpr double kDay_s = 86400.0;

// Full cycles between `low` and `high`, starting and ending at `high`, all at time 0 (no
// calendar ageing).
std::vector<cb::AgeingSample> cyclesAtTimeZero(int cycles, double low, double high) {
  std::vector<cb::AgeingSample> samples{{0.0, high, 0.0}};
  for (int i = 0; i < cycles; ++i) {
    samples.push_back({0.0, low, 0.0});
    samples.push_back({0.0, high, 0.0});
  }
  return samples;
}

// The same history, as a pack at `state_of_health` would report it.
std::vector<cb::AgeingSample> atStateOfHealth(std::vector<cb::AgeingSample> samples, double state_of_health) {
  for (cb::AgeingSample& s : samples) s.state_of_health = state_of_health;
  return samples;
}

// One sample a day at a constant SOC.
std::vector<cb::AgeingSample> restingDays(int days, double soc) {
  std::vector<cb::AgeingSample> samples;
  for (int d = 0; d <= days; ++d) samples.push_back({d * kDay_s, soc, 0.0});
  return samples;
}

// A linear cell voltage, so that hand computations stay short: 3.0 V empty, 4.2 V full.
double linearCellVoltage(double soc) { return 3.0 + 1.2 * soc; }

// The paper's missions, coarsely: fly from 0.95 to `lowest`, idle, charge back, at 10.4 A.
std::vector<cb::AgeingSample> missions(int count, double lowest, double current_a) {
  std::vector<cb::AgeingSample> samples;
  double t = 0.0;
  for (int m = 0; m < count; ++m) {
    samples.push_back({t, 0.95, 0.0});
    samples.push_back({t + 600.0, 0.5 * (0.95 + lowest), current_a});
    samples.push_back({t + 1200.0, lowest, current_a});
    samples.push_back({t + 1500.0, lowest, 0.0});
    samples.push_back({t + 2600.0, 0.8, -10.4});
    samples.push_back({t + 3000.0, 0.95, -10.4});
    t += 5760.0;
  }
  return samples;
}

cb::AgeingModelOptions defaultOptions() {
  cb::AgeingModelOptions options;
  options.cell_voltage_of_soc = linearCellVoltage;
  return options;
}

}  // namespace

// ---- Xu et al. 2018 -------------------------------------------------------------------------

TEST(XuModel, StressFunctionsMatchTheirDefinitions) {
  EXPECT_DOUBLE_EQ(cb::xuDepthStress(1.0), 1.0 / 17000.0);
  EXPECT_DOUBLE_EQ(cb::xuDepthStress(1.2), cb::xuDepthStress(1.0));  // depth clamped to 1
  EXPECT_DOUBLE_EQ(cb::xuDepthStress(0.0), 0.0);
  EXPECT_DOUBLE_EQ(cb::xuSocStress(0.5), 1.0);
  EXPECT_DOUBLE_EQ(cb::xuSocStress(0.9), std::exp(1.04 * 0.4));
  EXPECT_DOUBLE_EQ(cb::xuTemperatureStress(298.15), 1.0);
  EXPECT_DOUBLE_EQ(cb::xuTemperatureStress(308.15), std::exp(0.0693 * 10.0 * 298.15 / 308.15));
  EXPECT_DOUBLE_EQ(cb::xuCapacityLoss(0.0), 0.0);
}

TEST(XuModel, CyclesToTwentyPercentLossMatchTheReference) {
  // No SEI term, mean SOC 0.5, 25 C: L = 1 - exp(-N S_d(d)) = 0.2.
  cb::XuParameters no_sei;
  no_sei.a_sei = 0.0;
  const double target = -std::log(0.8);
  EXPECT_EQ(std::lround(target / cb::xuDepthStress(1.0, no_sei)), 3793);
  EXPECT_EQ(std::lround(target / cb::xuDepthStress(0.5, no_sei)), 16764);
  EXPECT_EQ(std::lround(target / cb::xuDepthStress(0.2, no_sei)), 42521);
}

TEST(XuModel, CountedFullCyclesReachTwentyPercentWhereTheReferenceSays) {
  cb::XuParameters no_sei;
  no_sei.a_sei = 0.0;
  cb::XuAgeingModel half_depth(cb::OperatingConditions{}, no_sei);
  half_depth.addSamples(cyclesAtTimeZero(16764, 0.25, 0.75));  // depth 0.5, mean SOC 0.5
  EXPECT_NEAR(half_depth.capacityLoss(), 1.0 - std::exp(-16764.0 * cb::xuDepthStress(0.5)), 1e-12);
  EXPECT_NEAR(half_depth.capacityLoss(), 0.2, 1e-5);
  cb::XuAgeingModel full_depth(cb::OperatingConditions{}, no_sei);
  full_depth.addSamples(cyclesAtTimeZero(3793, 0.0, 1.0));
  EXPECT_NEAR(full_depth.capacityLoss(), 0.2, 1e-4);
}

TEST(XuModel, SeiPhaseAddsItsShareEarly) {
  // With the SEI term a small damage costs far more: L(0.01) = 1 - a e^-1.21 - (1 - a) e^-0.01.
  const double expected = 1.0 - 0.0575 * std::exp(-1.21) - 0.9425 * std::exp(-0.01);
  EXPECT_DOUBLE_EQ(cb::xuCapacityLoss(0.01), expected);
  EXPECT_GT(cb::xuCapacityLoss(0.01), 0.03);
}

TEST(XuModel, CalendarTermUsesTimeAveragedSocAndTemperature) {
  const auto conditions = cb::OperatingConditions::fromCelsius(35.0);
  cb::XuAgeingModel model(conditions);
  model.addSamples(restingDays(365, 0.8));
  const double f_t = 4.14e-10 * 365 * kDay_s * std::exp(1.04 * 0.3) * cb::xuTemperatureStress(conditions.temperature_k);
  EXPECT_NEAR(model.calendarDamage(), f_t, 1e-15);
  EXPECT_DOUBLE_EQ(model.cycleDamage(), 0.0);
  EXPECT_NEAR(model.capacityLoss(), cb::xuCapacityLoss(f_t), 1e-15);
}

TEST(XuModel, PaperScenarioCycleDamageFallsMoreThanFec) {
  // Derived from the published constants: with the ceiling effect Xu's cycle damage falls 18.2 %, the FEC 15.8 %.
  cb::XuAgeingModel free_flight, ceiling;
  free_flight.addSamples(missions(450, 0.341, 9.5));
  ceiling.addSamples(missions(450, 0.437, 8.0));
  const double reduction = 1.0 - ceiling.cycleDamage() / free_flight.cycleDamage();
  EXPECT_NEAR(reduction, 0.182, 0.001);
}

// ---- Schmalstieg et al. 2014 ------------------------------------------------------------------

TEST(SchmalstiegModel, RatesMatchThePublishedForms) {
  EXPECT_DOUBLE_EQ(cb::schmalstiegCalendarCapacityRate(3.7, 308.15),
                   (7.543 * 3.7 - 23.75) * 1e6 * std::exp(-6976.0 / 308.15));
  EXPECT_NEAR(cb::schmalstiegCalendarCapacityRate(3.7, 308.15), 6.1277e-4, 1e-8);
  EXPECT_DOUBLE_EQ(cb::schmalstiegCalendarCapacityRate(3.0, 308.15), 0.0);  // clamped
  EXPECT_DOUBLE_EQ(cb::schmalstiegCycleCapacityRate(3.8, 0.6), 7.348e-3 * 0.133 * 0.133 + 7.60e-4 + 4.081e-3 * 0.6);
  EXPECT_DOUBLE_EQ(cb::schmalstiegCalendarResistanceRate(3.7, 308.15),
                   (5.270 * 3.7 - 16.32) * 1e5 * std::exp(-5986.0 / 308.15));
  EXPECT_DOUBLE_EQ(cb::schmalstiegCycleResistanceRate(3.725, 0.0), -1.521e-5);
}

TEST(SchmalstiegModel, PowerLawStateChainsExactlyUnderConstantStress) {
  double state = 0.0;
  for (int day = 0; day < 100; ++day) state = cb::advancePowerLawState(state, 2e-3, 0.75, 1.0);
  EXPECT_NEAR(state, 2e-3 * std::pow(100.0, 0.75), 1e-12);
  EXPECT_DOUBLE_EQ(cb::advancePowerLawState(0.01, 0.0, 0.75, 5.0), 0.01);  // no stress
}

TEST(SchmalstiegModel, CalendarLossAtConstantSocIsACapTimesDaysToThe075) {
  const auto conditions = cb::OperatingConditions::fromCelsius(35.0);
  cb::SchmalstiegAgeingModel model(conditions, linearCellVoltage);
  model.addSamples(restingDays(200, 0.5));  // 3.6 V
  const double a_cap = (7.543 * 3.6 - 23.75) * 1e6 * std::exp(-6976.0 / 308.15);
  const double a_res = (5.270 * 3.6 - 16.32) * 1e5 * std::exp(-5986.0 / 308.15);
  EXPECT_NEAR(model.capacityLoss(), a_cap * std::pow(200.0, 0.75), 1e-12);
  EXPECT_NEAR(model.resistanceGrowth(), a_res * std::pow(200.0, 0.75), 1e-12);
  EXPECT_DOUBLE_EQ(model.cycleCapacityLoss(), 0.0);
}

TEST(SchmalstiegModel, CycleLossIsBCapTimesSqrtOfThroughput) {
  cb::SchmalstiegAgeingModel model(cb::OperatingConditions::fromCelsius(35.0), linearCellVoltage);
  const int cycles = 500;
  model.addSamples(cyclesAtTimeZero(cycles, 0.2, 0.8));  // DoD 0.6, mean 0.5
  // V = 3 + 1.2 s over s in [0.2, 0.8]: Vrms^2 = (1/0.6) * integral of V^2 ds.
  const auto antiderivative = [](double s) { return std::pow(3.0 + 1.2 * s, 3) / (3.0 * 1.2); };
  const double vrms = std::sqrt((antiderivative(0.8) - antiderivative(0.2)) / 0.6);
  EXPECT_NEAR(model.rmsCellVoltage(0.5, 0.6), vrms, 1e-12);
  const double q_ah = 2.0 * cycles * 0.6 * 2.15;
  const double b_cap = 7.348e-3 * std::pow(vrms - 3.667, 2) + 7.60e-4 + 4.081e-3 * 0.6;
  const double b_res = 2.153e-4 * std::pow(vrms - 3.725, 2) - 1.521e-5 + 2.798e-4 * 0.6;
  EXPECT_NEAR(model.capacityLoss(), b_cap * std::sqrt(q_ah), 1e-12);
  EXPECT_NEAR(model.resistanceGrowth(), b_res * q_ah, 1e-12);
  EXPECT_DOUBLE_EQ(model.calendarCapacityLoss(), 0.0);
}

TEST(SchmalstiegModel, ThroughputCountsNominalCapacitiesWhileDepthStaysTheFadedPacks) {
  // At SOH 0.8 the same SOC swings move 0.8 times the charge: Q scales by 0.8, so the sqrt(Q)
  // capacity term by sqrt(0.8) and the linear resistance term by 0.8. The stress (DoD 0.6,
  // Vrms) is the swing the faded cell really sees, so b_cap and b_res stay.
  const auto conditions = cb::OperatingConditions::fromCelsius(35.0);
  cb::SchmalstiegAgeingModel new_pack(conditions, linearCellVoltage), faded(conditions, linearCellVoltage);
  new_pack.addSamples(cyclesAtTimeZero(500, 0.2, 0.8));
  faded.addSamples(atStateOfHealth(cyclesAtTimeZero(500, 0.2, 0.8), 0.8));
  EXPECT_NEAR(faded.chargeThroughputAh(), 0.8 * 2.0 * 500 * 0.6 * 2.15, 1e-9);
  EXPECT_NEAR(faded.cycleCapacityLoss(), std::sqrt(0.8) * new_pack.cycleCapacityLoss(), 1e-12);
  EXPECT_NEAR(faded.resistanceGrowth(), 0.8 * new_pack.resistanceGrowth(), 1e-12);
}

TEST(SchmalstiegModel, EachSwingCountsAtTheStateOfHealthItWasMadeAt) {
  // 10 cycles new, then 10 at SOH 0.5, all of depth 0.6 (constant stress, so the chained law is
  // exactly b_cap sqrt(Q)): Q = 2.15 Ah * 0.6 * (20 swings * 1 + 20 swings * 0.5).
  const auto conditions = cb::OperatingConditions::fromCelsius(35.0);
  cb::SchmalstiegAgeingModel model(conditions, linearCellVoltage);
  std::vector<cb::AgeingSample> history = cyclesAtTimeZero(20, 0.2, 0.8);
  for (std::size_t i = 21; i < history.size(); ++i) history[i].state_of_health = 0.5;
  // Fed in pieces that split the change, to show the model keeps what it needs between pieces.
  model.addSamples(history.data(), 15);
  model.addSamples(history.data() + 15, history.size() - 15);
  const double q_ah = 2.15 * 0.6 * (20 * 1.0 + 20 * 0.5);
  EXPECT_NEAR(model.chargeThroughputAh(), q_ah, 1e-12);
  const double vrms = model.rmsCellVoltage(0.5, 0.6);
  const double b_cap = 7.348e-3 * std::pow(vrms - 3.667, 2) + 7.60e-4 + 4.081e-3 * 0.6;
  EXPECT_NEAR(model.cycleCapacityLoss(), b_cap * std::sqrt(q_ah), 1e-12);
}

TEST(SchmalstiegModel, RejectsAPackVoltageGivenForACell) {
  cb::SchmalstiegAgeingModel model(cb::OperatingConditions{}, [](double soc) {
    return 4.0 * linearCellVoltage(soc);  // a 4S pack's voltage
  });
  try {
    model.addSamples(restingDays(2, 0.5));
    FAIL() << "pack voltage accepted";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("single cell"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cb::SchmalstiegAgeingModel(cb::OperatingConditions{}, nullptr), ceilplan::InputError);
}

// ---- Woehler + Miner, FEC baseline -------------------------------------------------------------

TEST(WoehlerModel, MinersRuleOverRainflowCycles) {
  cb::WoehlerParameters p;  // N100 300, k 1.5, end of life at 20 % loss
  EXPECT_DOUBLE_EQ(cb::woehlerCyclesToEndOfLife(1.0, p), 300.0);
  EXPECT_DOUBLE_EQ(cb::woehlerCyclesToEndOfLife(0.5, p), 300.0 * std::pow(0.5, -1.5));
  EXPECT_TRUE(std::isinf(cb::woehlerCyclesToEndOfLife(0.0, p)));
  cb::WoehlerAgeingModel model(p);
  model.addSamples(cyclesAtTimeZero(10, 0.45, 0.95));
  const double damage = 10.0 / (300.0 * std::pow(0.5, -1.5));
  EXPECT_NEAR(model.damage(), damage, 1e-12);
  EXPECT_NEAR(model.capacityLoss(), 0.2 * damage, 1e-12);
}

TEST(WoehlerModel, RejectsNonsenseParameters) {
  cb::WoehlerParameters p;
  p.cycles_at_full_depth = 0.0;
  EXPECT_THROW(cb::WoehlerAgeingModel{p}, ceilplan::InputError);
  p = {};
  p.exponent = -1.0;
  EXPECT_THROW(cb::FecAgeingModel{p}, ceilplan::InputError);
}

TEST(FecModel, LossIsProportionalToFullEquivalentCycles) {
  cb::FecAgeingModel model;
  model.addSamples(missions(15, 0.341, 9.5));
  // Each mission swings 0.95 -> 0.341 -> 0.95: FEC 0.609 (the paper's 0.6090 per mission).
  EXPECT_NEAR(model.fullEquivalentCycles(), 15 * 0.609, 1e-12);
  EXPECT_NEAR(model.capacityLoss(), 0.2 * 15 * 0.609 / 300.0, 1e-12);
}

TEST(FecModel, CountsTheChargeMovedAgainstTheNominalCapacity) {
  // Kocer et al. 2019, eq. 3-6: FEC = integral |i| dt / (2 C_nom). A pack at SOH 0.8 that swings
  // 0.95 -> 0.341 -> 0.95 moved 0.8 * 1.218 nominal capacities, so 0.8 * 0.609 FEC a mission.
  cb::FecAgeingModel model;
  model.addSamples(atStateOfHealth(missions(15, 0.341, 9.5), 0.8));
  EXPECT_NEAR(model.fullEquivalentCycles(), 0.8 * 15 * 0.609, 1e-12);
  EXPECT_EQ(model.cycleWearName(), "FEC");
}

TEST(AgeingModels, DepthStressModelsWeighTheFadedPacksOwnSwings) {
  // Xu and Woehler count rainflow cycles of the SOC: a cycle's depth is the stress the cell sees,
  // whatever its capacity, so a faded pack's swings count as they are.
  for (const std::string name : {"xu", "woehler"}) {
    const auto new_pack = cb::makeAgeingModel(name, defaultOptions());
    const auto faded = cb::makeAgeingModel(name, defaultOptions());
    new_pack->addSamples(missions(15, 0.341, 9.5));
    faded->addSamples(atStateOfHealth(missions(15, 0.341, 9.5), 0.8));
    EXPECT_DOUBLE_EQ(faded->cycleWear(), new_pack->cycleWear()) << name;
  }
}

// ---- The common interface ---------------------------------------------------------------------

TEST(AgeingModels, FeedingInPiecesEqualsFeedingAtOnce) {
  const unsigned seed = 7;
  std::mt19937 rng(seed);
  const auto samples = missions(300, 0.35, 9.5);
  for (const auto& name : cb::ageingModelNames()) {
    const auto whole = cb::makeAgeingModel(name, defaultOptions());
    whole->addSamples(samples);
    const auto pieces = cb::makeAgeingModel(name, defaultOptions());
    std::uniform_int_distribution<std::size_t> piece(1, 20);
    std::size_t done = 0;
    while (done < samples.size()) {
      const std::size_t n = std::min(piece(rng), samples.size() - done);
      pieces->addSamples(samples.data() + done, n);
      done += n;
    }
    EXPECT_DOUBLE_EQ(pieces->capacityLoss(), whole->capacityLoss()) << name << ", seed " << seed;
    EXPECT_GT(whole->capacityLoss(), 0.0) << name;
  }
}

TEST(AgeingModels, OpenRangesCountAsHalfCycles) {
  cb::WoehlerParameters p;
  p.exponent = 0.0;  // every cycle costs 1/N100, whatever its depth
  cb::WoehlerAgeingModel model(p);
  model.addSamples({{0.0, 0.9, 0.0}, {1.0, 0.3, 0.0}});  // one open half cycle
  EXPECT_DOUBLE_EQ(model.damage(), 0.5 / 300.0);
  model.addSamples({{2.0, 0.9, 0.0}});
  EXPECT_DOUBLE_EQ(model.damage(), 1.0 / 300.0);
}

TEST(AgeingModels, BadSamplesAreRejectedBeforeAnyIsUsed) {
  for (const auto& name : cb::ageingModelNames()) {
    const auto model = cb::makeAgeingModel(name, defaultOptions());
    model->addSamples({{0.0, 0.9, 1.0}, {10.0, 0.5, 1.0}});
    const double before = model->capacityLoss();
    EXPECT_THROW(model->addSamples({{20.0, 0.4, 1.0}, {30.0, 1.2, 1.0}}), ceilplan::InputError);
    EXPECT_THROW(model->addSamples({{20.0, 0.4, 1.0}, {30.0, -0.1, 1.0}}), ceilplan::InputError);
    EXPECT_THROW(model->addSamples({{20.0, std::nan(""), 1.0}}), ceilplan::InputError);
    EXPECT_THROW(model->addSamples({{20.0, 0.4, INFINITY}}), ceilplan::InputError);
    EXPECT_THROW(model->addSamples({{20.0, 0.4, 1.0, 0.0}}), ceilplan::InputError);
    EXPECT_THROW(model->addSamples({{20.0, 0.4, 1.0, 1.2}}), ceilplan::InputError);
    EXPECT_THROW(model->addSamples({{20.0, 0.4, 1.0, std::nan("")}}), ceilplan::InputError);
    try {
      model->addSamples({{5.0, 0.4, 1.0}});
      FAIL() << name << ": time going backwards accepted";
    } catch (const ceilplan::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("backwards"), std::string::npos) << e.what();
    }
    EXPECT_EQ(model->samplesSeen(), 2u) << name;
    EXPECT_DOUBLE_EQ(model->capacityLoss(), before) << name;
  }
}

TEST(AgeingModels, CloneContinuesIndependently) {
  const auto samples = missions(20, 0.35, 9.5);
  const auto model = cb::makeAgeingModel("xu", defaultOptions());
  model->addSamples(samples.data(), 60);
  const auto copy = model->clone();
  model->addSamples(samples.data() + 60, samples.size() - 60);
  EXPECT_EQ(copy->samplesSeen(), 60u);
  EXPECT_LT(copy->capacityLoss(), model->capacityLoss());
  copy->addSamples(samples.data() + 60, samples.size() - 60);
  EXPECT_DOUBLE_EQ(copy->capacityLoss(), model->capacityLoss());
}

TEST(AgeingModels, FactoryKnowsEachModelByName) {
  for (const auto& name : cb::ageingModelNames()) EXPECT_EQ(cb::makeAgeingModel(name, defaultOptions())->name(), name);
  try {
    cb::makeAgeingModel("wang", defaultOptions());
    FAIL() << "unknown model accepted";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("fec, xu, schmalstieg, woehler"), std::string::npos);
  }
  EXPECT_THROW(cb::makeAgeingModel("schmalstieg", cb::AgeingModelOptions{}), ceilplan::InputError);
}

TEST(OperatingConditions, CelsiusOverOneHundredFiftyLooksLikeKelvin) {
  EXPECT_DOUBLE_EQ(cb::OperatingConditions::fromCelsius(25.0).temperature_k, 298.15);
  try {
    cb::OperatingConditions::fromCelsius(298.15);
    FAIL() << "kelvin accepted as Celsius";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("kelvin"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cb::OperatingConditions::fromCelsius(-300.0), ceilplan::InputError);
  EXPECT_THROW(cb::OperatingConditions::fromCelsius(std::nan("")), ceilplan::InputError);
  EXPECT_THROW(cb::XuAgeingModel(cb::OperatingConditions{-5.0, ""}), ceilplan::InputError);
}

TEST(OperatingConditions, StudiesOutsideAModelsRangeCarryWarnings) {
  cb::OperatingConditions lipo_at_25c = cb::OperatingConditions::fromCelsius(25.0);
  lipo_at_25c.chemistry = "LiPo";
  const auto model = cb::makeAgeingModel("schmalstieg", defaultOptions());
  model->addSamples(missions(2, 0.35, 9.5));
  EXPECT_DOUBLE_EQ(model->observedCRates(5.2).charge, 2.0);
  const auto warnings = cb::validityWarnings(*model, lipo_at_25c, 5.2);
  ASSERT_EQ(warnings.size(), 3u);  // chemistry, charge rate, discharge rate; 25 C is inside
  EXPECT_NE(warnings[0].find("NMC"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[1].find("charge rate 2C"), std::string::npos) << warnings[1];

  cb::OperatingConditions nmc_at_60c = cb::OperatingConditions::fromCelsius(60.0);
  nmc_at_60c.chemistry = "nmc";
  const auto hot = cb::validityWarnings("schmalstieg", model->validity(), nmc_at_60c, {0.5, 0.5});
  ASSERT_EQ(hot.size(), 1u);
  EXPECT_NE(hot[0].find("temperature 60 C"), std::string::npos) << hot[0];

  const auto fec = cb::makeAgeingModel("fec", defaultOptions());
  fec->addSamples(missions(2, 0.35, 9.5));
  EXPECT_TRUE(cb::validityWarnings(*fec, lipo_at_25c, 5.2).empty());
}

TEST(AgeingModels, CapacityLossStopsAtTheWholeCapacity) {
  cb::WoehlerParameters p;
  p.cycles_at_full_depth = 10.0;
  cb::WoehlerAgeingModel model(p);
  model.addSamples(cyclesAtTimeZero(100, 0.0, 1.0));
  EXPECT_DOUBLE_EQ(model.damage(), 10.0);       // Miner's sum goes on...
  EXPECT_DOUBLE_EQ(model.capacityLoss(), 1.0);  // ...the capacity lost cannot exceed it all
}
