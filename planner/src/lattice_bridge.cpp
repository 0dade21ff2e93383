#include "lattice_bridge.hpp"

#include "ceilplan/core/format.hpp"

#include <ompl/datastructures/NearestNeighborsGNAT.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <queue>

namespace ceilplan::planner {

std::string describe(BlockingRule rule) {
  switch (rule) {
    case BlockingRule::Clearance:
      return "the vehicle's clearance";
    case BlockingRule::Unknown:
      return "unknown space";
    case BlockingRule::MapEdge:
      return "the map's edge";
    case BlockingRule::CeilingGap:
      return "the minimum rotor gap to a ceiling";
  }
  return "an unknown rule";
}

namespace {

std::string openingText(double metres) { return std::isfinite(metres) ? formatFixed(metres, 2) + " m" : "open"; }

}  // namespace

std::string Blockage::describe() const {
  if (!enclosed_end.empty())
    return "the " + enclosed_end + " at " + formatPoint(enclosed_at_m) +
           " is enclosed: the space the vehicle reaches from it, within " + formatPoint(enclosure_min_m) + " to " +
           formatPoint(enclosure_max_m) + ", has no opening to the other side; move the " + enclosed_end +
           " or open the map there";
  std::string text = "blocked at " + formatPoint(position_m) + " by " + planner::describe(rule);
  if (rule == BlockingRule::Unknown) return text + " (the map has no data there, and unknown space counts as occupied)";
  if (rule != BlockingRule::Clearance || std::isnan(width_m)) return text;
  if (width_m == 0.0 || height_m == 0.0) return text + ": no opening there";
  return text + ": the opening there is " + openingText(width_m) + " wide and " + openingText(height_m) +
         " high, the vehicle needs " + formatFixed(needed_width_m, 2) + " x " + formatFixed(needed_height_m, 2) +
         " m with its margins";
}

namespace detail {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kCandidates = 24;           // pairs whose surroundings are measured
constexpr int kAttempts = 6;              // pairs tried with a fine search
constexpr double kShiftStepM = 0.2;       // between the ways measured parallel to a pair's
constexpr double kPairSeparationM = 1.0;  // between the middles of two pairs tried
constexpr double kReachM = 1.0;           // from the straight way between a pair, at least the vehicle's width
constexpr std::size_t kMaxFineNodes = 2'000'000;
constexpr double kOpeningReachM = 3.0;  // beyond it an opening counts as open
// The wide search: on the fine lattice, within twice kReachM of the closest pair's way,
// doubling until the box holds the map or this many nodes (13 bytes each).
constexpr std::size_t kMaxWideNodes = 8'000'000;

// A fine lattice over a box: spacing a multiple of half a voxel (at least `min_factor`),
// aligned with the voxel centres.
class FineLattice {
 public:
  FineLattice(const environment::GridFrame& frame, const Eigen::AlignedBox3d& box, int min_factor = 1,
              std::size_t max_nodes = kMaxFineNodes) {
    const Eigen::AlignedBox3d bounds = frame.bounds();
    const Eigen::AlignedBox3d clipped = box.intersection(bounds);
    covers_bounds_ = box.contains(bounds);
    const double half_voxel = 0.5 * frame.resolution_m();
    std::array<double, 3> extent{};
    for (int axis = 0; axis < 3; ++axis) {
      origin_[axis] = frame.centreOf(axis, 0);
      extent[axis] = std::max(0.0, clipped.max()[axis] - clipped.min()[axis]);
    }
    // Coarser only when the box would hold too many nodes.
    const double spacing = min_factor * half_voxel;
    const double cells = (extent[0] / spacing + 1) * (extent[1] / spacing + 1) * (extent[2] / spacing + 1);
    const int factor =
        min_factor * std::max(1, static_cast<int>(std::ceil(std::cbrt(cells / static_cast<double>(max_nodes)))));
    spacing_m_ = factor * half_voxel;
    for (int axis = 0; axis < 3; ++axis) {
      lo_[axis] = static_cast<int>(std::ceil((clipped.min()[axis] - origin_[axis]) / spacing_m_));
      const int hi = static_cast<int>(std::floor((clipped.max()[axis] - origin_[axis]) / spacing_m_));
      size_[axis] = std::max(0, hi - lo_[axis] + 1);
    }
  }

