#include "ceilplan/mission/viewpoint.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/environment/vertical_ceiling_test.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace ceilplan::mission {

namespace {

constexpr double kCurrentResolutionA = 1e-3;
constexpr double kStandoffResolutionM = 1e-3;
constexpr double kCoarseStepM = 0.1;  // the first lattice over the standoff shell, at most

// Whether the segment from the body to the target point crosses only free voxels (stopping
// half a voxel short of the point, which lies on an occupied voxel's face).
bool seesPoint(const environment::VoxelGrid& grid, const Eigen::Vector3d& body_m, const Eigen::Vector3d& point_m) {
  const environment::GridFrame& frame = grid.frame();
  const double step_m = 0.25 * frame.resolution_m();
  const Eigen::Vector3d toward_point = point_m - body_m;
  const double length_m = toward_point.norm() - 0.5 * frame.resolution_m();
  for (double s = 0.0; s <= length_m; s += step_m) {
    const Eigen::Vector3d p = body_m + toward_point.normalized() * s;
    if (grid.at(frame.indexOf(0, p.x()), frame.indexOf(1, p.y()), frame.indexOf(2, p.z())) !=
        environment::CellState::Free)
      return false;
  }
  return true;
}

// The hover current under `gaps` (hoverCurrentA's, from gaps already looked up).
double hoverCurrentUnder(const energy::EnergyModel& model, const environment::Environment::CeilingAndGround& gaps,
                         double soc) {
  if (static_cast<int>(gaps.ceiling.rotors.size()) != model.rotorCount() ||
      model.rotorCount() > energy::EnergyModel::kMaxRotors)
    throw ceilplan::InputError("the map's vehicle has " + std::to_string(gaps.ceiling.rotors.size()) +
                               " rotors, the energy model " + std::to_string(model.rotorCount()) +
                               ": use one vehicle file for both");
  const planner::PointConditions conditions = planner::surfaceConditions(gaps.ceiling, gaps.ground);
  energy::FlightCondition hover;
  hover.ground_gap_m = conditions.ground_gap_m;
  hover.soc = soc;
  return model.currentA(conditions.rotors.data(), model.rotorCount(), hover);
}

class ViewpointSearch {
 public:
  ViewpointSearch(const InspectionTarget& target, const environment::Environment& environment,
                  const energy::EnergyModel& model, const ViewpointOptions& options)
      : target_(target), environment_(environment), model_(model), options_(options) {}

  // Every lattice point at `step_m` spacing within `reach_m` of `centre_m`. With `hug`, the top
  // admissible point of each lattice column is also tried as high as it stays admissible.
  // Each point's key is found column by column (in ceiling mode a column's points look their
  // gaps up together: Environment::ceilingAndGroundAlong searches each column under the discs
  // once for all of them), then the points are considered in the lattice's order (z, then y,
  // then x), which decides between equals.
  // By value: the refining pass scans around best(), which the scan itself moves.
  // NOLINTNEXTLINE(performance-unnecessary-value-param)
  void scan(const Eigen::Vector3d centre_m, double step_m, double reach_m, bool hug) {
    const int n = static_cast<int>(std::ceil(reach_m / step_m));
    const int side = 2 * n + 1;
    const auto bodyAt = [&](int i, int j, int k) {
      return ontoShell(centre_m + step_m * Eigen::Vector3d(i, j, k), step_m);
    };
    const auto place = [&](int i, int j, int k) {
      return (static_cast<std::size_t>(k + n) * side + (j + n)) * side + (i + n);
    };
    keys_.assign(static_cast<std::size_t>(side) * side * side, kInadmissible);
    std::vector<Eigen::Vector3d> bodies_m;
    std::vector<std::size_t> places;
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        bodies_m.clear(), places.clear();
        for (int k = -n; k <= n; ++k) {
          const Eigen::Vector3d body_m = bodyAt(i, j, k);
          if (!validInRange(body_m)) continue;
          bodies_m.push_back(body_m);
          places.push_back(place(i, j, k));
        }
        if (options_.mode != FlightMode::Ceiling) {
          for (std::size_t p = 0; p < bodies_m.size(); ++p)
            if (environment_.ceilingGapAtLeast(bodies_m[p], options_.min_ceiling_gap_m))
              keys_[places[p]] = key(bodies_m[p]);
          continue;
        }
        // Ceiling mode reads the gaps above and below once for both (the nearest gap above is
        // the ceiling's, to the bit), and prices the point from them.
        environment_.ceilingAndGroundAlong(
            bodies_m, [&](std::size_t p, const environment::Environment::CeilingAndGround& gaps) {
              if (gaps.ceiling.nearest_gap_m >= options_.min_ceiling_gap_m)
                keys_[places[p]] = currentKey(hoverCurrentUnder(model_, gaps, options_.soc));
            });
      }
    for (int k = -n; k <= n; ++k)
      for (int j = -n; j <= n; ++j)
        for (int i = -n; i <= n; ++i) {
          const double point_key = keys_[place(i, j, k)];
          if (point_key == kInadmissible) continue;
          const Eigen::Vector3d body_m = bodyAt(i, j, k);
          consider(body_m, point_key);
          const Eigen::Vector3d step_up_m(0, 0, step_m);
          if (hug && !admissible(body_m + step_up_m)) {
            const Eigen::Vector3d top_m = raised(body_m, step_m);
            consider(top_m, this->key(top_m));
          }
        }
  }

