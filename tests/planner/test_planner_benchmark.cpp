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
#include <string>

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
  options.log_file = (std::filesystem::path(CEILPLAN_TEST_TMP) / "planner_benchmark.log").string();
  std::filesystem::create_directories(CEILPLAN_TEST_TMP);
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
  EXPECT_TRUE(std::filesystem::exists(options.log_file));
}

}  // namespace
}  // namespace ceilplan::planner