  std::size_t nodeCount() const { return static_cast<std::size_t>(size_[0]) * size_[1] * size_[2]; }
  double spacing_m() const { return spacing_m_; }
  bool coversBounds() const { return covers_bounds_; }  // the box held the whole map
  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < size_[0] && j < size_[1] && k < size_[2];
  }
  std::size_t id(int i, int j, int k) const { return (static_cast<std::size_t>(k) * size_[1] + j) * size_[0] + i; }
  std::array<int, 3> indices(std::size_t id) const {
    return {static_cast<int>(id % size_[0]), static_cast<int>((id / size_[0]) % size_[1]),
            static_cast<int>(id / (static_cast<std::size_t>(size_[0]) * size_[1]))};
  }
  Eigen::Vector3d position(int i, int j, int k) const {
    return {origin_[0] + (lo_[0] + i) * spacing_m_, origin_[1] + (lo_[1] + j) * spacing_m_,
            origin_[2] + (lo_[2] + k) * spacing_m_};
  }
  Eigen::Vector3d position(std::size_t id) const {
    const std::array<int, 3> i = indices(id);
    return position(i[0], i[1], i[2]);
  }
  // Nodes within sqrt(3) spacings of a point (a corner of its cell at least).
  template <typename Visit>
  void forEachNodeNear(const Eigen::Vector3d& point_m, Visit&& visit) const {
    int lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
      const double index = (point_m[axis] - origin_[axis]) / spacing_m_ - lo_[axis];
      lo[axis] = std::max(0, static_cast<int>(std::floor(index)) - 1);
      hi[axis] = std::min(size_[axis] - 1, static_cast<int>(std::ceil(index)) + 1);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i)
          if ((position(i, j, k) - point_m).norm() <= std::sqrt(3.0) * spacing_m_ + 1e-9) visit(id(i, j, k));
  }

 private:
  std::array<double, 3> origin_{};
  double spacing_m_ = 0.0;
  std::array<int, 3> lo_{}, size_{};
  bool covers_bounds_ = false;
};

// Distance from a point to the segment [a, b].
double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// The box within `radius_m` of the segment from `a` to `b`.
Eigen::AlignedBox3d boxAround(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double radius_m) {
  Eigen::AlignedBox3d box(a.cwiseMin(b), a.cwiseMax(b));
  box.min().array() -= radius_m;
  box.max().array() += radius_m;
  return box;
}

