// Sortie splitting: no sortie breaks the reserve, the split minimises wear under the chosen
// ageing model (checked against every possible split), convex DoD stress buys extra sorties
// that a charge-proportional model would not, and every split says why.

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/sortie_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace ceilplan::mission {
namespace {

// Targets on a line at x = positions[k] (home at x = 0): a leg costs `ah_per_m` per metre plus
// `takeoff_ah` when it leaves home, and lasts a second per metre. Each target dwells `dwell_s`
// at `dwell_a`.
TourCosts lineTour(const std::vector<double>& positions, double ah_per_m, double dwell_s, double dwell_a,
                   double takeoff_ah = 0.0) {
  TourCosts tour;
  std::vector<double> x = {0.0};
  x.insert(x.end(), positions.begin(), positions.end());
  const std::size_t n = x.size();
  tour.names.push_back("home");
  for (std::size_t k = 1; k < n; ++k) tour.names.push_back("t" + std::to_string(k));
  tour.legs = PairTable<LegCost>(static_cast<int>(n));
  tour.dwells.assign(n, Dwell{dwell_s, dwell_a, std::nullopt, {}});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      const double metres = std::fabs(x[j] - x[i]);
      LegCost& leg = tour.legs[i][j];
      leg.charge_ah = ah_per_m * metres + (i == 0 && j != 0 ? takeoff_ah : 0.0);
      leg.duration_s = metres;
      leg.mean_current_a = leg.duration_s > 0 ? leg.charge_ah * 3600 / leg.duration_s : 0.0;
    }
  return tour;
}

std::vector<int> inOrder(int targets) {
  std::vector<int> order(targets);
  for (int k = 0; k < targets; ++k) order[k] = k + 1;
  return order;
}

SortieOptions model(const std::string& name) {
  SortieOptions options;
  options.ageing_model = name;
  return options;
}

// Paper pack: 5.2 Ah, 0.95 start, 0.25 reserve: 3.64 Ah per sortie.
const BatterySpec kBattery{};

TEST(SortiePlan, OneSortieWhenTheWholeTourFitsAndWearFollowsCharge) {
  const TourCosts tour = lineTour({10, 20, 30}, 0.01, 20, 10);
  const SortiePlan plan = planSorties(tour, inOrder(3), kBattery, model("fec"));
  ASSERT_EQ(plan.sorties.size(), 1u);
  const Sortie& sortie = plan.sorties[0];
  EXPECT_EQ(sortie.targets, inOrder(3));
  ASSERT_EQ(sortie.legs.size(), 4u);
  EXPECT_EQ(sortie.legs.front().from, 0);
  EXPECT_EQ(sortie.legs.back().to, 0);
  const double charge = 0.01 * 60 + 3 * 10.0 * 20 / 3600;
  EXPECT_NEAR(sortie.charge_ah, charge, 1e-12);
  EXPECT_NEAR(sortie.flight_s, 60 + 3 * 20, 1e-12);
  EXPECT_NEAR(sortie.lowest_soc, 0.95 - charge / 5.2, 1e-12);
  EXPECT_NEAR(sortie.dod, charge / 5.2, 1e-12);
  EXPECT_NEAR(sortie.fec, charge / 5.2, 1e-12);
  EXPECT_NEAR(sortie.recharge_s, charge / 10.4 * 3600, 1e-9);
  EXPECT_NEAR(sortie.wear, sortie.dod, 1e-12);  // fec model: sum |dSOC| / 2 over the cycle
  EXPECT_EQ(plan.ageing_model, "fec");
  EXPECT_NE(sortie.reason.find("one sortie flies the whole tour"), std::string::npos) << sortie.reason;
  EXPECT_DOUBLE_EQ(sortie.soc_history.back().soc, 0.95);
  EXPECT_NEAR(sortie.soc_history.back().t_s, sortie.flight_s + sortie.recharge_s, 1e-9);
}

TEST(SortiePlan, TheReserveForcesASplitAndTheReasonSaysSo) {
  // Each target's dwell takes 1.2 Ah: three of them cannot fit in 3.64 Ah.
  const TourCosts tour = lineTour({5, 10, 15, 20}, 0.01, 432, 10);
  const SortiePlan plan = planSorties(tour, inOrder(4), kBattery, model("fec"));
  ASSERT_EQ(plan.sorties.size(), 2u);
  for (const Sortie& sortie : plan.sorties) EXPECT_GE(sortie.lowest_soc, 0.25);
  EXPECT_NE(plan.sorties[0].reason.find("split after 't2': one sortie on through 't4' would land at"),
            std::string::npos)
      << plan.sorties[0].reason;
  EXPECT_NE(plan.sorties[0].reason.find("below the 25 % reserve"), std::string::npos) << plan.sorties[0].reason;
  EXPECT_NE(plan.sorties[1].reason.find("last sortie"), std::string::npos);
  EXPECT_NEAR(plan.charge_ah, plan.sorties[0].charge_ah + plan.sorties[1].charge_ah, 1e-12);
  EXPECT_NEAR(plan.min_soc, std::min(plan.sorties[0].lowest_soc, plan.sorties[1].lowest_soc), 1e-12);
}

TEST(SortiePlan, ConvexDodStressChoosesMoreSortiesUnderWoehlerButNotUnderFec) {
  // Four targets close to home, each dwelling for 0.81 Ah: one sortie of all reaches 63 % DoD
  // and still clears the reserve. Woehler's DoD^1.5 makes shallower sorties cheaper despite the
  // extra transit; FEC only sees the extra charge.
  const TourCosts tour = lineTour({2, 3, 4, 5}, 0.005, 290, 10);
  const SortiePlan fec = planSorties(tour, inOrder(4), kBattery, model("fec"));
  const SortiePlan woehler = planSorties(tour, inOrder(4), kBattery, model("woehler"));
  ASSERT_EQ(fec.sorties.size(), 1u);
  ASSERT_GT(woehler.sorties.size(), 1u);
  EXPECT_GT(woehler.charge_ah, fec.charge_ah);
  EXPECT_NE(woehler.sorties[0].reason.find("two sorties of"), std::string::npos) << woehler.sorties[0].reason;
  EXPECT_NE(woehler.sorties[0].reason.find("less than one of"), std::string::npos) << woehler.sorties[0].reason;
  EXPECT_NE(woehler.sorties[0].reason.find("under woehler, for 0.0"), std::string::npos) << woehler.sorties[0].reason;
  // Each plan is the better one under its own model.
  EXPECT_LT(planWear(woehler, "woehler").cycle_wear, planWear(fec, "woehler").cycle_wear);
  EXPECT_LT(planWear(fec, "fec").cycle_wear, planWear(woehler, "fec").cycle_wear);
}

// Every way of cutting 1..targets into consecutive sorties: the least feasible total wear.
double bruteForceWear(const TourCosts& tour, int targets, const std::string& name) {
  double best = std::numeric_limits<double>::infinity();
  for (unsigned cuts = 0; cuts < (1u << (targets - 1)); ++cuts) {
    SortiePlan plan;
    std::vector<int> part;
    bool feasible = true;
    for (int k = 1; k <= targets; ++k) {
      part.push_back(k);
      if (k < targets && !(cuts & (1u << (k - 1)))) continue;
      plan.sorties.push_back(flySortie(tour, part, kBattery));
      feasible = feasible && plan.sorties.back().lowest_soc >= kBattery.reserve_soc;
      part.clear();
    }
    if (feasible) best = std::min(best, planWear(plan, name).cycle_wear);
  }
  return best;
}

TEST(SortiePlan, DynamicProgrammeFindsTheLeastWearSplit) {
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> position(1, 60), dwell(30, 250);
  for (int instance = 0; instance < 6; ++instance) {
    std::vector<double> x(6);
    for (double& v : x) v = position(random);
    TourCosts tour = lineTour(x, 0.01, 0, 10);
    for (std::size_t k = 1; k < tour.dwells.size(); ++k) tour.dwells[k] = {dwell(random), 12.0, std::nullopt, {}};
    for (const std::string name : {"woehler", "xu"}) {
      const SortiePlan plan = planSorties(tour, inOrder(6), kBattery, model(name));
      for (const Sortie& sortie : plan.sorties) EXPECT_GE(sortie.lowest_soc, 0.25 - 1e-12);
      const double brute = bruteForceWear(tour, 6, name);
      EXPECT_NEAR(plan.wear, brute, 1e-9 * brute) << name << " instance " << instance;
      EXPECT_NEAR(planWear(plan, name).cycle_wear, plan.wear, 1e-9 * brute);
    }
  }
}

TEST(SortiePlan, ALoadProfileIsIntegratedAtTheSocTheSortieHasReached) {
  // Loads are currents here: the profile's trapezoid integral is the leg's charge.
  TourCosts tour = lineTour({100}, 0.004, 10, 10);
  tour.legs[0][1].load_profile = {{0, 5}, {50, 20}, {100, 5}};
  const Sortie profiled = planSorties(tour, {1}, kBattery, model("fec")).sorties[0];
  const double profile_ah = (12.5 * 50 + 12.5 * 50) / 3600;
  EXPECT_NEAR(profiled.legs[0].charge_ah, profile_ah, 1e-12);
  EXPECT_NEAR(profiled.soc_history[1].soc, 0.95 - profile_ah / 2 / 5.2, 1e-12);
  for (std::size_t k = 1; k < profiled.soc_history.size(); ++k)
    EXPECT_GE(profiled.soc_history[k].t_s, profiled.soc_history[k - 1].t_s);

  // A pack whose current rises as its SOC falls (constant power into a falling voltage): the
  // same leg costs more flown second than first, because it starts lower.
  TourCosts rising = lineTour({50, 100}, 0.0, 0, 10);
  rising.current_at_soc = [](double load, double soc) { return load / (0.5 + soc); };
  for (int from = 0; from < rising.legs.placeCount(); ++from)
    for (int to = 0; to < rising.legs.placeCount(); ++to)
      if (LegCost* leg = rising.legs.find(from, to); leg && leg->duration_s > 0)
        leg->load_profile = {{0, 10}, {leg->duration_s, 10}};
  rising.dwells[1] = {120, 0, 10.0, {}};
  rising.dwells[2] = {120, 0, 10.0, {}};
  const Sortie sortie = planSorties(rising, {1, 2}, kBattery, model("fec")).sorties[0];
  ASSERT_EQ(sortie.legs.size(), 3u);
  // home->t1 and t1->t2 are both 50 m; the second starts after a dwell, at a lower SOC.
  EXPECT_GT(sortie.legs[1].charge_ah, sortie.legs[0].charge_ah);
  EXPECT_NEAR(sortie.legs[0].charge_ah, 10 / 1.45 * 50 / 3600, 1e-3 * sortie.legs[0].charge_ah);
  // The history's currents integrate to the sortie's charge (trapezoids between samples).
  double integral_ah = 0;
  for (std::size_t k = 1; k + 1 < sortie.soc_history.size(); ++k) {
    const SocSample& a = sortie.soc_history[k - 1];
    const SocSample& b = sortie.soc_history[k];
    integral_ah += (a.soc - b.soc) * kBattery.pack.usableCapacityAh();
  }
  EXPECT_NEAR(integral_ah, sortie.charge_ah, 1e-12);
  EXPECT_NEAR(sortie.lowest_soc, 0.95 - sortie.charge_ah / kBattery.pack.usableCapacityAh(), 1e-12);
}

TEST(SortiePlan, PlanWearReportsEveryModelForOneSplit) {
  const TourCosts tour = lineTour({5, 10, 15, 20}, 0.01, 360, 10);
  const SortiePlan plan = planSorties(tour, inOrder(4), kBattery, model("xu"));
  for (const std::string& name : battery::ageingModelNames()) {
    battery::AgeingModelOptions options;
    if (name == "schmalstieg") continue;  // needs a cell voltage curve
    const PlanWear wear = planWear(plan, name, options);
    EXPECT_EQ(wear.model, name);
    EXPECT_GT(wear.cycle_wear, 0.0);
    EXPECT_GT(wear.capacity_loss, 0.0);
  }
  EXPECT_NEAR(planWear(plan, "fec").cycle_wear, plan.fec, 1e-12);
  // Rainflow closes each sortie's cycle before the next: back to back equals the sum.
  EXPECT_NEAR(planWear(plan, "xu").cycle_wear, plan.wear, 1e-12 * plan.wear);
  double separately = 0.0;
  for (const Sortie& sortie : plan.sorties) {
    SortiePlan alone;
    alone.sorties = {sortie};
    separately += planWear(alone, "woehler").cycle_wear;
  }
  EXPECT_NEAR(planWear(plan, "woehler").cycle_wear, separately, 1e-12 * separately);
}

TEST(SortiePlan, NamesTargetsNoSortieCanReach) {
  // Well-formed input asking for the impossible: infeasible (exit code 3), not bad input.
  // t2 dwells for 4 Ah on its own: beyond any single sortie.
  TourCosts tour = lineTour({5, 10, 15}, 0.01, 60, 10);
  tour.dwells[2] = {1440, 10, std::nullopt, {}};
  try {
    planSorties(tour, inOrder(3), kBattery);
    FAIL() << "expected an error";
  } catch (const ceilplan::InfeasibleError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("no single sortie can reach, inspect and return from 't2'"), std::string::npos) << message;
    EXPECT_EQ(message.find("'t1'"), std::string::npos) << message;
  }
}