  bool found() const { return any_.found(); }
  // The best reachable position, or the best of all where none is reachable.
  const Eigen::Vector3d& best() const { return reachable_.found() ? reachable_.position_m : any_.position_m; }
  bool bestReachable() const { return reachable_.found() || !options_.reachable; }

 private:
  // A lattice point within a step outside the standoff shell, moved radially onto it, so that
  // a shell thinner than the lattice spacing is still met.
  Eigen::Vector3d ontoShell(const Eigen::Vector3d& body_m, double step_m) const {
    const Eigen::Vector3d offset_m = body_m - target_.point_m;
    const double distance_m = offset_m.norm();
    if (distance_m == 0.0 || distance_m < target_.standoff_min_m - step_m ||
        distance_m > target_.standoff_max_m + step_m)
      return body_m;
    const double onto_m = std::clamp(distance_m, target_.standoff_min_m, target_.standoff_max_m);
    return target_.point_m + offset_m * (onto_m / distance_m);
  }

  // In the standoff range and a valid state.
  bool validInRange(const Eigen::Vector3d& body_m) const {
    const double distance_m = (body_m - target_.point_m).norm();
    return distance_m >= target_.standoff_min_m && distance_m <= target_.standoff_max_m &&
           environment_.contains(body_m) && environment_.isStateValid(body_m);
  }

  // validInRange, and clear of the ceiling by the minimum gap.
  bool admissible(const Eigen::Vector3d& body_m) const {
    return validInRange(body_m) && environment_.ceilingGapAtLeast(body_m, options_.min_ceiling_gap_m);
  }

  // Ceiling mode: the current keeps falling as the gap above closes, and a lattice leaves the
  // highest admissible position up to a step below; bisect upwards for it (admissibility is
  // taken as lost once, upwards, within the span).
  Eigen::Vector3d raised(const Eigen::Vector3d& body_m, double span_m) const {
    // admissible() at each height, its ceiling test from the columns under the discs found once
    // for the whole vertical line.
    const environment::VerticalCeilingTest ceiling(environment_, body_m);
    double low_m = 0.0, high_m = span_m;
    for (int step = 0; step < 24; ++step) {
      const double middle_m = 0.5 * (low_m + high_m);
      const Eigen::Vector3d at_m = body_m + Eigen::Vector3d(0, 0, middle_m);
      (validInRange(at_m) && ceiling.gapAtLeast(at_m, options_.min_ceiling_gap_m) ? low_m : high_m) = middle_m;
    }
    return body_m + Eigen::Vector3d(0, 0, low_m);
  }

  // What the mode minimises at a position. Ceiling mode: the hover current, to the
  // milliampere, so that a difference no meter would show does not pull the viewpoint away from
  // the target. Free mode ignores proximity effects (every position draws the same) and keeps
  // the conventional standoff where it fits, the largest that fits where it does not: the
  // shortfall, to the millimetre.
  double key(const Eigen::Vector3d& body_m) const {
    if (options_.mode == FlightMode::Ceiling)
      return currentKey(hoverCurrentA(environment_, model_, body_m, options_.soc));
    const double shortfall_m = std::max(0.0, options_.standoff_m - planner::standoffAt(environment_, body_m));
    return std::round(shortfall_m / kStandoffResolutionM);
  }
  static double currentKey(double current_a) { return std::round(current_a / kCurrentResolutionA); }