// The shortest path on `lattice` from `a` to `b` within `radius_m` of the segment between them
// (A*, 26-connected, valid states), its motions checked lazily: a motion found invalid is
// struck out and the search runs again. Connectivity is what matters here; the coarse search
// then prices the passage under the objective.
std::vector<Eigen::Vector3d> fineSearch(const SafetyRules& rules, const FineLattice& lattice, const Eigen::Vector3d& a,
                                        const Eigen::Vector3d& b, double radius_m,
                                        const ompl::base::PlannerTerminationCondition& ptc) {
  const std::size_t node_count = lattice.nodeCount();
  if (node_count == 0) return {};
  const std::size_t goal_id = node_count, start_id = node_count + 1;
  enum : std::uint8_t { kUnchecked = 0, kValid = 1, kInvalid = 2, kClosed = 4, kJoinsGoal = 8 };
  std::vector<std::uint8_t> flags(node_count, kUnchecked);
  const auto nodeAt = [&](std::size_t id) {
    if (id == goal_id) return b;
    if (id == start_id) return a;
    return lattice.position(id);
  };
  const auto nodeValid = [&](std::size_t id) {
    if (!(flags[id] & (kValid | kInvalid))) {
      const Eigen::Vector3d p = lattice.position(id);
      flags[id] |= distanceToSegment(p, a, b) <= radius_m && rules.environment().contains(p) && rules.isStateValid(p)
                       ? kValid
                       : kInvalid;
    }
    return (flags[id] & kValid) != 0;
  };
  std::vector<std::size_t> start_joins;
  lattice.forEachNodeNear(a, [&](std::size_t id) {
    if (nodeValid(id) && rules.isMotionValid(a, lattice.position(id))) start_joins.push_back(id);
  });
  lattice.forEachNodeNear(b, [&](std::size_t id) {
    if (nodeValid(id) && rules.isMotionValid(lattice.position(id), b)) flags[id] |= kJoinsGoal;
  });
  if (rules.isMotionValid(a, b)) return {a, b};

  std::vector<std::pair<std::uint32_t, std::uint32_t>> struck;  // motions found invalid, sorted
  const auto isStruck = [&](std::size_t from, std::size_t to) {
    return std::binary_search(struck.begin(), struck.end(),
                              std::make_pair(static_cast<std::uint32_t>(from), static_cast<std::uint32_t>(to)));
  };
  std::vector<double> cost_to(node_count + 2);
  std::vector<std::uint32_t> parent(node_count + 2);
  for (int round = 0; round < 64 && !ptc(); ++round) {
    std::fill(cost_to.begin(), cost_to.end(), kInfinity);
    for (std::uint8_t& flag : flags) flag &= static_cast<std::uint8_t>(~kClosed);
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
    const auto relax = [&](std::size_t from, std::size_t to, double g) {
      if (g < cost_to[to]) {
        cost_to[to] = g;
        parent[to] = static_cast<std::uint32_t>(from);
        open.emplace(g + (nodeAt(to) - b).norm(), to);
      }
    };
    cost_to[start_id] = 0.0;
    for (std::size_t id : start_joins) relax(start_id, id, (lattice.position(id) - a).norm());
    std::size_t expansions = 0;
    while (!open.empty()) {
      const std::size_t id = open.top().second;
      open.pop();
      if (id == goal_id) break;
      if (flags[id] & kClosed) continue;
      flags[id] |= kClosed;
      if (++expansions % 4096 == 0 && ptc()) return {};
      const Eigen::Vector3d here = lattice.position(id);
      if (flags[id] & kJoinsGoal) relax(id, goal_id, cost_to[id] + (b - here).norm());
      const std::array<int, 3> at = lattice.indices(id);
      for (int dk = -1; dk <= 1; ++dk)
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di) {
            if ((di | dj | dk) == 0 || !lattice.inside(at[0] + di, at[1] + dj, at[2] + dk)) continue;
            const std::size_t next = lattice.id(at[0] + di, at[1] + dj, at[2] + dk);
            if ((flags[next] & kClosed) || !nodeValid(next) || isStruck(id, next)) continue;
            relax(id, next, cost_to[id] + (lattice.position(next) - here).norm());
          }
    }
    if (!std::isfinite(cost_to[goal_id])) return {};
    // Check the motions of the path found; strike out the invalid ones and search again.
    std::vector<std::size_t> nodes;
    for (std::size_t id = goal_id; id != start_id; id = parent[id]) nodes.push_back(id);
    nodes.push_back(start_id);
    std::reverse(nodes.begin(), nodes.end());
    bool valid = true;
    for (std::size_t k = 2; k + 1 < nodes.size(); ++k)
      if (!rules.isMotionValid(nodeAt(nodes[k - 1]), nodeAt(nodes[k]))) {
        struck.emplace_back(static_cast<std::uint32_t>(nodes[k - 1]), static_cast<std::uint32_t>(nodes[k]));
        struck.emplace_back(static_cast<std::uint32_t>(nodes[k]), static_cast<std::uint32_t>(nodes[k - 1]));
        valid = false;
      }
    if (valid) {
      std::vector<Eigen::Vector3d> path;
      for (std::size_t id : nodes) path.push_back(nodeAt(id));
      return turningPoints(path);
    }
    std::sort(struck.begin(), struck.end());
  }
  return {};
}

enum class CellKind { Free, Occupied, Unknown, Edge };

// How far space stays open from `point_m` along `direction`, up to kOpeningReachM (+inf
// beyond), and what ends it: an occupied voxel, an unknown one (unless `unknown_is_open` or the
// map's policy counts it free) or the map's edge.
struct Run {
  double length_m = kInfinity;
  CellKind end = CellKind::Free;
};

