// The lattice A* (an OMPL planner) is optimal on its lattice: it matches an exhaustive
// Bellman-Ford over the same nodes, edges and motion costs.

#include "planner_fixtures.hpp"

#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/lattice_planner.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace ceilplan::testing {
namespace {

double bruteForceCost(const planner::SafetyRules& rules, const planner::FlightObjective& objective, int stride,
                      const Eigen::Vector3d& start, const Eigen::Vector3d& goal) {
  const environment::GridFrame& frame = rules.environment().grid().frame();
  std::vector<Eigen::Vector3d> nodes{start, goal};
  for (int c = 0; c * stride < frame.size()[2]; ++c)
    for (int b = 0; b * stride < frame.size()[1]; ++b)
      for (int a = 0; a * stride < frame.size()[0]; ++a) {
        const Eigen::Vector3d p(frame.centreOf(0, a * stride), frame.centreOf(1, b * stride),
                                frame.centreOf(2, c * stride));
        if (rules.isStateValid(p)) nodes.push_back(p);
      }
  const double spacing = stride * frame.resolution_m();
  struct Edge {
    std::size_t from, to;
    double cost;
  };
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (std::size_t j = 0; j < nodes.size(); ++j) {
      if (i == j || j == 0 || i == 1) continue;  // nothing enters the start or leaves the goal
      const Eigen::Vector3d d = nodes[j] - nodes[i];
      const bool lattice_edge = i > 1 && j > 1 && d.cwiseAbs().maxCoeff() < 1.01 * spacing;
      const bool join = (i == 0 || j == 1) && (i == 0 && j == 1 ? true : d.norm() <= std::sqrt(3.0) * spacing);
      if (!lattice_edge && !join) continue;
      if (rules.isMotionValid(nodes[i], nodes[j])) edges.push_back({i, j, objective.motionCost(nodes[i], nodes[j])});
    }
  std::vector<double> cost(nodes.size(), std::numeric_limits<double>::infinity());
  cost[0] = 0.0;
  for (std::size_t round = 0; round < nodes.size(); ++round) {
    bool changed = false;
    for (const Edge& e : edges)
      if (cost[e.from] + e.cost < cost[e.to]) {
        cost[e.to] = cost[e.from] + e.cost;
        changed = true;
      }
    if (!changed) break;
  }
  return cost[1];
}

TEST(LatticePlanner, MatchesExhaustiveSearchOnATinyLattice) {
  const environment::OccupancyMap map = beamRoom();
  const environment::Environment environment(map, quad());
  const energy::EnergyModel energy = paperEnergy();
  const planner::SafetyRules rules(environment, 0.05);
  const planner::FlightCostModel model(environment, energy, planner::CostModelOptions{});
  for (const std::string objective_name : {"charge", "time"}) {
    planner::ObjectiveChoice choice;
    choice.name = objective_name;
    const planner::FlightPlanner planner(rules, model, choice);
    const Eigen::Vector3d start(-0.8, -0.3, 1.9), goal(1.0, 0.4, 1.9);  // on either side of the beam
    planner::LatticeSettings settings;
    settings.spacing_m = 0.3;  // three voxels
    planner::LatticePlanner lattice(planner.spaceInformation(), settings);
    const Solved found = solveOnce(lattice, planner, start, goal);
    ASSERT_EQ(found.status, ompl::base::PlannerStatus::EXACT_SOLUTION) << objective_name;
    const double reference = bruteForceCost(rules, planner.objective(), 3, start, goal);
    EXPECT_NEAR(found.cost, reference, 1e-9 * reference) << objective_name;
    EXPECT_NEAR(planner.objective().pathCost(found.waypoints), found.cost, 1e-9 * reference);
    EXPECT_FALSE(rules.checkPathDensely(found.waypoints)) << objective_name;
  }
}

TEST(LatticePlanner, SaysNoPathWhenAWallSeparatesStartAndGoal) {
  const CeilingScene scene(analyticMap({-1.2, -1.2, 0}, {1.2, 1.2, 2.4}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < 0.2 || c.z() > 2.0 || (c.x() > -0.1 && c.x() < 0.1)) return CellState::Occupied;
    return CellState::Free;
  }));
  planner::LatticePlanner lattice(scene.planner.spaceInformation());
  EXPECT_EQ(solveOnce(lattice, scene.planner, {-0.6, 0.0, 1.0}, {0.6, 0.0, 1.0}).status,
            ompl::base::PlannerStatus::ABORT);  // proved: not stopped by the clock
}

// The lattice planners are deterministic: a slow or loaded machine gets the same route as a
// fast one, so the clock that stops a sampling planner does not stop them.
TEST(LatticePlanner, RunsToCompletionWhateverTheTimeLimit) {
  const CeilingScene scene(beamRoom());
  for (const std::string name : {"lattice", "roadmap"}) {
    planner::PlanRequest request;
    request.start_m = {-0.8, -0.3, 1.9};
    request.goal_m = {1.0, 0.4, 1.9};
    request.planner = name;
    request.refine = false;
    request.time_limit_s = 600.0;
    const planner::PlanResult unhurried = scene.planner.plan(request);
    request.time_limit_s = 1e-9;  // over before the first node is expanded
    const planner::PlanResult hurried = scene.planner.plan(request);
    EXPECT_EQ(hurried.waypoints, unhurried.waypoints) << name;
    EXPECT_DOUBLE_EQ(hurried.cost, unhurried.cost) << name;
  }
}

TEST(LatticePlanner, IsChosenByNameLikeEveryOtherPlannerAndTheSpacingIsInMetres) {
  const CeilingScene scene(beamRoom());
  const ompl::base::PlannerPtr lattice =
      planner::makePlanner(planner::referencePlannerName(), scene.planner.spaceInformation());
  EXPECT_EQ(lattice->getName(), "lattice");
  EXPECT_TRUE(planner::plannerInfo("lattice").deterministic());
  EXPECT_FALSE(planner::plannerInfo("lattice").multiQuery());
  EXPECT_EQ(lattice->params().getParam("spacing_m")->getValue(), "0.4");
  EXPECT_TRUE(lattice->params().setParam("spacing_m", "0.2"));
  EXPECT_NEAR(lattice->as<planner::LatticePlanner>()->getSpacing(), 0.2, 1e-12);
  EXPECT_THROW(planner::makePlanner("FastestStar", scene.planner.spaceInformation()), ceilplan::InputError);
  planner::LatticeSettings bad;
  bad.spacing_m = 0.0;
  EXPECT_THROW(planner::LatticePlanner(scene.planner.spaceInformation(), bad), ceilplan::InputError);
}

}  // namespace
}  // namespace ceilplan::testing
