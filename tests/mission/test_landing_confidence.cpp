// Landing confidence (battery.reserve_confidence): the linearised odds of landing above the
// reserve are what a normal landing SOC gives, a sortie short of the asked confidence is not
// flown (so sorties get shorter or more numerous, never below it), and a Monte Carlo check over
// the flight record with another seed agrees with the linearisation within its sampling error.
// Gusts (wind.gust_m_s) mix the landing SOC over the charge each gust costs, flown by the model.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/landing_confidence.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace ceilplan::mission {
namespace {

const std::filesystem::path kBridge = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml";

// One fitted parameter (hover power) with a standard error of `se_w`, and a residual current.
energy::FitUncertainty hoverOnly(double se_w, double residual_a) {
  energy::FitUncertainty fit;
  fit.samples = 100;
  fit.residual_std_a = residual_a;
  fit.residual_rms_a = residual_a;
  fit.parameters = {energy::FreeParameter::kHoverPowerW};
  fit.covariance = {{se_w * se_w}};
  fit.standard_errors = {se_w};
  return fit;
}

TEST(LandingConfidence, TheOddsAreThoseOfANormalLandingSoc) {
  // 0.1 Ah per W of hover power, SE 0.1 W: 0.01 Ah; the residual 0.36 A over 100 s: 0.01 Ah.
  ChargeSensitivity sensitivity{{0.1}, 100.0, {}};
  const energy::FitUncertainty fit = hoverOnly(0.1, 0.36);
  EXPECT_NEAR(chargeVarianceAh2(sensitivity, fit), 2e-4, 1e-12);
  const double std_soc = std::sqrt(2e-4) / 1.0;  // a 1 Ah pack
  const LandingOdds odds = landingOdds(0.30, sensitivity, fit, 1.0, 0.25);
  EXPECT_NEAR(odds.soc_std, std_soc, 1e-12);
  EXPECT_NEAR(odds.p_land_above_reserve, 0.5 * std::erfc(-(0.05 / std_soc) / std::sqrt(2.0)), 1e-9);
  EXPECT_NEAR(odds.soc_p01, 0.30 - 2.3263478740 * std_soc, 1e-8);
  // The effective reserve is where the odds are exactly the confidence.
  const double effective = effectiveReserveSoc(0.25, 0.99, sensitivity, fit, 1.0);
  EXPECT_NEAR(landingOdds(effective, sensitivity, fit, 1.0, 0.25).p_land_above_reserve, 0.99, 1e-9);
}

// Targets 10 m apart on a line; legs draw 0.01 Ah per metre and a second per metre, and each
// target's 432 s dwell 1.2 Ah: the charge's sensitivity to the hover power is its share per watt.
TourCosts lineTour(int targets, const energy::FitUncertainty& fit) {
  TourCosts tour;
  tour.names.push_back("home");
  for (int k = 1; k <= targets; ++k) tour.names.push_back("t" + std::to_string(k));
  const int n = targets + 1;
  tour.legs = PairTable<LegCost>(n);
  tour.dwells.assign(static_cast<std::size_t>(n), Dwell{432.0, 10.0, std::nullopt, {{1.2 / 100.0}, 432.0, {}}});
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      LegCost& leg = tour.legs[i][j];
      const double metres = 10.0 * std::abs(i - j);
      leg.charge_ah = 0.01 * metres;
      leg.duration_s = metres;
      leg.mean_current_a = metres > 0 ? leg.charge_ah * 3600 / metres : 0.0;
      leg.sensitivity = {{leg.charge_ah / 100.0}, leg.duration_s, {}};
    }
  tour.uncertainty = fit;
  return tour;
}

std::vector<int> inOrder(int targets) {
  std::vector<int> order(static_cast<std::size_t>(targets));
  for (int k = 0; k < targets; ++k) order[static_cast<std::size_t>(k)] = k + 1;
  return order;
}