Run openRun(const environment::Environment& environment, const Eigen::Vector3d& point_m,
            const Eigen::Vector3d& direction, bool unknown_is_open) {
  const environment::VoxelGrid& grid = environment.grid();
  const environment::GridFrame& frame = grid.frame();
  const environment::MapIndex& index = *environment.index();
  const bool unknown_blocks = index.unknownBlocks() && !unknown_is_open;
  const auto kindAt = [&](double s) {
    const Eigen::Vector3d p = point_m + s * direction;
    if (!frame.contains(p)) return CellKind::Edge;  // the body must stay in the map, whatever the policy
    const environment::CellState cell =
        grid.at(frame.indexOf(0, p.x()), frame.indexOf(1, p.y()), frame.indexOf(2, p.z()));
    if (cell == environment::CellState::Occupied) return CellKind::Occupied;
    return unknown_blocks && cell == environment::CellState::Unknown && !index.isAssumedFree(p) ? CellKind::Unknown
                                                                                                : CellKind::Free;
  };
  const double step_m = 0.25 * frame.resolution_m();
  for (double s = 0.0; s <= kOpeningReachM; s += step_m) {
    const CellKind kind = kindAt(s);
    if (kind == CellKind::Free) continue;
    if (s == 0.0) return {0.0, kind};
    // The face between the last open sample and this one, to a millimetre.
    double open = s - step_m, closed = s;
    while (closed - open > 1e-3) {
      const double middle = 0.5 * (open + closed);
      (kindAt(middle) == CellKind::Free ? open : closed) = middle;
    }
    return {0.5 * (open + closed), kind};
  }
  return {};
}

// The vehicle's extent (with its margins) along a unit direction: the inflated cylinder's
// support width.
double vehicleExtent(const environment::VehicleGeometry& vehicle, const Eigen::Vector3d& direction) {
  const double vertical = std::abs(direction.z());
  return 2.0 * vehicle.inflatedRadius_m() * std::sqrt(std::max(0.0, 1.0 - vertical * vertical)) +
         (vehicle.inflatedTop_m() - vehicle.inflatedBottom_m()) * vertical;
}

// The opening across a way at one point: its extents along the two directions square to the
// way (sideways first), what the vehicle needs along each, the tighter one's ratio (below 1:
// too tight) and what bounds it.
struct Opening {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double across_m[2] = {0.0, 0.0};
  double needed_m[2] = {0.0, 0.0};
  double ratio = kInfinity;
  CellKind bound = CellKind::Free;
};

Opening openingAt(const environment::Environment& environment, const Eigen::Vector3d& point_m,
                  const Eigen::Vector3d& way, bool unknown_is_open) {
  Eigen::Vector3d side = way.cross(Eigen::Vector3d::UnitZ());
  side = side.norm() > 1e-6 ? Eigen::Vector3d(side.normalized()) : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d directions[2] = {side, way.cross(side).normalized()};
  // The map's edge first, then unknown space: the rule a user can act on.
  const auto rank = [](CellKind kind) { return kind == CellKind::Edge ? 3 : kind == CellKind::Unknown ? 2 : 1; };
  Opening opening;
  opening.position_m = point_m;
  for (int d = 0; d < 2; ++d) {
    const Run forth = openRun(environment, point_m, directions[d], unknown_is_open);
    const Run back = forth.length_m == 0.0 ? forth : openRun(environment, point_m, -directions[d], unknown_is_open);
    opening.across_m[d] = forth.length_m == 0.0 ? 0.0 : forth.length_m + back.length_m;
    // Named at its middle, where it is bounded both ways.
    if (std::isfinite(opening.across_m[d]) && opening.across_m[d] > 0.0)
      opening.position_m += 0.5 * (forth.length_m - back.length_m) * directions[d];
    opening.needed_m[d] = vehicleExtent(environment.vehicle(), directions[d]);
    const double ratio = opening.across_m[d] / opening.needed_m[d];
    if (ratio < opening.ratio) {
      opening.ratio = ratio;
      opening.bound = rank(forth.end) >= rank(back.end) ? forth.end : back.end;
    }
  }
  return opening;
}

// The tightest opening on the straight way between two points, sampled every voxel.
Opening constriction(const environment::Environment& environment, const Eigen::Vector3d& from_m,
                     const Eigen::Vector3d& to_m, bool unknown_is_open) {
  const double length_m = (to_m - from_m).norm();
  const Eigen::Vector3d way = length_m > 0.0 ? Eigen::Vector3d((to_m - from_m) / length_m) : Eigen::Vector3d::UnitX();
  const int steps = std::max(1, static_cast<int>(std::ceil(length_m / environment.grid().frame().resolution_m())));
  Opening tightest;
  for (int k = 0; k <= steps; ++k) {
    const Opening opening =
        openingAt(environment, from_m + (to_m - from_m) * (static_cast<double>(k) / steps), way, unknown_is_open);
    if (opening.ratio < tightest.ratio) tightest = opening;
  }
  return tightest;
}

