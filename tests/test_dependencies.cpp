// Proves that every third-party library ceilplan builds on is found, compiled against and
// linked, by making each do one small real thing.

#include <CLI/CLI.hpp>
#include <GeographicLib/LocalCartesian.hpp>
#ifdef CEILPLAN_WITH_BENCHMARK
#include <benchmark/benchmark.h>
#endif
#include <dynamicEDT3D/dynamicEDTOctomap.h>
#include <gtest/gtest.h>
#include <octomap/octomap.h>
#include <ompl/base/ScopedState.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <yaml-cpp/yaml.h>
#include <nlohmann/json.hpp>
#include <nlopt.hpp>

#include <Eigen/Dense>

#include <cmath>
#include <vector>

TEST(Dependencies, EigenSolvesALinearSystem) {
  Eigen::Matrix2d a;
  a << 2, 1, 1, 3;
  const Eigen::Vector2d x = a.colPivHouseholderQr().solve(Eigen::Vector2d(3, 5));
  EXPECT_NEAR(x(0), 0.8, 1e-12);
  EXPECT_NEAR(x(1), 1.4, 1e-12);
}

TEST(Dependencies, OctoMapStoresAnOccupiedVoxel) {
  octomap::OcTree tree(0.1);
  tree.updateNode(octomap::point3d(1.0f, 1.0f, 1.0f), true);
  const octomap::OcTreeNode* node = tree.search(1.0, 1.0, 1.0);
  ASSERT_NE(node, nullptr);
  EXPECT_TRUE(tree.isNodeOccupied(node));
  EXPECT_EQ(tree.search(5.0, 5.0, 5.0), nullptr);
}

TEST(Dependencies, DynamicEdtMeasuresDistanceToAnObstacle) {
  octomap::OcTree tree(0.1);
  for (double x = -1.0; x <= 1.0; x += 0.1)
    for (double y = -1.0; y <= 1.0; y += 0.1)
      for (double z = -1.0; z <= 1.0; z += 0.1) tree.updateNode(octomap::point3d(x, y, z), false);
  tree.updateNode(octomap::point3d(0.05f, 0.05f, 0.05f), true);
  DynamicEDTOctomap edt(2.0f, &tree, octomap::point3d(-1, -1, -1), octomap::point3d(1, 1, 1), false);
  edt.update();
  EXPECT_NEAR(edt.getDistance(octomap::point3d(0.55f, 0.05f, 0.05f)), 0.5, 1e-5);
}

TEST(Dependencies, OmplSamplesInsideBounds) {
  auto space = std::make_shared<ompl::base::RealVectorStateSpace>(3);
  space->setBounds(0.0, 1.0);
  ompl::base::ScopedState<ompl::base::RealVectorStateSpace> state(space);
  state.random();
  for (int i = 0; i < 3; ++i) {
    EXPECT_GE(state[i], 0.0);
    EXPECT_LE(state[i], 1.0);
  }
}

TEST(Dependencies, NloptMinimisesAQuadratic) {
  nlopt::opt optimiser(nlopt::LN_COBYLA, 1);
  optimiser.set_min_objective(
      [](const std::vector<double>& x, std::vector<double>&, void*) { return (x[0] - 2) * (x[0] - 2); }, nullptr);
  optimiser.set_xtol_abs(1e-9);
  std::vector<double> x{0.0};
  double value = 0;
  optimiser.optimize(x, value);
  EXPECT_NEAR(x[0], 2.0, 1e-6);
}

TEST(Dependencies, YamlCppParsesAMap) {
  const YAML::Node node = YAML::Load("capacity_ah: 5.2\nlist: [1, 2]");
  EXPECT_DOUBLE_EQ(node["capacity_ah"].as<double>(), 5.2);
  EXPECT_EQ(node["list"].size(), 2u);
}

TEST(Dependencies, Cli11ParsesAFlag) {
  CLI::App app;
  double value = 0;
  app.add_option("--value", value);
  app.parse(std::vector<std::string>{"3.5", "--value"});
  EXPECT_DOUBLE_EQ(value, 3.5);
}

TEST(Dependencies, NlohmannJsonRoundTrips) {
  const nlohmann::json j = nlohmann::json::parse(R"({"fec": [0.609, 0.5128]})");
  EXPECT_DOUBLE_EQ(j["fec"][1].get<double>(), 0.5128);
}

TEST(Dependencies, GeographicLibConvertsToLocalEnu) {
  GeographicLib::LocalCartesian origin(47.0, 8.0, 400.0);
  double lat = 0, lon = 0, alt = 0;
  origin.Reverse(100.0, 0.0, 10.0, lat, lon, alt);
  double east = 0, north = 0, up = 0;
  origin.Forward(lat, lon, alt, east, north, up);
  EXPECT_NEAR(east, 100.0, 1e-6);
  EXPECT_NEAR(up, 10.0, 1e-6);
  EXPECT_GT(lon, 8.0);
}

#ifdef CEILPLAN_WITH_BENCHMARK
// Debian's Google Benchmark 1.7.1 miscompiles DoNotOptimize on a non-const double lvalue under
// GCC 12 (the value reads back as zero): benchmarks here pass only const values or results.
TEST(Dependencies, GoogleBenchmarkIsLinked) {
  const double x = std::sqrt(2.0);
  benchmark::DoNotOptimize(x);
  EXPECT_NEAR(x * x, 2.0, 1e-12);
  EXPECT_GT(benchmark::CPUInfo::Get().num_cpus, 0);
}
#endif
