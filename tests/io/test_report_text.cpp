// The terminal text of mapgen and bench-planners (io/report_text.hpp).

#include "ceilplan/io/octomap_file.hpp"
#include "ceilplan/io/report_text.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>

namespace ceilplan::io {
namespace {

TEST(ReportText, APlannerBenchmarkOpensWithItsSettingsAndTheLatticeReference) {
  planner::PlannerBenchmarkOptions options;
  options.runs = 3;
  options.time_limit_s = 0.25;
  EXPECT_EQ(plannerBenchmarkHeadline("free", "fec", "FEC", options, 7),
            "bench-planners: free mode, objective fec (FEC), 3 runs of 0.2 s per planner, seed 7\n");
  planner::PlanResult reference;
  reference.search_cost = 0.0123456789;
  reference.cost = 0.01;
  reference.total_time_s = 2.26;
  EXPECT_EQ(latticeReferenceLine(reference, 0.2),
            "lattice reference (spacing 0.2 m): 0.0123457 raw, 0.01 post-processed, 2.3 s\n");
}

TEST(ReportText, AGeneratedSceneNamesItsSizeAndABridgesLengthOnlyWhenNotTheShippedOne) {
  environment::SceneOptions options;
  options.resolution_m = 0.5;
  const environment::VoxelGrid grid = environment::generateScene(environment::Scene::Open, options);
  const auto tree = environment::toOcTree(grid);
  const std::filesystem::path file = testing::scratchDirectory("report_text") / "open.bt";
  writeOctoMapFile(file, *tree);
  const std::string line = generatedSceneLine("open", options, grid, tree->size(), file);
  const auto& size = grid.frame().size();
  EXPECT_EQ(line.rfind("scene open, resolution 0.5 m, seed 1: " + std::to_string(size[0]) + " x " +
                           std::to_string(size[1]) + " x " + std::to_string(size[2]) + " voxels, " +
                           std::to_string(tree->size()) + " octree nodes -> " + file.string() + " (" +
                           std::to_string(std::filesystem::file_size(file)) + " bytes)\n",
                       0),
            0u)
      << line;
  options.bridge_length_m = 64.0;  // ignored but for a bridge
  EXPECT_EQ(generatedSceneLine("open", options, grid, tree->size(), file).find("length"), std::string::npos);
  EXPECT_EQ(generatedSceneLine("bridge", options, grid, tree->size(), file).rfind("scene bridge, length 64 m, ", 0),
            0u);
  options.bridge_length_m = environment::kShippedBridgeLength_m;
  EXPECT_EQ(generatedSceneLine("bridge", options, grid, tree->size(), file).find("length"), std::string::npos);
}

}  // namespace
}  // namespace ceilplan::io