// The most open of the straight ways parallel to the one between two points, shifted across
// it by up to `reach_m`: its tightest opening (a gap beside the straight way is found there).
Opening bottleneck(const environment::Environment& environment, const Eigen::Vector3d& from_m,
                   const Eigen::Vector3d& to_m, bool unknown_is_open, double reach_m) {
  const Eigen::Vector3d way =
      (to_m - from_m).norm() > 0.0 ? Eigen::Vector3d((to_m - from_m).normalized()) : Eigen::Vector3d::UnitX();
  Eigen::Vector3d side = way.cross(Eigen::Vector3d::UnitZ());
  side = side.norm() > 1e-6 ? Eigen::Vector3d(side.normalized()) : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d up = way.cross(side).normalized();
  const int reach = static_cast<int>(std::floor(reach_m / kShiftStepM));
  Opening best;
  best.ratio = -1.0;
  for (int j = -reach; j <= reach; ++j)
    for (int i = -reach; i <= reach; ++i) {
      const Eigen::Vector3d shift = kShiftStepM * (i * side + j * up);
      const Opening opening = constriction(environment, from_m + shift, to_m + shift, unknown_is_open);
      if (opening.ratio > best.ratio) best = opening;
    }
  return best;
}

}  // namespace

std::vector<Eigen::Vector3d> turningPoints(const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector3d> result;
  for (const Eigen::Vector3d& p : points) {
    if (!result.empty() && (p - result.back()).norm() < 1e-9) continue;
    if (result.size() >= 2) {
      const Eigen::Vector3d u = result[result.size() - 1] - result[result.size() - 2];
      const Eigen::Vector3d v = p - result.back();
      if (u.cross(v).norm() <= 1e-9 * u.norm() * v.norm() && u.dot(v) > 0.0) result.pop_back();
    }
    result.push_back(p);
  }
  return result;
}

Blockage diagnoseBlockage(const SafetyRules& rules, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) {
  const environment::Environment& environment = rules.environment();
  const Eigen::Vector3d way = (to_m - from_m).normalized();
  // The bottleneck near the way, counting unknown space open (so a gap it fills is found).
  const Eigen::Vector3d gap_m = bottleneck(environment, from_m, to_m, true, kReachM).position_m;
  // Measured square to the gap: of the cuts through it turned about the vertical, the tightest
  // (a cut askew across a slot measures it wider than it is).
  Eigen::Vector3d cut_way = way;
  Opening opening = openingAt(environment, gap_m, way, false);
  for (int degrees = -60; degrees <= 60; degrees += 5) {
    const Eigen::Vector3d turned = Eigen::AngleAxisd(degrees * M_PI / 180.0, Eigen::Vector3d::UnitZ()) * way;
    const Opening cut = openingAt(environment, gap_m, turned, false);
    if (cut.ratio < opening.ratio) {
      opening = cut;
      cut_way = turned;
    }
  }
  Blockage blockage;
  blockage.position_m = opening.position_m;
  blockage.width_m = opening.across_m[0];
  blockage.height_m = opening.across_m[1];
  blockage.needed_width_m = opening.needed_m[0];
  blockage.needed_height_m = opening.needed_m[1];
  if (!environment.contains(opening.position_m) || opening.bound == CellKind::Edge) {
    blockage.rule = BlockingRule::MapEdge;
  } else if (opening.ratio < 1.0) {
    // Unknown space blocks when it bounds the gap, or when counting it open widens the gap.
    blockage.rule =
        opening.bound == CellKind::Unknown || openingAt(environment, gap_m, cut_way, true).ratio > opening.ratio
            ? BlockingRule::Unknown
            : BlockingRule::Clearance;
  } else {
    // Wide enough along the two directions measured, and still blocked: by something askew
    // (a corner, a lamp), a crooked or short opening, or a ceiling too close to the rotors.
    // Name the rule the body breaks there, or nearest along the way.
    blockage.width_m = blockage.height_m = std::numeric_limits<double>::quiet_NaN();
    blockage.rule = BlockingRule::CeilingGap;
    const double step_m = environment.grid().frame().resolution_m();
    for (double s = 0.0; s <= kReachM; s += step_m) {
      std::optional<environment::Violation> violation;
      for (const Eigen::Vector3d& p : {Eigen::Vector3d(gap_m + s * way), Eigen::Vector3d(gap_m - s * way)})
        if (!violation && environment.contains(p)) violation = environment.stateViolation(p);
      if (!violation) continue;
      blockage.rule = violation->kind == environment::ViolationKind::Unknown      ? BlockingRule::Unknown
                      : violation->kind == environment::ViolationKind::OutsideMap ? BlockingRule::MapEdge
                                                                                  : BlockingRule::Clearance;
      break;
    }
  }
  return blockage;
}