TEST(LandingConfidence, ASortieShortOfTheConfidenceIsNotFlown) {
  const TourCosts tour = lineTour(4, hoverOnly(20.0, 0.3));  // 20 % of a 100 W hover power
  BatterySpec battery;
  SortieOptions options;
  options.ageing_model = "fec";
  const SortiePlan plain = planSorties(tour, inOrder(4), battery, options);
  battery.reserve_confidence = 0.99;
  const SortiePlan sure = planSorties(tour, inOrder(4), battery, options);
  // Two targets a sortie land at 41 % planned, with a standard deviation of 11 %: 93 % above 25 %.
  ASSERT_EQ(plain.sorties.size(), 2u);
  ASSERT_LT(plain.sorties[0].landing->p_land_above_reserve, 0.99);
  EXPECT_GT(sure.sorties.size(), plain.sorties.size());
  for (const Sortie& sortie : sure.sorties) {
    ASSERT_TRUE(sortie.landing.has_value());
    EXPECT_GE(sortie.landing->p_land_above_reserve, 0.99 - 1e-9);
    EXPECT_GE(sortie.lowest_soc, battery.reserve_soc);
  }
  EXPECT_NE(sure.sorties.back().reason.find("reserve with probability 0.99"), std::string::npos)
      << sure.sorties.back().reason;
  // The split points' search (a large tour's) keeps the same test.
  options.split_points = {0, 1, 2, 3};
  for (const Sortie& sortie : planSorties(tour, inOrder(4), battery, options).sorties)
    EXPECT_GE(sortie.landing->p_land_above_reserve, 0.99 - 1e-9);
}

// The charge a stretch draws in each gust point's wind, `per_sigma_ah` per standard deviation.
std::vector<double> linearGustCharges(double per_sigma_ah) {
  std::vector<double> charges(kGustPoints);
  for (int i = 0; i < kGustPoints; ++i) charges[static_cast<std::size_t>(i)] = per_sigma_ah * gustPointSigma(i);
  return charges;
}

TEST(LandingConfidence, AGustWhoseChargeIsLinearInTheWindsSpeedAddsItsVarianceAsANormalDoes) {
  // As above, plus 0.01 Ah per standard deviation of the gust: the landing SOC is normal with
  // variance 2e-4 + 1e-4 (the mixture, integrated over +-4 standard deviations of the gust).
  const energy::FitUncertainty fit = hoverOnly(0.1, 0.36);
  const ChargeSensitivity calm{{0.1}, 100.0, {}};
  const ChargeSensitivity gusty{{0.1}, 100.0, linearGustCharges(0.01)};
  EXPECT_EQ(chargeVarianceAh2(gusty, fit), chargeVarianceAh2(calm, fit));
  const double std_soc = std::sqrt(3e-4);
  const LandingOdds odds = landingOdds(0.30, gusty, fit, 1.0, 0.25);
  EXPECT_NEAR(odds.soc_std, std_soc, 1e-5);
  EXPECT_NEAR(odds.p_land_above_reserve, 0.5 * std::erfc(-(0.05 / std_soc) / std::sqrt(2.0)), 1e-4);
  EXPECT_NEAR(odds.soc_p01, 0.30 - 2.3263478740 * std_soc, 1e-4);
  EXPECT_EQ(landingProbability(0.30, gusty, fit, 1.0, 0.25), odds.p_land_above_reserve);
  // A planned split sees the gust: a higher effective reserve, where the odds are the confidence.
  const double effective = effectiveReserveSoc(0.25, 0.99, gusty, fit, 1.0);
  EXPECT_GT(effective, effectiveReserveSoc(0.25, 0.99, calm, fit, 1.0));
  EXPECT_NEAR(landingProbability(effective, gusty, fit, 1.0, 0.25), 0.99, 1e-9);
  EXPECT_TRUE(meetsConfidence(effective + 1e-6, 0.99, gusty, fit, 1.0, 0.25));
  EXPECT_FALSE(meetsConfidence(effective - 1e-6, 0.99, gusty, fit, 1.0, 0.25));
  // The gust lasts the sortie: consecutive stretches' gust charges add point by point.
  ChargeSensitivity sortie = gusty;
  sortie += gusty;
  sortie += calm;
  EXPECT_EQ(sortie.gust_charge_ah, linearGustCharges(0.02));
  ChargeSensitivity from_calm = calm;
  from_calm += gusty;
  EXPECT_EQ(from_calm.gust_charge_ah, gusty.gust_charge_ah);
}

