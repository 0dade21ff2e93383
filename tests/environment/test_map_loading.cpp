// Loading OctoMaps: real files load; damaged or foreign ones give one clear line.

#include "analytic_maps.hpp"
#include "run_command.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/environment/environment.hpp"

#include <octomap/ColorOcTree.h>
#include <octomap/OcTreeStamped.h>

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace ceilplan::environment {
namespace {

const std::filesystem::path kGeb079 = "/usr/share/doc/liboctomap-dev/examples/data/geb079.bt";

std::string loadError(const std::filesystem::path& file) {
  try {
    OccupancyMap::load(file);
  } catch (const ceilplan::InputError& e) {
    return e.what();
  }
  return "(loaded)";
}

void writeBytes(const std::filesystem::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

void expectOneLineNaming(const std::string& message, const std::filesystem::path& file, const std::string& problem) {
  EXPECT_NE(message.find(file.string()), std::string::npos) << message;
  EXPECT_NE(message.find(problem), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(MapLoading, BadFilesGiveOneLineNamingTheFileAndTheProblem) {
  const auto dir = testing::scratchDirectory("bad_maps");
  expectOneLineNaming(loadError(dir / "missing.bt"), dir / "missing.bt", "no such map file");

  writeBytes(dir / "text.bt", "hello, I am not a map\n");
  expectOneLineNaming(loadError(dir / "text.bt"), dir / "text.bt", "not an OctoMap file");

  const std::string whole = testing::readWholeFile(CEILPLAN_SOURCE_DIR "/maps/open.bt");
  writeBytes(dir / "truncated.bt", whole.substr(0, whole.size() / 2));
  expectOneLineNaming(loadError(dir / "truncated.bt"), dir / "truncated.bt", "truncated");

  octomap::OcTree empty(0.1);
  empty.writeBinary((dir / "empty.bt").string());
  expectOneLineNaming(loadError(dir / "empty.bt"), dir / "empty.bt", "empty");

  // A .ot of a tree type whose node records ceilplan cannot read (ColorOcTree and OcTreeStamped
  // are converted: see OtherTreeTypes below).
  std::ostringstream stream;
  octomap::OcTree plain(0.1);
  plain.updateNode(octomap::point3d(0.05f, 0.05f, 0.05f), true);
  plain.write(stream);
  std::string foreign = stream.str();
  foreign.replace(foreign.find("id OcTree"), 9, "id SemanticOcTree");
  writeBytes(dir / "semantic.ot", foreign);
  expectOneLineNaming(loadError(dir / "semantic.ot"), dir / "semantic.ot", "SemanticOcTree");

  // A node stream deeper than OctoMap's 16 levels: OctoMap alone would recurse until the data ran out.
  writeBytes(dir / "deep.bt",
             "# Octomap OcTree binary file\nid OcTree\nsize 100\nres 0.1\ndata\n" + std::string(200, '\xff'));
  expectOneLineNaming(loadError(dir / "deep.bt"), dir / "deep.bt", "corrupt");
}

// OctoMap stops where its tree ends: bytes after it, or a second tree, would be dropped unseen.
// A FIFO, a device or a directory is refused before it is opened (a FIFO would block, /dev/zero
// would be read for ever), and so is a file larger than ceilplan could index.
TEST(MapLoading, ATreeMustBeTheWholeFileAndTheFileARegularOne) {
  const auto dir = testing::scratchDirectory("whole_maps");
  const std::string bt = testing::readWholeFile(CEILPLAN_SOURCE_DIR "/maps/open.bt");
  std::ostringstream full;
  OccupancyMap::load(CEILPLAN_SOURCE_DIR "/maps/open.bt").tree().write(full);
  const std::string ot = full.str();
  writeBytes(dir / "trailing.bt", bt + "junk");
  writeBytes(dir / "newline.bt", bt + "\n");
  writeBytes(dir / "two.bt", bt + bt);
  writeBytes(dir / "trailing.ot", ot + "junk");
  writeBytes(dir / "two.ot", ot + ot);
  writeBytes(dir / "binary_then_full.bt", bt + ot);
  ASSERT_EQ(::mkfifo((dir / "pipe.bt").c_str(), 0600), 0);
  std::filesystem::create_directories(dir / "folder.bt");
  const struct {
    std::string file, says;
  } rows[] = {
      {"trailing.bt",
       "corrupt OctoMap file: 4 bytes follow the end of the tree; is the file damaged, or two files joined?"},
      {"newline.bt", "corrupt OctoMap file: 1 byte follows the end of the tree"},
      {"two.bt", "holds a second OctoMap tree after the first; a map file holds one tree, so split the file"},
      {"trailing.ot", "corrupt OctoMap file: 4 bytes follow the end of the tree"},
      {"two.ot", "holds a second OctoMap tree after the first"},
      {"binary_then_full.bt", "holds a second OctoMap tree after the first"},
      {"pipe.bt", "is a FIFO (named pipe), not a map file; give a regular file"},
      {"folder.bt", "is a directory, not a map file; give a regular file"},
  };
  ::alarm(60);  // a reader blocked on the FIFO kills the test rather than hanging it
  for (const auto& row : rows) expectOneLineNaming(loadError(dir / row.file), dir / row.file, row.says);
  expectOneLineNaming(loadError("/dev/zero"), "/dev/zero", "/dev/zero: is a device, not a map file");
  ::alarm(0);
  // The bound is stated before the read: a sparse file of that size costs nothing to make.
  {
    std::ofstream huge(dir / "huge.bt", std::ios::binary);
    huge << "# Octomap OcTree binary file\n";
    huge.seekp(static_cast<std::streamoff>(OccupancyMap::kMaxFileBytes));
    huge << 'x';
  }
  expectOneLineNaming(
      loadError(dir / "huge.bt"), dir / "huge.bt",
      "holds " + std::to_string(OccupancyMap::kMaxFileBytes + 1) + " bytes, more than ceilplan reads for a map file");
}

// Two voxels 1.5 km apart at 5 cm: the map loads, but its box holds more voxels than ceilplan
// indexes; the refusal names the map's file.
TEST(MapLoading, AMapTooLargeToIndexIsRefusedNamingItsFile) {
  const auto dir = testing::scratchDirectory("far_map");
  octomap::OcTree far(0.05);
  far.updateNode(octomap::point3d(0.0f, 0.0f, 0.0f), true);
  far.updateNode(octomap::point3d(1500.0f, 1500.0f, 100.0f), true);
  far.writeBinary((dir / "far.bt").string());
  const OccupancyMap map = OccupancyMap::load(dir / "far.bt");
  std::string message = "(indexed)";
  try {
    MapIndex::build(map);
  } catch (const ceilplan::InputError& e) {
    message = e.what();
  }
  expectOneLineNaming(message, dir / "far.bt", "more than ceilplan indexes");
}

TEST(MapLoading, FullFormatAndBinaryFormatLoadTheSameTree) {
  const auto dir = testing::scratchDirectory("formats");
  const OccupancyMap binary = OccupancyMap::load(CEILPLAN_SOURCE_DIR "/maps/open.bt");
  binary.tree().write((dir / "open.ot").string());
  const OccupancyMap full = OccupancyMap::load(dir / "open.ot");
  EXPECT_EQ(full.tree().size(), binary.tree().size());
  EXPECT_DOUBLE_EQ(full.resolution_m(), 0.1);
}

// Occupied walls and floor around free air, a few unknown voxels: set identically in a tree of
// each type (colours by height in a ColorOcTree), so their occupancy must load identically.
template <class Tree>
void fillRoom(Tree& tree) {
  for (double z = 0.05; z < 1.6; z += 0.1)
    for (double y = -0.95; y < 1.0; y += 0.1)
      for (double x = -1.45; x < 1.5; x += 0.1) {
        if (x > 0.9 && z > 1.0) continue;  // unknown corner
        const bool occupied = z < 0.2 || std::abs(x) > 1.3 || std::abs(y) > 0.8 || (x > -0.2 && x < 0.2 && z < 0.8);
        tree.setNodeValue(octomap::point3d(float(x), float(y), float(z)),
                          occupied ? tree.getClampingThresMaxLog() : tree.getClampingThresMinLog(), true);
      }
  tree.updateInnerOccupancy();
  tree.prune();
}

void expectSameOccupancy(const OccupancyMap& loaded, const octomap::OcTree& reference) {
  const VoxelGrid a = VoxelGrid::fromTree(loaded.tree()), b = VoxelGrid::fromTree(reference);
  ASSERT_EQ(a.frame().size(), b.frame().size());
  ASSERT_EQ(a.frame().origin(), b.frame().origin());
  std::size_t occupied = 0, free = 0;
  for (std::size_t v = 0; v < a.frame().voxelCount(); ++v) {
    ASSERT_EQ(a.atLinear(v), b.atLinear(v)) << v;
    occupied += a.atLinear(v) == CellState::Occupied;
    free += a.atLinear(v) == CellState::Free;
  }
  EXPECT_GT(occupied, 300u);
  EXPECT_GT(free, 300u);
}

TEST(MapLoading, OtherOccupancyTreesLoadAsTheirOccupancy) {
  const auto dir = testing::scratchDirectory("tree_types");
  octomap::OcTree reference(0.1);
  fillRoom(reference);

  octomap::ColorOcTree colour(0.1);
  fillRoom(colour);
  for (auto it = colour.begin_leafs(), end = colour.end_leafs(); it != end; ++it)
    it->setColor(static_cast<uint8_t>(it.getZ() * 100), 40, colour.isNodeOccupied(*it) ? 200 : 10);
  ASSERT_TRUE(colour.write((dir / "colour.ot").string()));
  ASSERT_TRUE(colour.writeBinary((dir / "colour.bt").string()));
  expectSameOccupancy(OccupancyMap::load(dir / "colour.ot"), reference);
  expectSameOccupancy(OccupancyMap::load(dir / "colour.bt"), reference);

  octomap::OcTreeStamped stamped(0.1);
  fillRoom(stamped);
  ASSERT_TRUE(stamped.write((dir / "stamped.ot").string()));
  expectSameOccupancy(OccupancyMap::load(dir / "stamped.ot"), reference);

  // A ColorOcTree cut short is still caught before OctoMap reads it.
  const std::string whole = testing::readWholeFile(dir / "colour.ot");
  writeBytes(dir / "cut.ot", whole.substr(0, whole.size() - 9));
  expectOneLineNaming(loadError(dir / "cut.ot"), dir / "cut.ot", "truncated");
}

TEST(MapLoading, AGridSurvivesTheTripThroughAnOcTree) {
  VoxelGrid grid(GridFrame(0.1, {-7, 2, -3}, {13, 9, 11}));
  grid.fillBox({-0.5, 0.3, -0.2}, {0.4, 0.9, 0.6}, CellState::Free);
  grid.fillBox({-0.2, 0.4, 0.0}, {0.1, 0.6, 0.3}, CellState::Occupied);
  const std::unique_ptr<octomap::OcTree> tree = toOcTree(grid);
  const VoxelGrid back = VoxelGrid::fromTree(*tree);
  const Eigen::AlignedBox3d box = grid.frame().bounds();
  for (double z = box.min().z() + 0.05; z < box.max().z(); z += 0.1)
    for (double y = box.min().y() + 0.05; y < box.max().y(); y += 0.1)
      for (double x = box.min().x() + 0.05; x < box.max().x(); x += 0.1) {
        const GridFrame& a = grid.frame();
        const GridFrame& b = back.frame();
        EXPECT_EQ(grid.at(a.indexOf(0, x), a.indexOf(1, y), a.indexOf(2, z)),
                  back.at(b.indexOf(0, x), b.indexOf(1, y), b.indexOf(2, z)));
      }
}

TEST(RealScan, Geb079LoadsWithItsFloorAtZeroAndItsCeilingAboutTwoSixtyFiveUp) {
  const OccupancyMap map = OccupancyMap::load(kGeb079);
  EXPECT_DOUBLE_EQ(map.resolution_m(), 0.08);
  const Environment environment(map, testing::quad());
  // Over the corridor at 1.5 m: where the scan saw them, the floor and ceiling heights.
  std::vector<double> floors, ceilings;
  for (double x = 0.0; x <= 22.0; x += 0.5)
    for (double y = -0.5; y <= 0.5; y += 0.5) {
      const Eigen::Vector3d p(x, y, 1.5);
      if (std::isfinite(environment.ceilingGapAt(p))) ceilings.push_back(1.5 + environment.ceilingGapAt(p));
      if (std::isfinite(environment.groundGapAt(p))) floors.push_back(1.5 - environment.groundGapAt(p));
    }
  ASSERT_GT(ceilings.size(), 60u);
  ASSERT_GT(floors.size(), 20u);
  std::sort(ceilings.begin(), ceilings.end());
  std::sort(floors.begin(), floors.end());
  EXPECT_NEAR(ceilings[ceilings.size() / 2], 2.64, 0.1);
  EXPECT_NEAR(floors[floors.size() / 2], 0.0, 0.05);
  // Close under the ceiling the rotors see it over their whole discs.
  const SurfaceGaps gaps = environment.ceiling({3.0, 0.0, 2.45});
  EXPECT_GT(gaps.nearest_gap_m, 0.05);
  EXPECT_LT(gaps.nearest_gap_m, 0.3);
  EXPECT_GT(gaps.coverage, 0.9);
}

}  // namespace
}  // namespace ceilplan::environment
