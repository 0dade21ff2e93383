// OctoMap files written whole: .bt (maximum likelihood) and .ot (OctoMap's full format).

#include "ceilplan/io/octomap_file.hpp"

#include "ceilplan/core/error.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>
#include <octomap/OcTree.h>

#include <filesystem>
#include <memory>

namespace ceilplan::io {
namespace {

octomap::OcTree smallTree() {
  octomap::OcTree tree(0.1);
  for (int i = 0; i < 10; ++i) tree.updateNode(octomap::point3d(0.1f * i, 0.0f, 1.0f), true);
  tree.updateNode(octomap::point3d(0.0f, 0.5f, 0.5f), false);
  return tree;
}

TEST(OctoMapFile, WritesBinaryAndFullFilesOctoMapReadsBack) {
  const auto dir = testing::scratchDirectory("octomap_file");
  const octomap::OcTree tree = smallTree();
  writeOctoMapFile(dir / "map.bt", tree);
  octomap::OcTree binary(0.1);
  ASSERT_TRUE(binary.readBinary((dir / "map.bt").string()));
  EXPECT_EQ(binary.getNumLeafNodes(), tree.getNumLeafNodes());
  EXPECT_TRUE(binary.isNodeOccupied(binary.search(0.5, 0.0, 1.0)));

  writeOctoMapFile(dir / "map.ot", tree);
  const std::unique_ptr<octomap::AbstractOcTree> full(octomap::AbstractOcTree::read((dir / "map.ot").string()));
  ASSERT_TRUE(full);
  const auto* read_back = dynamic_cast<const octomap::OcTree*>(full.get());
  ASSERT_NE(read_back, nullptr);
  EXPECT_EQ(read_back->size(), tree.size());
  EXPECT_FLOAT_EQ(read_back->search(0.0, 0.5, 0.5)->getLogOdds(), tree.search(0.0, 0.5, 0.5)->getLogOdds());
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

TEST(OctoMapFile, RefusesOtherExtensionsBeforeWriting) {
  const auto dir = testing::scratchDirectory("octomap_file_bad");
  EXPECT_TRUE(isOctoMapFileName("a/b.bt"));
  EXPECT_TRUE(isOctoMapFileName("b.ot"));
  EXPECT_FALSE(isOctoMapFileName("b.bt.txt"));
  EXPECT_THROW(writeOctoMapFile(dir / "map.txt", smallTree()), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "map.txt"));
  writeOctoMapFile(dir / "map.bt", smallTree());
  EXPECT_THROW(writeOctoMapFile(dir / "map.bt" / "below_a_file.bt", smallTree()), Error);
}

}  // namespace
}  // namespace ceilplan::io