TEST(LandingConfidence, ALullCostsMoreThanTheLinearisedGustNearTheMinimumPowerAirspeed) {
  // A gust that costs nothing to first order but more on either side (a convex charge, as near
  // the minimum-power airspeed): a variance from dQ/dw alone would be 0, the mixture is not.
  const energy::FitUncertainty fit = hoverOnly(0.1, 0.36);
  ChargeSensitivity convex{{0.1}, 100.0, {}};
  for (int i = 0; i < kGustPoints; ++i) convex.gust_charge_ah.push_back(0.01 * gustPointSigma(i) * gustPointSigma(i));
  const LandingOdds calm = landingOdds(0.30, ChargeSensitivity{{0.1}, 100.0, {}}, fit, 1.0, 0.25);
  const LandingOdds odds = landingOdds(0.30, convex, fit, 1.0, 0.25);
  EXPECT_LT(odds.p_land_above_reserve, calm.p_land_above_reserve - 0.01);
  EXPECT_LT(odds.soc_p01, calm.soc_p01 - 0.005);
  EXPECT_GT(odds.soc_std, calm.soc_std);
}

TEST(LandingConfidence, HoveringInWindTheChargeFallsWithTheWindBelowTheMinimumPowerAirspeedAndRisesPastIt) {
  // The default quad's power is least near 8-9 m/s of airspeed (docs/models.md, "Wind").
  const energy::EnergyModel model(energy::paperQuadParameters());
  planner::PathSample hover;
  hover.ceiling_gap_m = energy::kNoSurface;
  hover.ground_gap_m = energy::kNoSurface;
  hover.soc = 0.8;
  SortieWind wind;
  wind.wind.from_deg = 90.0;
  wind.wind.gust_m_s = 1.0;
  // The charge of a 600 s hover drawing 1 Ah in the mean wind, in a gust of `sigma` standard deviations.
  const auto gustCharge = [&](double speed_m_s, double sigma) {
    wind.wind.speed_m_s = speed_m_s;
    const ChargeSensitivity s = steadyChargeSensitivity(model, hover, 1.0, 600.0, hoverOnly(1.0, 0.1), wind);
    EXPECT_EQ(s.gust_charge_ah.size(), static_cast<std::size_t>(kGustPoints));
    for (int i = 0; i < kGustPoints; ++i)
      if (gustPointSigma(i) == sigma) return s.gust_charge_ah[static_cast<std::size_t>(i)];
    ADD_FAILURE() << "no gust point at " << sigma;
    return 0.0;
  };
  EXPECT_EQ(gustCharge(4.0, 0.0), 0.0);
  EXPECT_LT(gustCharge(4.0, 1.0), 0.0);
  EXPECT_GT(gustCharge(4.0, -1.0), 0.0);
  EXPECT_GT(gustCharge(12.0, 1.0), 0.0);
  EXPECT_LT(gustCharge(12.0, -1.0), 0.0);
  // Near the minimum, a lull of 3 m/s costs more than the same gust saves.
  EXPECT_GT(gustCharge(8.0, -3.0) + gustCharge(8.0, 3.0), 0.0);
  // Fully sheltered, the hover meets no wind and no gust.
  wind.share = [](const planner::PathSample&) { return 0.0; };
  EXPECT_EQ(gustCharge(12.0, 1.0), 0.0);
  EXPECT_EQ(gustCharge(12.0, -4.0), 0.0);
}

TEST(LandingConfidence, AConfidenceWithoutTheVehiclesUncertaintyIsRefused) {
  TourCosts tour = lineTour(2, hoverOnly(1.0, 0.1));
  tour.uncertainty.reset();
  BatterySpec battery;
  battery.reserve_confidence = 0.99;
  try {
    planSorties(tour, inOrder(2), battery);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs the calibrated vehicle's uncertainty"), std::string::npos) << e.what();
  }
  // Gusts alone do not make a confidence: the uncalibrated model's own error is unknown.
  for (Dwell& dwell : tour.dwells) dwell.sensitivity.gust_charge_ah = linearGustCharges(0.01);
  EXPECT_THROW(planSorties(tour, inOrder(2), battery), InputError);
  // Gust charges at other points than the gust points are refused before the split.
  tour.uncertainty = hoverOnly(1.0, 0.1);
  tour.dwells[1].sensitivity.gust_charge_ah.pop_back();
  try {
    planSorties(tour, inOrder(2), battery);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dwell at 't1' has 16 gust charges, not 0 or 17"), std::string::npos)
        << e.what();
  }
  battery.reserve_confidence = 1.0;
  EXPECT_THROW(battery.validate(), InputError);
}

