#include "ceilplan/environment/voxel_grid.hpp"

#include "generated_tree.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace ceilplan::environment {
namespace {

using detail::GeneratedTree;

constexpr int kKeyOffset = 32768;  // OctoMap key of global voxel index 0
constexpr int kTreeDepth = 16;

Index3 checkedSize(const Index3& size) {
  std::size_t count = 1;
  for (int axis = 0; axis < 3; ++axis) {
    if (size[axis] <= 0) throw ceilplan::InputError("voxel grid: every dimension must be at least one voxel");
    count *= static_cast<std::size_t>(size[axis]);
    if (count > VoxelGrid::kMaxVoxels)
      throw ceilplan::InputError("the map's known voxels span a box of " + std::to_string(size[0]) + " x " +
                                 std::to_string(size[1]) + " x " + std::to_string(size[2]) +
                                 " voxels, more than ceilplan indexes (" + std::to_string(VoxelGrid::kMaxVoxels) +
                                 "); crop the map or coarsen its resolution");
  }
  return size;
}

class TreeBuilder {
 public:
  TreeBuilder(const VoxelGrid& grid, GeneratedTree& tree) : grid_(grid), tree_(tree) {}

  void build(octomap::OcTreeNode* node, const Index3& cube_min, int cube_size) {
    const int half = cube_size / 2;
    for (unsigned child = 0; child < 8; ++child) {
      const Index3 child_min{cube_min[0] + ((child & 1) ? half : 0), cube_min[1] + ((child & 2) ? half : 0),
                             cube_min[2] + ((child & 4) ? half : 0)};
      const std::optional<CellState> state = uniformState(child_min, half);
      if (state == CellState::Unknown) continue;
      octomap::OcTreeNode* created = tree_.createNodeChild(node, child);
      if (state) {
        created->setLogOdds(*state == CellState::Occupied ? tree_.getClampingThresMaxLog()
                                                          : tree_.getClampingThresMinLog());
      } else {
        build(created, child_min, half);
      }
    }
  }

 private:
  // The state shared by every voxel of the cube (global indices), or nothing if they differ.
  std::optional<CellState> uniformState(const Index3& cube_min, int cube_size) const {
    Index3 lo, hi;
    bool whole_cube_inside = true;
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::max(cube_min[axis] - grid_.frame().origin()[axis], 0);
      hi[axis] = std::min(cube_min[axis] + cube_size - grid_.frame().origin()[axis], grid_.frame().size()[axis]);
      if (lo[axis] >= hi[axis]) return CellState::Unknown;
      whole_cube_inside = whole_cube_inside && hi[axis] - lo[axis] == cube_size;
    }
    const CellState first = whole_cube_inside ? grid_.at(lo[0], lo[1], lo[2]) : CellState::Unknown;
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i)
          if (grid_.at(i, j, k) != first) return std::nullopt;
    return first;
  }

  const VoxelGrid& grid_;
  GeneratedTree& tree_;
};

}  // namespace

GridFrame::GridFrame(double resolution_m, const Index3& origin, const Index3& size)
    : resolution_m_(resolution_m), inverse_resolution_(1.0 / resolution_m), origin_(origin), size_(checkedSize(size)) {
  if (!(resolution_m > 0.0) || !std::isfinite(resolution_m))
    throw ceilplan::InputError("voxel grid: resolution must be a positive number of metres");
}

Eigen::AlignedBox3d GridFrame::bounds() const {
  return Eigen::AlignedBox3d(Eigen::Vector3d(faceOf(0, 0), faceOf(1, 0), faceOf(2, 0)),
                             Eigen::Vector3d(faceOf(0, size_[0]), faceOf(1, size_[1]), faceOf(2, size_[2])));
}

VoxelGrid::VoxelGrid(const GridFrame& frame) : frame_(frame), cells_(frame.voxelCount(), CellState::Unknown) {}

void VoxelGrid::fillBox(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m, CellState state) {
  Index3 lo, hi;
  const double inverse_resolution = 1.0 / frame_.resolution_m();
  for (int axis = 0; axis < 3; ++axis) {
    // Voxels whose centre (g + 0.5) r lies in [min, max).
    const auto first = [&](double bound) {
      return std::clamp(std::ceil(bound * inverse_resolution - 0.5) - frame_.origin()[axis], 0.0,
                        double(frame_.size()[axis]));
    };
    lo[axis] = static_cast<int>(first(min_m[axis]));
    hi[axis] = static_cast<int>(first(max_m[axis]));
  }
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) set(i, j, k, state);
}

VoxelGrid VoxelGrid::fromTree(const octomap::OcTree& tree, const std::function<void(double)>& progress, int workers) {
  struct Leaf {
    octomap::OcTreeKey corner;
    int width;
    CellState state;
  };
  std::vector<Leaf> leaves;
  leaves.reserve(tree.getNumLeafNodes());
  Index3 lo{std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), std::numeric_limits<int>::max()};
  Index3 hi{std::numeric_limits<int>::min(), std::numeric_limits<int>::min(), std::numeric_limits<int>::min()};
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const Leaf leaf{it.getIndexKey(), 1 << (kTreeDepth - static_cast<int>(it.getDepth())),
                    tree.isNodeOccupied(*it) ? CellState::Occupied : CellState::Free};
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::min(lo[axis], static_cast<int>(leaf.corner[axis]));
      hi[axis] = std::max(hi[axis], static_cast<int>(leaf.corner[axis]) + leaf.width);
    }
    leaves.push_back(leaf);
  }
  if (leaves.empty()) throw ceilplan::InputError("the map is empty (no known voxel)");
  VoxelGrid grid(GridFrame(tree.getResolution(), Index3{lo[0] - kKeyOffset, lo[1] - kKeyOffset, lo[2] - kKeyOffset},
                           Index3{hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}));
  // Leaves are disjoint, so threads writing different leaves never share a voxel.
  const std::size_t chunk = 1024;
  parallelFor((leaves.size() + chunk - 1) / chunk, workers,
              [&](std::size_t c) {
                for (std::size_t n = c * chunk; n < std::min(leaves.size(), (c + 1) * chunk); ++n) {
                  const Leaf& leaf = leaves[n];
                  const int i0 = leaf.corner[0] - lo[0], j0 = leaf.corner[1] - lo[1], k0 = leaf.corner[2] - lo[2];
                  for (int k = k0; k < k0 + leaf.width; ++k)
                    for (int j = j0; j < j0 + leaf.width; ++j) {
                      CellState* row = grid.cells_.data() + grid.frame_.linear(i0, j, k);
                      std::fill(row, row + leaf.width, leaf.state);
                    }
                }
              },
              progress);
  return grid;
}

std::unique_ptr<octomap::OcTree> toOcTree(const VoxelGrid& grid) {
  auto tree = std::make_unique<GeneratedTree>(grid.frame().resolution_m());
  octomap::OcTreeNode* root = tree->createRoot();
  TreeBuilder(grid, *tree).build(root, Index3{-kKeyOffset, -kKeyOffset, -kKeyOffset}, 1 << kTreeDepth);
  tree->updateInnerOccupancy();
  return tree;
}

}  // namespace ceilplan::environment
