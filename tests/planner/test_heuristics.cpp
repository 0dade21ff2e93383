// The objectives' heuristics are admissible: c_min x distance never exceeds a motion's cost.

#include "planner_fixtures.hpp"

#include "ceilplan/planner/flight_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace ceilplan::testing {
namespace {

// Beams 0.6 m deep every 1.5 m under a 3.5 m ceiling.
double beamedCeiling(double x, double) {
  const double phase = std::fmod(x + 0.5, 1.5);
  return phase < 0.3 ? 2.9 : 3.5;
}

planner::ObjectiveChoice choice(const std::string& name) {
  planner::ObjectiveChoice c;
  c.name = name;
  if (name == "ageing") {
    battery::AgeingModelOptions options;
    c.ageing = planner::measureAgeingRates("xu", options, battery::Pack{}, 0.95, 0.05, 9.0);
  }
  return c;
}

using RandomPairs = std::vector<std::pair<Eigen::Vector3d, Eigen::Vector3d>>;

// On the beamed corridor, both modes' cost models under every objective, each with 300 random
// pairs of points (short hops of up to `hop_m` near the ceiling band and long ones anywhere):
// visit(model, objective, label, pairs).
void forEachObjectiveOnRandomPairs(
    unsigned seed, double hop_m,
    const std::function<void(const planner::FlightCostModel&, const planner::FlightObjective&, const std::string&,
                             const RandomPairs&)>& visit) {
  const environment::OccupancyMap map = corridor(beamedCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::SafetyRules rules(environment, 0.05);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> x(-0.4, 6.4), y(-2.4, 2.4), z(0.25, 3.45);
  for (const bool proximity : {true, false}) {
    planner::CostModelOptions options;
    options.proximity_effects = proximity;
    const planner::FlightCostModel model(environment, energy, options);
    for (const std::string& name : planner::objectiveNames()) {
      const planner::FlightPlanner planner(rules, model, choice(name));
      RandomPairs pairs;
      for (int k = 0; k < 300; ++k) {
        const Eigen::Vector3d a(x(random), y(random), z(random));
        const Eigen::Vector3d b = k % 2 ? Eigen::Vector3d(x(random), y(random), z(random))
                                        : Eigen::Vector3d(a + Eigen::Vector3d::Random() * hop_m);
        if (environment.contains(b)) pairs.emplace_back(a, b);
      }
      visit(model, planner.objective(), name + (proximity ? " ceiling" : " free"), pairs);
    }
  }
}

TEST(Heuristics, CostToGoNeverExceedsTheMotionCostOnRandomPairs) {
  forEachObjectiveOnRandomPairs(7, 0.3,
                                [](const planner::FlightCostModel&, const planner::FlightObjective& objective,
                                   const std::string& label, const RandomPairs& pairs) {
                                  ASSERT_GT(objective.minCostPerMetre(), 0.0) << label;
                                  for (const auto& [a, b] : pairs)
                                    EXPECT_LE(objective.heuristic(a, b), objective.motionCost(a, b) * (1 + 1e-12))
                                        << label << " from " << a.transpose() << " to " << b.transpose();
                                });
}

// The roadmap prices an edge it has not costed yet by its direction (climbing costs more than
// descending): minCostPerMetreAt(elevation) must never exceed a motion's cost per metre at
// that elevation, in either mode and under every objective, and the cheapest over the fan is
// minCostPerMetre (without its margin).
TEST(Heuristics, TheCheapestMetreAtEachElevationNeverExceedsAMotionsCostPerMetreThere) {
  forEachObjectiveOnRandomPairs(11, 0.4,
                                [](const planner::FlightCostModel& model, const planner::FlightObjective& objective,
                                   const std::string& label, const RandomPairs& pairs) {
                                  double cheapest = std::numeric_limits<double>::infinity();
                                  for (const double elevation : model.costFanElevations_rad())
                                    cheapest =
                                        std::min(cheapest, model.minCostPerMetreAt(objective.weights(), elevation));
                                  EXPECT_DOUBLE_EQ(objective.minCostPerMetre(), 0.995 * cheapest) << label;
                                  for (const auto& [a, b] : pairs) {
                                    if ((b - a).norm() < 1e-3) continue;
                                    const double elevation = std::atan2(b.z() - a.z(), (b - a).head<2>().norm());
                                    EXPECT_LE(model.minCostPerMetreAt(objective.weights(), elevation) * (b - a).norm(),
                                              objective.motionCost(a, b) * (1 + 1e-12))
                                        << label << " from " << a.transpose() << " to " << b.transpose();
                                  }
                                });
}

TEST(Heuristics, MinCostPerMetreIsTight) {
  // Within a few per cent of the cheapest motion one can actually find: diving along the
  // descent-rate corner right under a ceiling.
  const environment::OccupancyMap map = corridor(flatCeiling);
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::SafetyRules rules(environment, 0.05);
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  const planner::FlightPlanner planner(rules, model, choice("time"));
  const double fastest = std::hypot(2.0, 1.0);  // cruise 2 m/s and climb 1 m/s together
  EXPECT_NEAR(planner.objective().minCostPerMetre(), 0.995 / fastest, 1e-9);
}

}  // namespace
}  // namespace ceilplan::testing