  // The best position so far by key, ties by distance to the point.
  struct Best {
    double key = std::numeric_limits<double>::infinity();
    double distance_m = std::numeric_limits<double>::infinity();
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
    bool found() const { return key < std::numeric_limits<double>::infinity(); }
    bool beatenBy(double other_key, double other_distance_m) const {
      return other_key < key || (other_key == key && other_distance_m < distance_m);
    }
  };

  // Keeps an admissible position (its key given) that sees the target if it beats the best so
  // far, and the best reachable one apart (the reachability test, the costliest, last).
  void consider(const Eigen::Vector3d& body_m, double key) {
    const double distance_m = (body_m - target_.point_m).norm();
    const bool better = any_.beatenBy(key, distance_m);
    const bool better_reachable = options_.reachable && reachable_.beatenBy(key, distance_m);
    if (!(better || better_reachable) || !seesPoint(environment_.grid(), body_m, target_.point_m)) return;
    if (better) any_ = Best{key, distance_m, body_m};
    if (better_reachable && options_.reachable(body_m)) reachable_ = Best{key, distance_m, body_m};
  }

  const InspectionTarget& target_;
  const environment::Environment& environment_;
  const energy::EnergyModel& model_;
  const ViewpointOptions& options_;
  Best any_, reachable_;
  // Each lattice point's key in the scan under way (kInadmissible where it is not admissible),
  // kept between scans for its storage.
  static constexpr double kInadmissible = -1.0;  // keys are never negative
  std::vector<double> keys_;
};

}  // namespace

void InspectionTarget::validate() const {
  const std::string what = "target '" + name + "'";
  if (name.empty()) throw ceilplan::InputError("a target needs a name");
  if (!point_m.allFinite()) throw ceilplan::InputError(what + ": point must be finite, got " + formatPoint(point_m));
  if (!(std::isfinite(standoff_min_m) && std::isfinite(standoff_max_m) && standoff_min_m >= 0.0 &&
        standoff_max_m > 0.0 && standoff_min_m <= standoff_max_m && standoff_max_m <= kMaxStandoff_m))
    throw ceilplan::InputError(what +
                               ": standoff range must be 0 <= min <= max, 0 < max <= " + formatNumber(kMaxStandoff_m) +
                               ", got [" + formatNumber(standoff_min_m) + ", " + formatNumber(standoff_max_m) + "] m");
  if (!std::isfinite(dwell_s) || dwell_s < 0.0)
    throw ceilplan::InputError(what + ": dwell time must be finite and non-negative, got " + formatNumber(dwell_s) +
                               " s");
}

void requireOnStructure(const InspectionTarget& target, const environment::Environment& environment) {
  if (!environment.contains(target.point_m)) return;
  const environment::VoxelGrid& grid = environment.grid();
  const environment::GridFrame& frame = grid.frame();
  const double reach_m = target.standoff_max_m;
  int low[3], high[3];
  for (int axis = 0; axis < 3; ++axis) {
    low[axis] = std::max(0, frame.indexOf(axis, target.point_m[axis] - reach_m));
    high[axis] = std::min(frame.size()[axis] - 1, frame.indexOf(axis, target.point_m[axis] + reach_m));
  }
  for (int k = low[2]; k <= high[2]; ++k)
    for (int j = low[1]; j <= high[1]; ++j)
      for (int i = low[0]; i <= high[0]; ++i) {
        if (grid.at(i, j, k) != environment::CellState::Occupied) continue;
        // Distance from the point to the voxel's box.
        const Eigen::Vector3d lower(frame.faceOf(0, i), frame.faceOf(1, j), frame.faceOf(2, k));
        const Eigen::Vector3d upper = lower + Eigen::Vector3d::Constant(frame.resolution_m());
        if ((target.point_m.cwiseMax(lower).cwiseMin(upper) - target.point_m).norm() <= reach_m) return;
      }
  throw ceilplan::InputError("target '" + target.name + "' at " + formatPoint(target.point_m) +
                             " lies in free air: no structure within its standoff range of " + formatNumber(reach_m) +
                             " m; put the point on the surface it inspects");
}