TEST(SortiePlan, RefusesAReserveAtOrAboveTheStartSoc) {
  const TourCosts tour = lineTour({5}, 0.01, 10, 10);
  BatterySpec battery;
  battery.reserve_soc = 0.96;
  try {
    planSorties(tour, {1}, battery);
    FAIL() << "expected an error";
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("reserve SOC 0.96 is not below the start SOC 0.95"), std::string::npos)
        << e.what();
  }
}

TEST(SortiePlan, RefusesBadInput) {
  TourCosts tour = lineTour({5, 10}, 0.01, 10, 10);
  EXPECT_THROW(planSorties(tour, {1}, kBattery), ceilplan::InputError);     // a target missing
  EXPECT_THROW(planSorties(tour, {1, 1}, kBattery), ceilplan::InputError);  // a target twice
  EXPECT_THROW(planSorties(tour, {1, 2}, kBattery, model("nope")), ceilplan::InputError);
  TourCosts nan = tour;
  nan.legs[1][2].charge_ah = std::nan("");
  EXPECT_THROW(planSorties(nan, {1, 2}, kBattery), ceilplan::InputError);
  TourCosts negative = tour;
  negative.dwells[2].duration_s = -1;
  EXPECT_THROW(planSorties(negative, {1, 2}, kBattery), ceilplan::InputError);
  BatterySpec empty_pack;
  empty_pack.pack.capacity_ah = -1;
  EXPECT_THROW(planSorties(tour, {1, 2}, empty_pack), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::mission
