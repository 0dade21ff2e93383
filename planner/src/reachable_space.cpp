#include "ceilplan/planner/reachable_space.hpp"

#include "lattice_grid.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include <cmath>

namespace ceilplan::planner {

ReachableSpace::ReachableSpace(const SafetyRules& rules, const Eigen::Vector3d& origin_m, double spacing_m, int workers)
    : rules_(rules), origin_m_(origin_m), requested_spacing_m_(spacing_m) {
  if (!(std::isfinite(spacing_m) && spacing_m > 0.0))
    throw ceilplan::InputError("the reachable space's lattice spacing must be a positive number of metres, got " +
                               formatNumber(spacing_m));
  const environment::Environment& environment = rules.environment();
  if (!origin_m.allFinite() || !environment.contains(origin_m) || !rules.isStateValid(origin_m))
    throw ceilplan::InputError("the reachable space's origin " + formatPoint(origin_m) + " is not a valid state");
  const detail::LatticeGrid lattice(environment.grid().frame(), spacing_m);
  spacing_m_ = lattice.spacing_m();
  reached_.assign(lattice.nodeCount(), 0);

  std::vector<std::size_t> frontier;
  lattice.forEachNodeNear(origin_m, [&](std::size_t id) {
    if (rules.isMotionValid(origin_m, lattice.position(id))) frontier.push_back(id);
  });
  for (const std::size_t id : frontier) reached_[id] = 1;
  // Breadth first, a level at a time: the level's motions are checked on the workers (reading
  // reached_ only), then its new nodes are marked, so the result does not depend on the threads.
  const detail::LatticeDirections directions;
  while (!frontier.empty()) {
    reached_count_ += frontier.size();
    std::vector<std::vector<std::size_t>> found(frontier.size());
    parallelFor(frontier.size(), workers, [&](std::size_t k) {
      const std::array<int, 3> at = lattice.indices(frontier[k]);
      const Eigen::Vector3d from_m = lattice.position(frontier[k]);
      for (const std::array<int, 3>& offset : directions.offsets) {
        const int a = at[0] + offset[0], b = at[1] + offset[1], c = at[2] + offset[2];
        if (!lattice.inside(a, b, c)) continue;
        const std::size_t to = lattice.id(a, b, c);
        if (reached_[to]) continue;
        // The end first: a node inside structure costs one state check, not a walk up to it.
        const Eigen::Vector3d to_m = lattice.position(a, b, c);
        if (rules.isStateValid(to_m) && rules.isMotionValid(from_m, to_m)) found[k].push_back(to);
      }
    });
    frontier.clear();
    for (const std::vector<std::size_t>& ids : found)
      for (const std::size_t id : ids)
        if (!reached_[id]) {
          reached_[id] = 1;
          frontier.push_back(id);
        }
  }
}

bool ReachableSpace::reaches(const Eigen::Vector3d& body_m) const {
  const environment::Environment& environment = rules_.environment();
  if (!body_m.allFinite() || !environment.contains(body_m) || !rules_.isStateValid(body_m)) return false;
  const detail::LatticeGrid lattice(environment.grid().frame(), spacing_m_);
  if ((body_m - origin_m_).norm() <= lattice.joinRadius_m() && rules_.isMotionValid(origin_m_, body_m)) return true;
  bool reached = false;
  lattice.forEachNodeNear(body_m, [&](std::size_t id) {
    if (!reached && reached_[id]) reached = rules_.isMotionValid(body_m, lattice.position(id));
  });
  return reached;
}

}  // namespace ceilplan::planner