void nameEnclosedEnd(Blockage& blockage, const environment::VoxelGrid& grid, const Eigen::Vector3d& start_m,
                     const Eigen::Vector3d& goal_m) {
  const environment::GridFrame& frame = grid.frame();
  struct Flood {
    std::vector<bool> seen;
    std::deque<std::size_t> queue;
    environment::Index3 lo, hi;
  };
  std::array<Flood, 2> floods;  // from the start, from the goal
  const std::array<const Eigen::Vector3d*, 2> ends{&start_m, &goal_m};
  for (int side = 0; side < 2; ++side) {
    const environment::Index3 cell{frame.indexOf(0, ends[side]->x()), frame.indexOf(1, ends[side]->y()),
                                   frame.indexOf(2, ends[side]->z())};
    if (!frame.inside(cell[0], cell[1], cell[2])) return;
    floods[side].seen.assign(frame.voxelCount(), false);
    floods[side].seen[frame.linear(cell[0], cell[1], cell[2])] = true;
    floods[side].queue.push_back(frame.linear(cell[0], cell[1], cell[2]));
    floods[side].lo = floods[side].hi = cell;
  }
  constexpr int kFaces[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (;;) {
    for (int side = 0; side < 2; ++side) {
      Flood& flood = floods[side];
      if (flood.queue.empty()) {
        const bool goal = side == 1;
        blockage.enclosed_end = goal ? "goal" : "start";
        blockage.enclosed_at_m = *ends[side];
        for (int axis = 0; axis < 3; ++axis) {
          blockage.enclosure_min_m[axis] = frame.faceOf(axis, flood.lo[axis]);
          blockage.enclosure_max_m[axis] = frame.faceOf(axis, flood.hi[axis] + 1);
        }
        return;
      }
      const std::size_t voxel = flood.queue.front();
      flood.queue.pop_front();
      if (floods[1 - side].seen[voxel]) return;  // the floods met: a way exists, however narrow
      const environment::Index3 at = frame.unlinear(voxel);
      for (const auto& face : kFaces) {
        const int i = at[0] + face[0], j = at[1] + face[1], k = at[2] + face[2];
        if (!frame.inside(i, j, k)) continue;
        const std::size_t next = frame.linear(i, j, k);
        if (flood.seen[next] || grid.atLinear(next) == environment::CellState::Occupied) continue;
        flood.seen[next] = true;
        flood.queue.push_back(next);
        for (int axis = 0; axis < 3; ++axis) {
          const int index = axis == 0 ? i : axis == 1 ? j : k;
          flood.lo[axis] = std::min(flood.lo[axis], index);
          flood.hi[axis] = std::max(flood.hi[axis], index);
        }
      }
    }
  }
}

BridgeOutcome findBridge(const SafetyRules& rules, const std::vector<Eigen::Vector3d>& side_a,
                         const std::vector<Eigen::Vector3d>& side_b,
                         const ompl::base::PlannerTerminationCondition& ptc) {
  BridgeOutcome outcome;
  if (side_a.empty() || side_b.empty()) return outcome;
  // Each point of side a with its nearest of side b, closest pairs first. GNAT measures with
  // its distance function, so a point of side a is asked about through one more entry.
  std::vector<Eigen::Vector3d> positions = side_b;
  const std::size_t probe = positions.size();
  positions.push_back(Eigen::Vector3d::Zero());
  ompl::NearestNeighborsGNAT<std::size_t> nearest;
  nearest.setDistanceFunction(
      [&positions](const std::size_t& i, const std::size_t& j) { return (positions[i] - positions[j]).norm(); });
  std::vector<std::size_t> indices(side_b.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  nearest.add(indices);
  struct Pair {
    double distance_m;
    std::size_t a, b;
    double openness = 0.0;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < side_a.size(); ++i) {
    positions[probe] = side_a[i];
    const std::size_t j = nearest.nearest(probe);
    pairs.push_back({(side_a[i] - side_b[j]).norm(), i, j});
  }
  // The pairs whose way is most open first (counting unknown space open, so a gap the policy
  // closes is still tried and named), the closest first among equals: the straight ways of all,
  // then the ways near them of the best few, well apart.
  for (Pair& pair : pairs)
    pair.openness = constriction(rules.environment(), side_a[pair.a], side_b[pair.b], true).ratio;
  const auto moreOpen = [](const Pair& x, const Pair& y) {
    return x.openness != y.openness ? x.openness > y.openness : x.distance_m < y.distance_m;
  };
  std::stable_sort(pairs.begin(), pairs.end(), moreOpen);
  std::vector<Pair> candidates;
  for (const Pair& pair : pairs) {
    if (static_cast<int>(candidates.size()) == kCandidates) break;
    const Eigen::Vector3d middle = 0.5 * (side_a[pair.a] + side_b[pair.b]);
    if (std::none_of(candidates.begin(), candidates.end(), [&](const Pair& c) {
          return (0.5 * (side_a[c.a] + side_b[c.b]) - middle).norm() < kPairSeparationM;
        }))
      candidates.push_back(pair);
  }
  for (Pair& pair : candidates)
    pair.openness = bottleneck(rules.environment(), side_a[pair.a], side_b[pair.b], true, kReachM).ratio;
  std::stable_sort(candidates.begin(), candidates.end(), moreOpen);

  const double vehicle_width_m = 2.0 * rules.environment().vehicle().inflatedRadius_m();
  const environment::GridFrame& frame = rules.environment().grid().frame();
  const auto join = [&outcome](std::vector<Eigen::Vector3d> path, const Pair& pair) {
    outcome.waypoints = std::move(path);
    outcome.from = pair.a;
    outcome.to = pair.b;
    outcome.blockage.reset();
  };
  for (std::size_t k = 0; k < candidates.size() && static_cast<int>(k) < kAttempts && !ptc(); ++k) {
    const Pair& pair = candidates[k];
    const Eigen::Vector3d& a = side_a[pair.a];
    const Eigen::Vector3d& b = side_b[pair.b];
    const double radius_m = std::max(kReachM, vehicle_width_m);
    std::vector<Eigen::Vector3d> path =
        fineSearch(rules, FineLattice(frame, boxAround(a, b, radius_m)), a, b, radius_m, ptc);
    if (!path.empty()) {
      join(std::move(path), pair);
      return outcome;
    }
    // The most open way tried names the gap.
    if (!outcome.blockage) outcome.blockage = diagnoseBlockage(rules, a, b);
  }
  // Last, a fine search from the closest pair, ever wider: a passage far from every straight
  // way tried (a shaft the vehicle barely fits, a way round through the next room) is found
  // wherever the vehicle fits, as long as the box holds at most kMaxWideNodes fine nodes.
  const Pair& closest = *std::min_element(pairs.begin(), pairs.end(),
                                          [](const Pair& x, const Pair& y) { return x.distance_m < y.distance_m; });
  for (double radius_m = 2.0 * kReachM; !ptc(); radius_m *= 2.0) {
    const Eigen::Vector3d &a = side_a[closest.a], &b = side_b[closest.b];
    const FineLattice lattice(frame, boxAround(a, b, radius_m), 1, kMaxWideNodes);
    if (lattice.spacing_m() > 0.5 * frame.resolution_m() * (1.0 + 1e-9)) break;  // too large a box to search finely
    std::vector<Eigen::Vector3d> path = fineSearch(rules, lattice, a, b, radius_m, ptc);
    if (!path.empty()) {
      join(std::move(path), closest);
      return outcome;
    }
    if (lattice.coversBounds()) break;
  }
  if (ptc()) outcome.blockage.reset();
  return outcome;
}

}  // namespace detail
}  // namespace ceilplan::planner
