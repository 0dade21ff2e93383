// planner::benchmarkPlanners: OMPL's harness on one query, each run's cost against a lattice
// reference, and bad options refused before any run.

#include "planner_fixtures.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/planner/planner_benchmark.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "input_error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::planner {
namespace {

std::string errorOf(const PlannerBenchmarkOptions& options) {
  return testing::inputErrorOf([&] { options.validate(); });
}

TEST(PlannerBenchmark, DefaultsToTheSamplingPlannersAndRefusesUnknownNames) {
  PlannerBenchmarkOptions options;
  ASSERT_FALSE(options.planners.empty());
  for (const std::string& name : options.planners) EXPECT_EQ(plannerInfo(name).kind, PlannerKind::Sampling) << name;
  EXPECT_EQ(errorOf(options), "(no error)");
  options.planners.clear();
  EXPECT_EQ(errorOf(options), "give at least one planner name");
  options.planners = {"PRMstar", "RRTstarr"};
  EXPECT_NE(errorOf(options).find("RRTstarr"), std::string::npos);
  options.planners = {"PRMstar", referencePlannerName()};  // the lattice planners run too
  EXPECT_EQ(errorOf(options), "(no error)");
  options.runs = 0;
  EXPECT_NE(errorOf(options), "(no error)");
  options.runs = 1;
  options.time_limit_s = 0.0;
  EXPECT_NE(errorOf(options), "(no error)");
}

TEST(PlannerBenchmark, PlannerListsSplitOnCommasSkippingEmptyNamesAndJoinBack) {
  EXPECT_EQ(plannerNamesOfList("BITstar,PRMstar"), (std::vector<std::string>{"BITstar", "PRMstar"}));
  EXPECT_EQ(plannerNamesOfList(",lattice,,RRTstar,"), (std::vector<std::string>{"lattice", "RRTstar"}));
  EXPECT_TRUE(plannerNamesOfList("").empty());
  EXPECT_EQ(plannerList({"BITstar", "PRMstar"}), "BITstar,PRMstar");
  EXPECT_EQ(plannerList({}), "");
  EXPECT_EQ(plannerNamesOfList(plannerList(samplingPlannerNames())), samplingPlannerNames());
}

TEST(PlannerBenchmark, TheReferenceIsTheLatticeOptimumOrANamedNoPath) {
  const testing::CeilingScene scene(testing::corridor(testing::flatCeiling));
  PlanRequest request;
  request.start_m = {0.5, 0.0, 3.4};
  request.goal_m = {5.5, 0.0, 3.4};
  request.planner = "BITstar";  // replaced: the reference is always the lattice's
  const PlanResult reference = planLatticeReference(scene.planner, request);
  EXPECT_EQ(reference.planner, referencePlannerName());
  EXPECT_GE(reference.waypoints.size(), 2u);
  EXPECT_LE(reference.cost, reference.search_cost * (1 + 1e-9));  // post-processed, never worse
  // The same corridor cut in two by a wall at x in [3, 3.3): no path.
  const testing::CeilingScene walled(
      testing::analyticMap({-0.7, -2.7, 0}, {6.7, 2.7, 4.2}, 0.1, [](const Eigen::Vector3d& c) {
        const bool wall = c.x() > 3.0 && c.x() < 3.3;
        const bool outside = c.z() < 0.2 || c.z() > 3.5 || std::abs(c.y()) > 2.5 || c.x() < -0.5 || c.x() > 6.5;
        return wall || outside ? testing::CellState::Occupied : testing::CellState::Free;
      }));
  try {
    planLatticeReference(walled.planner, request);
    ADD_FAILURE() << "no NoPathError";
  } catch (const NoPathError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("lattice reference: ", 0), 0u) << e.what();
  } catch (const InputError& e) {
    ADD_FAILURE() << "an InputError, not a NoPathError: " << e.what();
  }
}

TEST(PlannerBenchmark, ComparesEachRunWithTheLatticeReference) {
  seedOmpl(1);
  const testing::CeilingScene scene(testing::corridor(testing::flatCeiling));
  const Eigen::Vector3d start(0.5, 0.0, 3.4), goal(5.5, 0.0, 3.4);
  PlanRequest request;
  request.start_m = start;
  request.goal_m = goal;
  request.planner = referencePlannerName();
  const PlanResult reference = scene.planner.plan(request);

  PlannerBenchmarkOptions options;
  options.planners = {"PRMstar"};
  options.runs = 2;
  options.time_limit_s = 0.3;
  std::ostringstream log;
  options.log = &log;
  const std::vector<PlannerBenchmarkRow> rows = benchmarkPlanners(scene.planner, start, goal, reference, options);
  ASSERT_EQ(rows.size(), 1u);
  const PlannerBenchmarkRow& row = rows.front();
  EXPECT_EQ(row.planner, "PRMstar");
  EXPECT_EQ(row.runs, 2u);
  ASSERT_GE(row.solved, 1);
  EXPECT_GE(row.median_cost_ratio, 0.9);  // a sampled path cannot beat the lattice optimum by much
  EXPECT_LE(row.best_cost_ratio, row.median_cost_ratio);
  EXPECT_GE(row.median_raw_cost_ratio, 0.9);
  EXPECT_GT(row.median_first_solution_s, 0.0);
  EXPECT_LE(row.median_first_solution_s, 0.3 + 0.1);
  EXPECT_NE(log.str().find("PRMstar"), std::string::npos) << log.str();  // OMPL's log names the planner run
}

}  // namespace
}  // namespace ceilplan::planner