std::optional<Eigen::Vector3d> surfacePoint(const InspectionTarget& target,
                                            const environment::Environment& environment) {
  const Eigen::Vector3d& p = target.point_m;
  if (!environment.contains(p)) return p;
  const environment::VoxelGrid& grid = environment.grid();
  const environment::GridFrame& frame = grid.frame();
  const int i0 = frame.indexOf(0, p.x()), j0 = frame.indexOf(1, p.y()), k0 = frame.indexOf(2, p.z());
  if (grid.at(i0, j0, k0) != environment::CellState::Occupied) return p;
  const double resolution_m = frame.resolution_m();
  std::optional<Eigen::Vector3d> best;
  double best_m = target.standoff_max_m;
  // The nearest point of each face an occupied voxel shares with a free one, shell by shell (in
  // whole voxels) outwards, until no voxel of the next shell can hold a nearer face.
  for (int n = 0; (n - 1) * resolution_m <= best_m; ++n)
    for (int k = k0 - n; k <= k0 + n; ++k)
      for (int j = j0 - n; j <= j0 + n; ++j)
        for (int i = i0 - n; i <= i0 + n; ++i) {
          if (std::max({std::abs(i - i0), std::abs(j - j0), std::abs(k - k0)}) != n) continue;
          if (grid.at(i, j, k) != environment::CellState::Occupied) continue;
          const int voxel[3] = {i, j, k};
          for (int axis = 0; axis < 3; ++axis)
            for (int side : {-1, 1}) {
              int neighbour[3] = {i, j, k};
              neighbour[axis] += side;
              if (grid.at(neighbour[0], neighbour[1], neighbour[2]) != environment::CellState::Free) continue;
              Eigen::Vector3d on_face;
              for (int other = 0; other < 3; ++other)
                on_face[other] =
                    std::clamp(p[other], frame.faceOf(other, voxel[other]), frame.faceOf(other, voxel[other] + 1));
              on_face[axis] = frame.faceOf(axis, side > 0 ? voxel[axis] + 1 : voxel[axis]);
              const double distance_m = (on_face - p).norm();
              if (distance_m <= best_m) std::tie(best, best_m) = std::make_tuple(on_face, distance_m);
            }
        }
  return best;
}

double hoverCurrentA(const environment::Environment& environment, const energy::EnergyModel& model,
                     const Eigen::Vector3d& body_m, double soc) {
  return hoverCurrentUnder(model, environment.ceilingAndGround(body_m), soc);
}

Viewpoint chooseViewpoint(const InspectionTarget& target, const environment::Environment& environment,
                          const energy::EnergyModel& model, const ViewpointOptions& options) {
  target.validate();
  if (!(std::isfinite(options.standoff_m) && options.standoff_m >= 0.0))
    throw ceilplan::InputError("the conventional standoff must be a finite number >= 0 m, got " +
                               formatNumber(options.standoff_m));
  if (!environment.contains(target.point_m))
    throw ceilplan::InputError("target '" + target.name + "' at " + formatPoint(target.point_m) +
                               " lies outside the map");
  ViewpointSearch search(target, environment, model, options);
  const double resolution_m = environment.grid().frame().resolution_m();
  const bool hug = options.mode == FlightMode::Ceiling;
  // The shell in metres, as the lattice planners are: at most kCoarseStepM apart (a whole number
  // of voxels), so a fine scan does not cost (1 / resolution)^3 lattice points per target.
  double step_m = resolution_m * std::max(1.0, std::floor(kCoarseStepM / resolution_m + 1e-9));
  search.scan(target.point_m, step_m, target.standoff_max_m, hug);
  if (!search.found())
    throw ceilplan::InputError("target '" + target.name + "' at " + formatPoint(target.point_m) +
                               ": no valid viewpoint within " + formatNumber(target.standoff_min_m) + "-" +
                               formatNumber(target.standoff_max_m) +
                               " m that sees it; check the point lies on a surface facing free space, or widen its "
                               "standoff range");
  // Then finer around the best, a quarter of the step at a time, down to a quarter voxel.
  while (step_m > 0.25 * resolution_m * (1.0 + 1e-9)) {
    const double reach_m = step_m;
    step_m = std::max(0.25 * step_m, 0.25 * resolution_m);
    search.scan(search.best(), step_m, reach_m, hug);
  }

  Viewpoint viewpoint;
  viewpoint.position_m = search.best();
  viewpoint.reachable = search.bestReachable();
  viewpoint.distance_m = (viewpoint.position_m - target.point_m).norm();
  viewpoint.ceiling_gap_m = environment.nearestCeilingGap_m(viewpoint.position_m);
  viewpoint.standoff_m = planner::standoffAt(environment, viewpoint.position_m);
  viewpoint.dwell_current_a = hoverCurrentA(environment, model, viewpoint.position_m, options.soc);
  viewpoint.dwell_charge_ah = viewpoint.dwell_current_a * target.dwell_s / 3600.0;
  return viewpoint;
}

}  // namespace ceilplan::mission