// The bridge with a 0.75 Ah pack (two sorties without confidence) and a vehicle calibrated to
// 3 % on hover power and 10 % on the ceiling constants, with a 0.3 A residual.
Mission calibratedBridge() {
  Mission mission = io::readMission(kBridge);
  mission.battery.pack.capacity_ah = 0.75;
  mission.planning.ageing_model = "fec";
  energy::FitUncertainty fit;
  fit.samples = 200;
  fit.residual_std_a = 0.3;
  fit.residual_rms_a = 0.3;
  const energy::EnergyParameters& p = mission.vehicle.energy;
  fit.parameters = {energy::FreeParameter::kHoverPowerW, energy::FreeParameter::kK1, energy::FreeParameter::kK2M};
  const double se[] = {0.03 * p.rotor.hover_power_w, 0.1 * p.ceiling.k1, 0.1 * p.ceiling.k2_m};
  fit.covariance = {{se[0] * se[0], 0, 0}, {0, se[1] * se[1], 0}, {0, 0, se[2] * se[2]}};
  fit.standard_errors = {se[0], se[1], se[2]};
  mission.vehicle.calibration = fit;
  return mission;
}

TEST(LandingConfidenceBridge, EverySortieLandsAboveTheReserveWithTheAskedProbabilityAndSamplingAgrees) {
  Mission mission = calibratedBridge();
  const TourResult plain = planTour(mission, PlanningContext(mission), FlightMode::Ceiling);
  mission.battery.reserve_confidence = 0.99;
  const PlanningContext context(mission);
  const TourResult sure = planTour(mission, context, FlightMode::Ceiling);

  EXPECT_GE(sure.plan.sorties.size(), plain.plan.sorties.size());
  bool some_plain_sortie_short = false;
  for (const Sortie& sortie : plain.plan.sorties)
    some_plain_sortie_short = some_plain_sortie_short || sortie.landing->p_land_above_reserve < 0.99;
  EXPECT_TRUE(some_plain_sortie_short) << "the confidence does not bind on this tour: the test would show nothing";

  // 20000 draws with a seed other than the tour's: the estimate's binomial standard deviation is
  // sqrt(p (1 - p) / N), 0.0007 at p = 0.99. Agreement within 4 of them, plus 0.002 for what
  // the linearisation leaves out (the current's curvature in the parameters).
  constexpr int kDraws = 20000;
  for (std::size_t k = 0; k < sure.plan.sorties.size(); ++k) {
    SCOPED_TRACE("sortie " + std::to_string(k + 1));
    const Sortie& sortie = sure.plan.sorties[k];
    ASSERT_TRUE(sortie.landing.has_value());
    EXPECT_GE(sortie.landing->p_land_above_reserve, 0.99 - 1e-9);
    EXPECT_GE(sortie.lowest_soc, mission.battery.reserve_soc);
    ASSERT_TRUE(sortie.sampled_landing.has_value());
    EXPECT_EQ(sortie.sampled_landing->seed, mission.planning.seed);
    const SampledLanding check = sampleLanding(context.energy(), sure.record.sorties[k].samples, sortie.lowest_soc,
                                               mission.battery.pack.usableCapacityAh(), mission.battery.reserve_soc,
                                               *mission.vehicle.calibration, kDraws, mission.planning.seed + 7919);
    const double p = sortie.landing->p_land_above_reserve;
    const double binomial_std = std::sqrt(p * (1.0 - p) / kDraws);
    EXPECT_NEAR(check.p_land_above_reserve, p, 4.0 * binomial_std + 0.002);
    EXPECT_NEAR(check.soc_p01, sortie.landing->soc_p01, 0.005);
  }
}

