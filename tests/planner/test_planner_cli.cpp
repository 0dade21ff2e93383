// `ceilplan plan` and `ceilplan evaluate` as a user runs them.

#include "planner_fixtures.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace ceilplan::testing {
namespace {

const std::string kMapDir = std::string(CEILPLAN_SOURCE_DIR) + "/maps/";
const std::string kVehicle = " --vehicle " + kMapDir + "vehicles/quad.yaml";
const std::string kWarehouse = " --map " + kMapDir + "warehouse.bt" + kVehicle;
// Between two trusses, 7 cm under the roof, and the next bay.
const std::string kUnderRoof = " --start 7.5,6,7.9 --goal 12.5,10,7.9";

TEST(PlanCli, WritesThePlanAndThePathAndEvaluateAgrees) {
  const auto dir = scratchDirectory("plan_warehouse");
  const CommandResult plan = runCeilplan("plan" + kWarehouse + kUnderRoof +
                                         " --planner BITstar --time-limit-s 1 --seed 3 --out " + dir.string());
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  EXPECT_NE(plan.out.find("seed 3"), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(readWholeFile(dir / "plan.json"));
  for (const char* key :
       {"waypoints", "length_m", "duration_s", "charge_ah", "energy_wh", "fec", "mean_current_a", "min_soc",
        "min_clearance_m", "min_ceiling_gap_m", "time_under_ceiling_s", "planner", "seed", "objective", "cost"})
    EXPECT_TRUE(json.contains(key)) << key;
  EXPECT_EQ(json["seed"], 3);
  EXPECT_EQ(json["objective"], "charge");
  EXPECT_GE(json["min_ceiling_gap_m"].get<double>(), 0.05 - 1e-9);
  EXPECT_NEAR(json["fec"].get<double>(), json["charge_ah"].get<double>() / 5.2, 1e-12);
  const std::string csv = readWholeFile(dir / "path.csv");
  // A provenance comment, then the header.
  const std::string comment = csv.substr(0, csv.find('\n'));
  EXPECT_EQ(comment.rfind("# ceilplan ", 0), 0u) << comment;
  for (const char* fragment : {" plan --map ", "| seed 3 |", "warehouse.bt sha256 ", "quad.yaml sha256 "})
    EXPECT_NE(comment.find(fragment), std::string::npos) << fragment;
  const std::string header = csv.substr(comment.size() + 1, csv.find('\n', comment.size() + 1) - comment.size() - 1);
  EXPECT_EQ(header, "t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,ground_gap_m,assumed_free");

  const CommandResult evaluate = runCeilplan("evaluate" + kWarehouse + " --path " + (dir / "path.csv").string() +
                                             " --json " + (dir / "e.json").string());
  ASSERT_EQ(evaluate.exit_code, 0) << evaluate.err;
  const nlohmann::json figures = nlohmann::json::parse(readWholeFile(dir / "e.json"));
  EXPECT_TRUE(figures["valid"].get<bool>());
  // path.csv repeats each waypoint's samples: the same route, so the same charge within the
  // change of integration points.
  EXPECT_NEAR(figures["charge_ah"].get<double>(), json["charge_ah"].get<double>(),
              0.01 * json["charge_ah"].get<double>());
}

TEST(PlanCli, EvaluateReadsThePathOfAPlanWithNothingOverhead) {
  // On the open scene nothing is overhead: path.csv leaves ceiling_gap_m empty on every row.
  const auto dir = scratchDirectory("plan_open");
  const std::string open = " --map " + kMapDir + "open.bt" + kVehicle;
  const CommandResult plan =
      runCeilplan("plan" + open + " --start -4,0,0.5 --goal 4,1,1.5 --planner lattice --out " + dir.string());
  ASSERT_EQ(plan.exit_code, 0) << plan.err;
  const std::string csv = readWholeFile(dir / "path.csv");
  std::istringstream lines(csv);
  std::string line;
  std::getline(lines, line);  // provenance
  std::getline(lines, line);  // header
  ASSERT_EQ(line.substr(0, 24), "t_s,x,y,z,speed_m_s,ceil");
  int rows = 0;
  while (std::getline(lines, line)) {
    ++rows;
    std::vector<std::string> fields;
    std::istringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    ASSERT_GE(fields.size(), 6u) << line;
    EXPECT_EQ(fields[5], "") << line;  // ceiling_gap_m: no surface
  }
  EXPECT_GE(rows, 2);
  const CommandResult evaluate = runCeilplan("evaluate" + open + " --path " + (dir / "path.csv").string() + " --json " +
                                             (dir / "e.json").string());
  ASSERT_EQ(evaluate.exit_code, 0) << evaluate.err;
  const nlohmann::json planned = nlohmann::json::parse(readWholeFile(dir / "plan.json"));
  const nlohmann::json figures = nlohmann::json::parse(readWholeFile(dir / "e.json"));
  EXPECT_TRUE(figures["valid"].get<bool>());
  EXPECT_TRUE(figures["min_ceiling_gap_m"].is_null());
  EXPECT_NEAR(figures["charge_ah"].get<double>(), planned["charge_ah"].get<double>(),
              0.01 * planned["charge_ah"].get<double>());
}

TEST(PlanCli, EvaluateSaysWhereAPathIsUnsafe) {
  const auto dir = scratchDirectory("evaluate_unsafe");
  std::ofstream(dir / "through_truss.csv") << "x,y,z\n7.5,6,7.5\n12.5,6,7.5\n";
  const CommandResult result = runCeilplan("evaluate" + kWarehouse + " --path " + (dir / "through_truss.csv").string() +
                                           " --json " + (dir / "e.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("valid: false"), std::string::npos);
  const nlohmann::json figures = nlohmann::json::parse(readWholeFile(dir / "e.json"));
  EXPECT_FALSE(figures["valid"].get<bool>());
  EXPECT_NE(figures["violation"].get<std::string>().find("occupied"), std::string::npos);
}

TEST(PlanCli, BadInputGetsOneLineAndTheRightExitCode) {
  const auto dir = scratchDirectory("plan_bad");
  const std::string out = " --out " + dir.string();
  struct Case {
    std::string arguments;
    int exit_code;
    std::string says;
  };
  const std::vector<Case> cases{
      {" --start 5,6,7.85 --goal 12.5,10,7.9", 2, "start (5.00, 6.00, 7.85) is not a valid state"},
      {" --start 7.5,6,7.9 --goal 99,10,7.9", 2, "goal (99.00, 10.00, 7.90) lies outside the map"},
      {" --start 7.5,6,nan --goal 12.5,10,7.9", 2, "--start"},
      {kUnderRoof + " --time-limit-s 0", 2, "--time-limit-s"},
      {kUnderRoof + " --planner FastestStar", 2, "--planner"},
      {kUnderRoof + " --objective happiness", 2, "--objective"},
      {kUnderRoof + " --seed 0", 2, "--seed"},
      {kUnderRoof + " --battery /nonexistent/pack.yaml", 2, "/nonexistent/pack.yaml: no such battery file"},
      {" --start 7.5,6,7.9 --goal 7.5,6,7.9", 2, "start and goal coincide"},
  };
  for (const Case& c : cases) {
    const CommandResult result = runCeilplan("plan" + kWarehouse + c.arguments + out);
    EXPECT_EQ(result.exit_code, c.exit_code) << c.arguments << ": " << result.err;
    EXPECT_NE(result.err.find(c.says), std::string::npos) << c.arguments << ": " << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "plan.json"));
}

TEST(PlanCli, NoPathHasItsOwnExitCode) {
  const auto dir = scratchDirectory("plan_no_path");
  const environment::OccupancyMap walled =
      analyticMap({-1.2, -1.2, 0}, {1.2, 1.2, 2.4}, 0.1, [](const Eigen::Vector3d& c) {
        if (c.z() < 0.2 || c.z() > 2.0 || (c.x() > -0.1 && c.x() < 0.1)) return CellState::Occupied;
        return CellState::Free;
      });
  ASSERT_TRUE(walled.tree().writeBinaryConst((dir / "walled.bt").string()));
  const CommandResult result =
      runCeilplan("plan --map " + (dir / "walled.bt").string() + kVehicle +
                  " --start -0.6,0,1 --goal 0.6,0,1 --planner lattice --out " + (dir / "out").string());
  EXPECT_EQ(result.exit_code, 3) << result.err;
  EXPECT_NE(result.err.find("no path"), std::string::npos) << result.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
}

TEST(CompareCli, CeilingModeBeatsFreeModeUnderAFlatCeilingAndProjectsTheDuty) {
  const auto dir = scratchDirectory("compare_corridor");
  ASSERT_TRUE(corridor(flatCeiling).tree().writeBinaryConst((dir / "corridor.bt").string()));
  const CommandResult result =
      runCeilplan("compare --map " + (dir / "corridor.bt").string() + kVehicle +
                  " --start 0.5,0,3.4 --goal 5.5,0,3.4 --planner lattice --days 2 --out " + (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const nlohmann::json json = nlohmann::json::parse(readWholeFile(dir / "out" / "compare.json"));
  EXPECT_GT(json["reduction_pct"]["charge"].get<double>(), 3.0);
  EXPECT_GT(json["reduction_pct"]["fec_total"].get<double>(), 3.0);
  EXPECT_EQ(json["ceiling"]["repeats_per_mission"], json["free"]["repeats_per_mission"]);
  for (const char* file :
       {"ceiling/plan.json", "ceiling/path.csv", "free/plan.json", "free/path.csv", "map_top.csv", "map_side.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / file)) << file;
  EXPECT_NE(result.out.find("FEC over the study"), std::string::npos);
}

TEST(BenchPlannersCli, TablesEachPlannerAgainstTheLatticeReference) {
  const auto dir = scratchDirectory("bench_corridor");
  ASSERT_TRUE(corridor(flatCeiling).tree().writeBinaryConst((dir / "corridor.bt").string()));
  // OMPL's planners and ceilplan's lattice ones, all from the one factory.
  const CommandResult result =
      runCeilplan("bench-planners --map " + (dir / "corridor.bt").string() + kVehicle +
                  " --start 0.5,0,3.4 --goal 5.5,0,3.4 --planners BITstar,PRMstar,lattice,roadmap --runs 2"
                  " --time-limit-s 3 --lattice-spacing-m 0.4 --json " +
                  (dir / "bench.json").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  EXPECT_NE(result.out.find("lattice reference"), std::string::npos);
  const nlohmann::json json = nlohmann::json::parse(readWholeFile(dir / "bench.json"));
  ASSERT_EQ(json["planners"].size(), 4u);
  for (const auto& planner : json["planners"]) {
    EXPECT_EQ(planner["runs"], 2);
    EXPECT_EQ(planner["solved"], 2) << planner["planner"];
    EXPECT_GE(planner["median_cost_ratio"].get<double>(), 0.9);  // cannot beat the lattice by much
  }
  // The lattice A* and the roadmap find the same lattice route (the roadmap stores its edge
  // costs in single precision); post-processing, stopped by a clock, may differ.
  EXPECT_NEAR(json["planners"][2]["median_raw_cost_ratio"].get<double>(),
              json["planners"][3]["median_raw_cost_ratio"].get<double>(), 1e-4);
  const CommandResult unknown = runCeilplan("bench-planners --map " + (dir / "corridor.bt").string() + kVehicle +
                                            " --start 0.5,0,3.4 --goal 5.5,0,3.4 --planners FastestStar");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("unknown planner 'FastestStar'"), std::string::npos) << unknown.err;
}

}  // namespace
}  // namespace ceilplan::testing
