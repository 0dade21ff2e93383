// Large tours (docs/tours.md, "Large tours"): legs kept sparsely, the nearest places, the
// neighbour-list order search (lower bounds only save work, never change the result) and the
// sortie split over split points (every sortie starts at one, lands above the reserve, and with
// every position allowed it is the exact split under a charge-proportional model).

#include "ceilplan/core/error.hpp"
#include "ceilplan/mission/pair_table.hpp"
#include "ceilplan/mission/sortie_plan.hpp"
#include "ceilplan/mission/tour_order.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>

namespace ceilplan::mission {
namespace {

std::vector<Eigen::Vector3d> randomPlaces(int count, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> x(0, 50), y(-10, 10), z(0, 6);
  std::vector<Eigen::Vector3d> places(count);
  for (auto& p : places) p = {x(random), y(random), z(random)};
  return places;
}

// A leg costs its length plus twice the height it climbs: asymmetric.
double legCost(const std::vector<Eigen::Vector3d>& places, int from, int to) {
  return (places[to] - places[from]).norm() + 2.0 * std::max(0.0, places[to].z() - places[from].z());
}

TEST(PairTable, StoresOnlyThePairsWrittenAndRefusesToInventTheOthers) {
  PairTable<double> table(4);
  EXPECT_EQ(table.placeCount(), 4);
  EXPECT_EQ(table.size(), 0u);
  table[1][2] = 3.5;
  table(2, 1) = 4.5;
  EXPECT_EQ(table.size(), 2u);
  EXPECT_TRUE(table.contains(1, 2));
  EXPECT_FALSE(table.contains(2, 3));
  EXPECT_EQ(table.find(2, 3), nullptr);
  const PairTable<double>& read = table;
  EXPECT_DOUBLE_EQ(read[1][2], 3.5);
  EXPECT_DOUBLE_EQ(read.at(2, 1), 4.5);
  EXPECT_THROW(read[2][3], std::out_of_range);
  EXPECT_THROW(read.at(0, 1), std::out_of_range);
  EXPECT_THROW(read.row(4), std::out_of_range);
  EXPECT_EQ(read.row(1).size(), 1u);
}

TEST(LargeTours, NearestPlacesAreTheBruteForceOnes) {
  const std::vector<Eigen::Vector3d> places = randomPlaces(300, 7);
  const std::vector<std::vector<int>> nearest = nearestPlaces(places, 8);
  ASSERT_EQ(nearest.size(), places.size());
  for (int p = 0; p < static_cast<int>(places.size()); ++p) {
    std::vector<int> others;
    for (int q = 0; q < static_cast<int>(places.size()); ++q)
      if (q != p) others.push_back(q);
    std::sort(others.begin(), others.end(), [&](int a, int b) {
      const double da = (places[a] - places[p]).squaredNorm(), db = (places[b] - places[p]).squaredNorm();
      return da < db || (da == db && a < b);
    });
    others.resize(8);
    EXPECT_EQ(nearest[p], others) << "place " << p;
  }
  EXPECT_EQ(nearestPlaces(randomPlaces(3, 1), 8)[0].size(), 2u);  // fewer places than asked
  EXPECT_THROW(nearestPlaces(places, 0), ceilplan::InputError);
}

struct CountedCosts {
  std::vector<Eigen::Vector3d> places;
  mutable int exact_calls = 0;
  PairCost cost() const {
    return [this](int from, int to) {
      ++exact_calls;
      return legCost(places, from, to);
    };
  }
};

TEST(LargeTours, NeighbourListSearchImprovesOnItsStartAndBoundsOnlySaveWork) {
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    CountedCosts loose{randomPlaces(201, seed)}, tight{loose.places};
    const int targets = 200;
    const std::vector<std::vector<int>> neighbours = nearestPlaces(loose.places, 8);
    const std::vector<int> start = nearestNeighbourOrder(loose.places, neighbours);
    CostMatrix matrix(targets + 1, targets + 1);
    for (int i = 0; i <= targets; ++i)
      for (int j = 0; j <= targets; ++j) matrix(i, j) = legCost(loose.places, i, j);
    // The weakest bound (0) and a tight one (the straight line, which every leg costs at least).
    const TourOrder weak = neighbourListTour(targets, loose.cost(), [](int, int) { return 0.0; }, neighbours, {start});
    const TourOrder strong = neighbourListTour(
        targets, tight.cost(), [&](int from, int to) { return (tight.places[to] - tight.places[from]).norm(); },
        neighbours, {start});
    EXPECT_EQ(weak.targets, strong.targets) << "seed " << seed;
    EXPECT_LT(tight.exact_calls, loose.exact_calls) << "seed " << seed;
    std::vector<int> sorted = strong.targets;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int> all(targets);
    std::iota(all.begin(), all.end(), 1);
    EXPECT_EQ(sorted, all);
    EXPECT_NEAR(strong.cost, tourCost(matrix, strong.targets), 1e-9);
    EXPECT_LT(strong.cost, tourCost(matrix, start)) << "seed " << seed;
    // Within a few per cent of the full-matrix heuristic (200 restarts over every pair).
    EXPECT_LT(strong.cost, 1.08 * heuristicTour(matrix, seed).cost) << "seed " << seed;
    EXPECT_EQ(strong.method, "neighbour-list 2-opt+or-opt");
    // Kicks only ever keep a cheaper order, and are reproducible from the seed.
    const TourOrder kicked = neighbourListTour(
        targets, tight.cost(), [](int, int) { return 0.0; }, neighbours, {start}, 30, 9);
    EXPECT_LE(kicked.cost, strong.cost + 1e-9);
    EXPECT_EQ(kicked.targets, neighbourListTour(
                                  targets, tight.cost(), [](int, int) { return 0.0; }, neighbours, {start}, 30, 9)
                                  .targets);
  }
}

// As a large tour asks: a leg between neighbours is stored (its bound is its cost), any other is
// estimated when first asked (then stored too) and bounded until then by 0.4 of the straight
// line, as loose as the tours' bound. A move is priced exactly only as far as its bounds say it
// may gain: the order of pricing every leg exactly, with fewer legs estimated.
TEST(LargeTours, NeighbourListSearchEstimatesAMovesLegsOnlyWhileItMayStillGain) {
  const std::vector<Eigen::Vector3d> places = randomPlaces(401, 5);
  const int targets = 400;
  const std::vector<std::vector<int>> neighbours = nearestPlaces(places, 8);
  const std::vector<int> start = nearestNeighbourOrder(places, neighbours);
  std::set<std::pair<int, int>> stored, estimated;
  for (int from = 0; from <= targets; ++from)
    for (int to : neighbours[from]) stored.insert({{from, to}, {to, from}});
  const PairCost cost = [&](int from, int to) {
    if (stored.insert({from, to}).second) estimated.insert({from, to});
    return legCost(places, from, to);
  };
  const PairCost bound = [&](int from, int to) {
    return stored.count({from, to}) ? legCost(places, from, to) : 0.4 * (places[to] - places[from]).norm();
  };
  const TourOrder order = neighbourListTour(targets, cost, bound, neighbours, {start}, 20, 3);
  const PairCost exact = [&](int from, int to) { return legCost(places, from, to); };
  EXPECT_EQ(order.targets, neighbourListTour(targets, exact, exact, neighbours, {start}, 20, 3).targets);
  // 5908 legs estimated; 7416 when a move its bounds let through was priced whole, both ways round.
  EXPECT_LT(estimated.size(), 6300u);
}

// A move changes two or three legs of the walk: the search prices those, not the whole walk
// again (which made it grow with the square of the places), and the cost it reports is still
// the walk's legs summed afresh in order, to the bit.
TEST(LargeTours, NeighbourListSearchAsksTheLegsAMoveChangesNotTheWholeWalk) {
  double calls_per_target[2] = {0.0, 0.0};
  const int sizes[2] = {400, 3200};
  for (int k = 0; k < 2; ++k) {
    const int targets = sizes[k];
    // The same density of places at both sizes: a strip as long as the tour.
    std::vector<Eigen::Vector3d> places = randomPlaces(targets + 1, 11);
    for (auto& p : places) p.x() *= targets / 50.0;
    CountedCosts counted{places};
    const std::vector<std::vector<int>> neighbours = nearestPlaces(places, 8);
    const std::vector<int> start = nearestNeighbourOrder(places, neighbours);
    const TourOrder order =
        neighbourListTour(targets, counted.cost(), [&](int from, int to) { return (places[to] - places[from]).norm(); },
                          neighbours, {start});
    double sum = 0.0;
    int at = 0;
    for (int target : order.targets) sum += legCost(places, at, target), at = target;
    sum += legCost(places, at, 0);
    EXPECT_EQ(order.cost, sum) << targets << " targets";
    calls_per_target[k] = static_cast<double>(counted.exact_calls) / targets;
  }
  // Eight times the places: 3.5 times the calls per target (the sweeps' own growth); asking the
  // whole walk again after every move made it 5.8 times (1522 and 8888 calls per target).
  EXPECT_LT(calls_per_target[1], 4.5 * calls_per_target[0])
      << calls_per_target[0] << " and " << calls_per_target[1] << " calls per target";
}

TEST(LargeTours, NeighbourListSearchRefusesBadInput) {
  const std::vector<Eigen::Vector3d> places = randomPlaces(5, 1);
  const std::vector<std::vector<int>> neighbours = nearestPlaces(places, 2);
  const PairCost cost = [&](int from, int to) { return legCost(places, from, to); };
  const PairCost zero = [](int, int) { return 0.0; };
  EXPECT_THROW(neighbourListTour(4, cost, zero, neighbours, {}), ceilplan::InputError);
  EXPECT_THROW(neighbourListTour(4, cost, zero, neighbours, {{1, 2, 3}}), ceilplan::InputError);
  EXPECT_THROW(neighbourListTour(4, cost, zero, neighbours, {{1, 2, 3, 3}}), ceilplan::InputError);
  EXPECT_THROW(neighbourListTour(4, cost, zero, {{1}, {2}}, {{1, 2, 3, 4}}), ceilplan::InputError);
  EXPECT_THROW(neighbourListTour(4, cost, zero, {{9}, {}, {}, {}, {}}, {{1, 2, 3, 4}}), ceilplan::InputError);
}

// Targets on a line, every leg at `ah_per_m` per metre, each target dwelling 60 s at 10 A: a tour
// long enough for several sorties of the paper's pack.
TourCosts lineTour(int targets) {
  TourCosts tour;
  tour.names.push_back("home");
  for (int k = 1; k <= targets; ++k) tour.names.push_back("t" + std::to_string(k));
  const int places = targets + 1;
  tour.legs = PairTable<LegCost>(places);
  tour.dwells.assign(places, Dwell{60.0, 10.0, std::nullopt, {}});
  for (int i = 0; i < places; ++i)
    for (int j = 0; j < places; ++j) {
      if (i == j) continue;
      const double metres = std::abs(i - j) * 2.0;
      tour.legs(i, j) = {0.003 * metres, metres, 0.003 * metres * 3600 / metres, {}, {}};
    }
  return tour;
}

TEST(LargeTours, SortiesStartAtSplitPointsAndLandAboveTheReserve) {
  const int targets = 60;
  const TourCosts tour = lineTour(targets);
  std::vector<int> order(targets);
  std::iota(order.begin(), order.end(), 1);
  const BatterySpec battery;
  SortieOptions options;
  options.ageing_model = "xu";
  options.split_points = {0, 10, 20, 25, 30, 40, 50};
  const SortiePlan plan = planSorties(tour, order, battery, options);
  ASSERT_GT(plan.sorties.size(), 1u);
  int position = 0;
  for (const Sortie& sortie : plan.sorties) {
    EXPECT_NE(std::find(options.split_points.begin(), options.split_points.end(), position), options.split_points.end())
        << position;
    EXPECT_GE(sortie.lowest_soc, battery.reserve_soc - 1e-12);
    position += static_cast<int>(sortie.targets.size());
  }
  EXPECT_EQ(position, targets);

  // Every position allowed and wear proportional to charge: the split of the exact search.
  SortieOptions fec;
  fec.ageing_model = "fec";
  const SortiePlan exact = planSorties(tour, order, battery, fec);
  fec.split_points.resize(targets);
  std::iota(fec.split_points.begin(), fec.split_points.end(), 0);
  const SortiePlan split = planSorties(tour, order, battery, fec);
  ASSERT_EQ(split.sorties.size(), exact.sorties.size());
  for (std::size_t s = 0; s < exact.sorties.size(); ++s) EXPECT_EQ(split.sorties[s].targets, exact.sorties[s].targets);
  EXPECT_NEAR(split.wear, exact.wear, 1e-12);

  SortieOptions bad;
  bad.split_points = {targets};
  EXPECT_THROW(planSorties(tour, order, battery, bad), ceilplan::InputError);
}

TEST(LargeTours, StretchesLongerThanASortieAreFoundUntilSplitPointsDivideThem) {
  // 60 targets of 1/6 Ah each and the paper's pack (3.64 Ah to the reserve): about 20 a sortie.
  const TourCosts tour = lineTour(60);
  std::vector<int> order(60);
  std::iota(order.begin(), order.end(), 1);
  const BatterySpec battery;
  EXPECT_EQ(stretchesNoSortieFlies(tour, order, battery, {0, 30}), (std::vector<int>{0, 30}));
  EXPECT_EQ(stretchesNoSortieFlies(tour, order, battery, {0, 15, 30}), (std::vector<int>{30}));
  EXPECT_TRUE(stretchesNoSortieFlies(tour, order, battery, {0, 15, 30, 45}).empty());
  SortieOptions options;
  options.split_points = {0, 15, 30};
  EXPECT_THROW(planSorties(tour, order, battery, options), ceilplan::InfeasibleError);
  options.split_points = {0, 15, 30, 45};
  EXPECT_GE(planSorties(tour, order, battery, options).sorties.size(), 3u);
  EXPECT_THROW(stretchesNoSortieFlies(tour, order, battery, {60}), ceilplan::InputError);
}

// A seeded tour whose current rises as the SOC falls (constant power into a falling voltage), so
// a leg home costs what the SOC the sortie reached there makes it cost: 240 targets along 200 m,
// each leg a load profile of 2 to 8 samples, each target a 30 s hover.
TourCosts profiledLineTour(std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> where(0.0, 200.0), power(8.0, 14.0);
  std::uniform_int_distribution<int> samples(2, 8);
  const int targets = 240;
  std::vector<double> x{0.0};
  for (int k = 0; k < targets; ++k) x.push_back(where(random));
  std::sort(x.begin() + 1, x.end());
  TourCosts tour;
  tour.names.push_back("home");
  for (int k = 1; k <= targets; ++k) tour.names.push_back("t" + std::to_string(k));
  tour.legs = PairTable<LegCost>(targets + 1);
  tour.dwells.assign(targets + 1, Dwell{30.0, 10.0 / 1.45, 10.0, {}});
  tour.current_at_soc = [](double load, double soc) { return load / (0.5 + soc); };
  const auto addLeg = [&](int from, int to) {
    LegCost& leg = tour.legs(from, to);
    leg.duration_s = 2.0 + std::abs(x[to] - x[from]) / 2.0;
    const int count = samples(random);
    for (int k = 0; k < count; ++k) leg.load_profile.push_back({leg.duration_s * k / (count - 1), power(random)});
    leg.mean_current_a = 10.0 / 1.45;
    leg.charge_ah = leg.mean_current_a * leg.duration_s / 3600.0;
  };
  for (int k = 1; k <= targets; ++k) {
    addLeg(0, k);
    addLeg(k, 0);
    if (k < targets) addLeg(k, k + 1);
  }
  return tour;
}

TEST(LargeTours, ASplitReusingEarlierSplitsSortiesIsTheSplitFlyingThemAgain) {
  // As a large tour splits each order: points every 30 positions, then every 5, then every
  // position within 5 of the sorties' starts; each split with the memo of the ones before.
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    const TourCosts tour = profiledLineTour(seed);
    const int targets = tour.targetCount();
    std::vector<int> order(targets);
    std::iota(order.begin(), order.end(), 1);
    const BatterySpec battery;
    SortieOptions options;  // xu, the tours' model
    SortieMemo memo;
    std::size_t reused = 0;
    std::vector<int> points;
    for (const int spacing : {30, 5, 0}) {
      if (spacing > 0) {
        for (int p = 0; p < targets; p += spacing) points.push_back(p);
      } else {
        const SortiePlan coarse = planSorties(tour, order, battery, options);
        int position = 0;
        for (const Sortie& sortie : coarse.sorties) {
          for (int p = std::max(1, position - 5); position > 0 && p <= std::min(targets - 1, position + 5); ++p)
            points.push_back(p);
          position += static_cast<int>(sortie.targets.size());
        }
      }
      std::sort(points.begin(), points.end());
      points.erase(std::unique(points.begin(), points.end()), points.end());
      options.split_points = points;
      const SortiePlan flown = planSorties(tour, order, battery, options);
      const SortiePlan looked_up = planSorties(tour, order, battery, options, memo);
      ASSERT_GE(flown.sorties.size(), 3u) << seed;
      ASSERT_EQ(looked_up.sorties.size(), flown.sorties.size()) << seed << " " << spacing;
      for (std::size_t s = 0; s < flown.sorties.size(); ++s) {
        EXPECT_EQ(looked_up.sorties[s].targets, flown.sorties[s].targets) << seed << " " << spacing << " " << s;
        EXPECT_EQ(looked_up.sorties[s].charge_ah, flown.sorties[s].charge_ah);
        EXPECT_EQ(looked_up.sorties[s].wear, flown.sorties[s].wear);
        EXPECT_EQ(looked_up.sorties[s].reason, flown.sorties[s].reason);
      }
      EXPECT_EQ(looked_up.wear, flown.wear);
      // Every split after the first looks up sorties the one before it flew home.
      if (spacing != 30) {
        EXPECT_GT(memo.reused(), reused) << seed << " " << spacing;
      }
      // The split flies its sorties home four at a time: each lands where it lands flown alone.
      int checked = 0;
      for (int first : {0, points[points.size() / 2]})
        for (int end = first + 1; end <= targets; ++end)
          if (const SortieEnding* ending = memo.find(first, end)) {
            const std::vector<int> targets_flown(order.begin() + first, order.begin() + end);
            EXPECT_EQ(ending->landing_soc, flySortie(tour, targets_flown, battery).lowest_soc) << first << " " << end;
            ++checked;
          }
      EXPECT_GE(checked, 2);
      reused = memo.reused();
    }
    EXPECT_GT(memo.size(), reused);
    memo.clear();
    EXPECT_EQ(memo.size(), 0u);
    EXPECT_EQ(memo.reused(), 0u);
  }
}

TEST(LargeTours, AStretchNoSortieCanFlyIsNamed) {
  TourCosts tour = lineTour(20);
  tour.dwells[12].duration_s = 3000.0;  // 8.3 Ah at 10 A: more than any sortie holds
  std::vector<int> order(20);
  std::iota(order.begin(), order.end(), 1);
  SortieOptions options;
  options.split_points = {0, 10, 15};
  try {
    planSorties(tour, order, BatterySpec{}, options);
    FAIL() << "expected an infeasible tour";
  } catch (const ceilplan::InfeasibleError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'t12'"), std::string::npos) << message;
    EXPECT_NE(message.find("home -> 't11' ... 't15' -> home"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace ceilplan::mission