// The calibrated bridge in an 8 m/s wind along the deck with 3 m/s gusts. 8 m/s is near the
// quad's minimum-power airspeed, where the charge barely moves with the wind's speed to first
// order (dQ/dw is about -2e-4 Ah per m/s a sortie) but rises steeply in a lull: a linearised gust
// term understated the lull (p 0.9997 against 0.943 sampled: docs/models.md, "Landing
// confidence"). Flown at the gust points, the odds meet the sampled check at 3 m/s too.
TEST(LandingConfidenceBridge, InGustsTheOddsMeetTheConfidenceAndSamplingAgrees) {
  Mission mission = calibratedBridge();
  mission.planning.wind.speed_m_s = 8.0;
  mission.planning.wind.from_deg = 90.0;
  mission.planning.wind.gust_m_s = 3.0;
  mission.battery.reserve_confidence = 0.99;
  const PlanningContext context(mission);
  const TourResult sure = planTour(mission, context, FlightMode::Ceiling);
  const energy::FitUncertainty& fit = *mission.vehicle.calibration;
  const double usable_ah = mission.battery.pack.usableCapacityAh();
  const double reserve = mission.battery.reserve_soc;

  constexpr int kDraws = 20000;  // as above: 4 binomial standard deviations plus 0.002
  for (std::size_t k = 0; k < sure.plan.sorties.size(); ++k) {
    SCOPED_TRACE("sortie " + std::to_string(k + 1));
    const Sortie& sortie = sure.plan.sorties[k];
    ASSERT_TRUE(sortie.landing.has_value());
    EXPECT_GE(sortie.landing->p_land_above_reserve, 0.99 - 1e-9);
    ASSERT_EQ(sortie.sensitivity.gust_charge_ah.size(), static_cast<std::size_t>(kGustPoints));
    // A lull of 3 standard deviations (hovering in still air and flying in 1 m/s) costs more than
    // the mean wind, and more than a gust of 3 standard deviations saves.
    const double lull_ah = sortie.sensitivity.gust_charge_ah.front();
    EXPECT_GT(lull_ah, 0.0);
    EXPECT_GT(lull_ah + sortie.sensitivity.gust_charge_ah.back(), 0.0);
    // Gusts take the 1st percentile below what the parameters and the residual alone give.
    ChargeSensitivity still = sortie.sensitivity;
    still.gust_charge_ah.clear();
    EXPECT_LT(sortie.landing->soc_p01, landingOdds(sortie.lowest_soc, still, fit, usable_ah, reserve).soc_p01);

    // The sampled check with another seed, each draw flying its own wind speed, agrees.
    const SampledLanding check =
        sampleLanding(context.energy(), sure.record.sorties[k].samples, sortie.lowest_soc, usable_ah, reserve, fit,
                      kDraws, mission.planning.seed + 7919, SortieWind::of(context.fullModel()));
    const double p = sortie.landing->p_land_above_reserve;
    EXPECT_NEAR(check.p_land_above_reserve, p, 4.0 * std::sqrt(p * (1.0 - p) / kDraws) + 0.002);
    EXPECT_NEAR(check.soc_p01, sortie.landing->soc_p01, 0.005);
    ASSERT_TRUE(sortie.sampled_landing.has_value());
    EXPECT_NEAR(sortie.sampled_landing->p_land_above_reserve, p,
                4.0 * std::sqrt(p * (1.0 - p) / sortie.sampled_landing->draws) + 0.002);
  }
}

TEST(LandingConfidence, TheSummaryWarnsWhenTheSampledOddsFallShortOfTheComputedOnes) {
  TourResult tour;
  Sortie sortie;
  sortie.landing = LandingOdds{0.02, 0.995, 0.27};
  SampledLanding sampled;
  sampled.draws = 1000;
  sampled.seed = 1;
  sampled.p_land_above_reserve = 0.99;  // 3 standard errors (0.0094) + 0.002 below 0.995: within
  sortie.sampled_landing = sampled;
  tour.plan.sorties.push_back(sortie);
  const std::string agreeing = io::tourSummary(tour);
  EXPECT_NE(agreeing.find("lands above the reserve with probability 0.995 (landing SOC 1st percentile 27.0 %; "
                          "sampled: 0.99 +- 0.0031 over 1000 draws, seed 1)"),
            std::string::npos)
      << agreeing;
  EXPECT_EQ(agreeing.find("warning"), std::string::npos) << agreeing;
  tour.plan.sorties[0].sampled_landing->p_land_above_reserve = 0.97;
  const std::string short_of_it = io::tourSummary(tour);
  EXPECT_NE(short_of_it.find("seed 1); warning: the sampled odds are below the computed ones beyond their sampling "
                             "error"),
            std::string::npos)
      << short_of_it;
}

}  // namespace
}  // namespace ceilplan::mission
