#pragma once
// An OcTree whose root we create ourselves, to build a tree top-down node by node (scene
// generation, converting other tree types). Private to the environment module.

#include <octomap/OcTree.h>

namespace ceilplan::environment::detail {

class GeneratedTree : public octomap::OcTree {
 public:
  explicit GeneratedTree(double resolution_m) : OcTree(resolution_m) {}
  octomap::OcTreeNode* createRoot() {
    root = new octomap::OcTreeNode();
    ++tree_size;
    size_changed = true;
    return root;
  }
};

}  // namespace ceilplan::environment::detail
