// io::importMap and its outputs, in-process: options refused before any file is read, a cloud
// and a mesh built into maps, non-finite points, the summary and the map written together.

#include "ceilplan/core/error.hpp"
#include "ceilplan/io/map_import.hpp"

#include "input_error.hpp"
#include "run_command.hpp"
#include "scan_files.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace ceilplan::io {
namespace {

std::string errorOf(const MapImportOptions& options) {
  return testing::inputErrorOf([&] { options.validate(); });
}

// A 4 x 3 m deck 3 m up, sampled every 5 cm.
std::vector<Eigen::Vector3d> deck() { return testing::sampleRectangle({0, 0, 3}, {4, 0, 0}, {0, 3, 0}, 0.05); }

TEST(MapImport, RefusesBadOptionsBeforeReadingAnyFile) {
  MapImportOptions options;
  EXPECT_NE(errorOf(options).find("give a point cloud or a mesh"), std::string::npos);
  options.points = "/nonexistent/cloud.pcd";
  EXPECT_EQ(errorOf(options), "(no error)");  // files are read by importMap
  options.mesh = "/nonexistent/mesh.stl";
  EXPECT_NE(errorOf(options).find("one of the two"), std::string::npos);
  options.points.clear();
  options.origins = "origins.csv";
  EXPECT_NE(errorOf(options).find("sensor origins go with a point cloud"), std::string::npos);
  options = MapImportOptions{};
  options.points = "cloud.pcd";
  options.resolution_m = 5.0;
  EXPECT_NE(errorOf(options).find("resolution of 5 m is outside 0.01 to 1 m"), std::string::npos);
  options.resolution_m = 0.1;
  options.max_range_m = -1.0;
  EXPECT_NE(errorOf(options).find("maximum range of -1 m"), std::string::npos);
  options.max_range_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(errorOf(options), "(no error)");
  options.max_range_m = 0.0;
  options.interior = "porous";
  EXPECT_NE(errorOf(options).find("porous"), std::string::npos);
  options.interior = "auto";
  options.crs = "EPSG:4326";
  EXPECT_NE(errorOf(options).find("is not a projected coordinate reference system"), std::string::npos);
  EXPECT_THROW(importMap(options), InputError);
}

TEST(MapImport, RefusesACropBoxWithoutVolumeOrFiniteCorners) {
  MapImportOptions options;
  options.points = "/nonexistent/cloud.pcd";
  options.crop_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, std::nan("")));
  EXPECT_EQ(errorOf(options).rfind("a crop box needs finite corners", 0), 0u) << errorOf(options);
  options.crop_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(errorOf(options), "a crop box's z minimum (1) must be below its maximum (1)");
  options.crop_m = Eigen::AlignedBox3d();
  EXPECT_EQ(errorOf(options), "a crop box must have corners; leave it out for no crop");
  options.crop_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 1, 1));
  EXPECT_EQ(errorOf(options), "(no error)");
}

TEST(MapImport, BuildsAMapFromACloudAlone) {
  const auto dir = testing::scratchDirectory("map_import_cloud");
  testing::writePcd(dir / "deck.pcd", deck(), true);
  MapImportOptions options;
  options.points = dir / "deck.pcd";
  std::string last_stage;
  double last_fraction = 0.0;
  const MapImport imported = importMap(options, [&](const std::string& stage, double fraction) {
    last_stage = stage;
    last_fraction = fraction;
  });
  EXPECT_FALSE(imported.from_mesh);
  EXPECT_EQ(imported.source, dir / "deck.pcd");
  ASSERT_TRUE(imported.built.tree);
  EXPECT_NEAR(imported.built.tree->getResolution(), 0.1, 1e-12);
  EXPECT_TRUE(imported.built.tree->isNodeOccupied(imported.built.tree->search(2.0, 1.5, 3.0)));
  EXPECT_NEAR(imported.extent_m.min().x(), 0.0, 0.1 + 1e-9);
  EXPECT_NEAR(imported.extent_m.max().y(), 3.0, 0.1 + 1e-9);
  EXPECT_EQ(imported.skipped_non_finite_points, 0u);
  EXPECT_FALSE(imported.frame);
  EXPECT_EQ(last_stage, "importing " + (dir / "deck.pcd").string());
  EXPECT_EQ(last_fraction, 1.0);
}

TEST(MapImport, RefusesOrSkipsNonFinitePoints) {
  const auto dir = testing::scratchDirectory("map_import_nan");
  std::vector<Eigen::Vector3d> points = deck();
  points[1].z() = std::numeric_limits<double>::quiet_NaN();
  testing::writePcd(dir / "nan.pcd", points, true);
  MapImportOptions options;
  options.points = dir / "nan.pcd";
  try {
    importMap(options);
    FAIL() << "a NaN point was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nan.pcd: point 1 (counting from 0) has a non-finite coordinate"),
              std::string::npos)
        << e.what();
  }
  options.skip_non_finite = true;
  EXPECT_EQ(importMap(options).skipped_non_finite_points, 1u);
}

TEST(MapImport, WritesTheMapAndItsSummaryTogether) {
  const auto dir = testing::scratchDirectory("map_import_write");
  testing::writeStlBinary(dir / "box.stl", testing::boxMesh({0, 0, 0}, {2, 2, 1}));
  MapImportOptions options;
  options.mesh = dir / "box.stl";
  options.resolution_m = 0.2;
  const MapImport imported = importMap(options);
  EXPECT_TRUE(imported.from_mesh);

  const nlohmann::json summary = mapImportJson(imported, options, dir / "out" / "box.bt");
  EXPECT_EQ(summary["map"], "box.bt");
  EXPECT_EQ(summary["kind"], "mesh");
  EXPECT_TRUE(summary["origins"].is_null());
  EXPECT_TRUE(summary["crs"].is_null());
  EXPECT_EQ(summary["resolution_m"].get<double>(), 0.2);
  EXPECT_EQ(summary["free_space"], imported.built.free_space);
  EXPECT_EQ(summary["figures"].size(), imported.built.figures.size());
  EXPECT_NEAR(summary["extent_m"]["min"][0].get<double>(), -1.0, 0.2 + 1e-9);  // the default 1 m margin

  const Provenance provenance = Provenance::of("ceilplan import --mesh box.stl");
  writeImportedMap(dir / "out" / "box.bt", imported, options, provenance);
  octomap::OcTree read_back(0.2);
  ASSERT_TRUE(read_back.readBinary((dir / "out" / "box.bt").string()));
  EXPECT_EQ(read_back.getNumLeafNodes(), imported.built.tree->getNumLeafNodes());
  EXPECT_EQ(nlohmann::json::parse(testing::readWholeFile(dir / "out" / "box.bt.json")),
            withProvenance(summary, provenance));

  EXPECT_THROW(writeImportedMap(dir / "box.ot", imported, options, Provenance::of("test")), InputError);
  EXPECT_THROW(writeImportedMap(dir / "out" / "box.bt" / "below_a_file.bt", imported, options, Provenance::of("test")),
               Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "box.ot"));
}

}  // namespace
}  // namespace ceilplan::io
