#include "ceilplan/environment/environment.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/environment/disc_area.hpp"
#include "disc_columns.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace ceilplan::environment {
namespace {

using detail::forEachDiscColumn;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr double kDenseStepVoxels = 0.1;  // checkPathDensely's step: finer than any planner's
constexpr double kReachMargin_m = 1e-6;   // validReach_m stays this far short of a blocked voxel or the box

constexpr int kKeptGaps = 256;  // columns under a rotor disc: 9 for a 10" rotor at 0.1 m, 196 at 0.02 m
// ceilingAndGroundAlong keeps a free span for each column in its points' box when there are at
// most this many per point and this many more (a lattice edge's 9 samples at 0.1 m: about 150
// columns); a long diagonal motion's box is mostly columns none of its discs reach.
constexpr long kSpansPerPoint = 32;
constexpr long kSpansBeyondPoints = 256;
// Beyond those columns, a batch is asked in runs of this many consecutive points (1.6 m of a
// motion sampled every 0.05 m), each run's columns looked up once for it, before falling back to
// a search of every column under every disc at every point.
constexpr std::size_t kRunPoints = 32;

void validateOptions(const EnvironmentOptions& options) {
  if (!(options.ceiling_reach_radii > 0.0) || !std::isfinite(options.ceiling_reach_radii))
    throw ceilplan::InputError("environment options: ceiling reach must be a positive number of rotor radii");
  if (!(options.ground_reach_radii > 0.0) || !std::isfinite(options.ground_reach_radii))
    throw ceilplan::InputError("environment options: ground reach must be a positive number of rotor radii");
  if (!(options.motion_step_voxels > 0.0) || options.motion_step_voxels > 1.0)
    throw ceilplan::InputError("environment options: motion step must lie in (0, 1] voxels");
  if (options.workers < 1) throw ceilplan::InputError("environment options: workers must be at least 1");
}

VehicleGeometry validated(VehicleGeometry vehicle) {
  vehicle.validate();
  return vehicle;
}

std::shared_ptr<const MapIndex> requireIndex(std::shared_ptr<const MapIndex> index) {
  if (!index) throw ceilplan::Error("environment: no map index given");
  return index;
}

}  // namespace

std::string Violation::describe() const {
  std::string where = "segment " + std::to_string(segment) + " at " + formatPoint(position_m, 3) + ": ";
  switch (kind) {
    case ViolationKind::OutsideMap:
      return where + "the body centre lies outside the map";
    case ViolationKind::Occupied:
      return where + "the vehicle (with its clearance margins) touches occupied space";
    case ViolationKind::Unknown:
      return where +
             "the vehicle (with its clearance margins) touches unknown space, which the unknown-space policy keeps as "
             "an obstacle";
  }
  return where;
}

Environment::Environment(std::shared_ptr<const MapIndex> index, VehicleGeometry vehicle, EnvironmentOptions options,
                         const std::function<void(double)>& progress)
    : index_(requireIndex(std::move(index))),
      columns_(&index_->columns()),
      distance_(&index_->distance()),
      vehicle_(validated(std::move(vehicle))),
      options_((validateOptions(options), options)),
      footprint_(index_->distance(), vehicle_.inflatedRadius_m(), options_.workers) {
  const double vertical = std::max(std::abs(vehicle_.inflatedBottom_m()), std::abs(vehicle_.inflatedTop_m()));
  bounding_sphere_m_ = std::hypot(vehicle_.inflatedRadius_m(), vertical);
  if (progress) progress(1.0);
}

Environment::Environment(const OccupancyMap& map, VehicleGeometry vehicle, EnvironmentOptions options,
                         const std::function<void(double)>& progress)
    : Environment(map, std::move(vehicle), options, MapIndexOptions{UnknownSpace{}, options.workers}, progress) {}

// By value like the other constructors; not moved on, because validated() reads it in the same call
// and the order in which the delegated call's arguments are built is unspecified.
// NOLINTNEXTLINE(performance-unnecessary-value-param)
Environment::Environment(const OccupancyMap& map, VehicleGeometry vehicle, EnvironmentOptions options,
                         const MapIndexOptions& index_options, const std::function<void(double)>& progress)
    : Environment((validated(vehicle), validateOptions(options),  // before the work starts
                   MapIndex::build(map, index_options,
                                   [&](double f) {
                                     if (progress) progress(0.95 * f);
                                   })),
                  vehicle, options, progress) {}

void Environment::requireInside(const Eigen::Vector3d& point_m, const char* query) const {
  if (!point_m.allFinite())
    throw ceilplan::InputError(std::string(query) + ": the point " + formatPoint(point_m, 3) + " is not finite");
  if (contains(point_m)) return;
  const Eigen::AlignedBox3d box = grid().frame().bounds();
  throw ceilplan::InputError(mapName() + ": " + query + " at " + formatPoint(point_m, 3) +
                             ": the point lies outside the map, whose known voxels span " + formatPoint(box.min(), 3) +
                             " to " + formatPoint(box.max(), 3));
}

template <class Visit>
bool Environment::anyColumnUnderCylinder(const Eigen::Vector3d& body_m, Visit&& visit) const {
  const GridFrame& frame = grid().frame();
  const double radius = vehicle_.inflatedRadius_m();
  const int j_end = frame.indexOf(1, body_m.y() + radius), i_end = frame.indexOf(0, body_m.x() + radius);
  for (int j = frame.indexOf(1, body_m.y() - radius); j <= j_end; ++j) {
    const double dy = std::max({frame.faceOf(1, j) - body_m.y(), 0.0, body_m.y() - frame.faceOf(1, j + 1)});
    for (int i = frame.indexOf(0, body_m.x() - radius); i <= i_end; ++i) {
      const double dx = std::max({frame.faceOf(0, i) - body_m.x(), 0.0, body_m.x() - frame.faceOf(0, i + 1)});
      if (dx * dx + dy * dy >= radius * radius) continue;  // touching the column's side is allowed
      if (visit(i, j)) return true;
    }
  }
  return false;
}

bool Environment::isSurface(const ColumnIndex::Boundary& boundary) const {
  return detail::isSurface(boundary, options_.unknown_is_surface);
}

double Environment::surfaceGap(const ColumnIndex::Boundary& boundary, double z_m) const {
  return isSurface(boundary) ? std::abs(boundary.face_m - z_m) : kInfinity;
}

double Environment::columnGap(int i, int j, double z_m, Direction direction) const {
  return surfaceGap(direction == Direction::Up ? columns_->above(i, j, z_m) : columns_->below(i, j, z_m), z_m);
}

double Environment::ceilingGapAt(const Eigen::Vector3d& point_m) const {
  requireInside(point_m, "ceiling gap");
  const GridFrame& frame = grid().frame();
  return columnGap(frame.indexOf(0, point_m.x()), frame.indexOf(1, point_m.y()), point_m.z(), Direction::Up);
}

double Environment::groundGapAt(const Eigen::Vector3d& point_m) const {
  requireInside(point_m, "ground gap");
  const GridFrame& frame = grid().frame();
  return columnGap(frame.indexOf(0, point_m.x()), frame.indexOf(1, point_m.y()), point_m.z(), Direction::Down);
}

SurfaceGaps Environment::ceiling(const Eigen::Vector3d& body_m) const {
  requireInside(body_m, "ceiling gap");
  SurfaceGaps up;
  gaps(body_m, &up, nullptr);
  return up;
}

bool Environment::ceilingGapAtLeast(const Eigen::Vector3d& body_m, double gap_m) const {
  requireInside(body_m, "ceiling gap");
  const double plane_z = body_m.z() + vehicle_.rotor_plane_height_m;
  for (const Eigen::Vector2d& offset : vehicle_.rotor_positions_m)
    if (!forEachDiscColumn(grid().frame(), body_m.head<2>() + offset, vehicle_.rotor_radius_m,
                           [&](int i, int j, int) { return columnGap(i, j, plane_z, Direction::Up) >= gap_m; }))
      return false;
  return true;
}

double Environment::nearestCeilingGap_m(const Eigen::Vector3d& body_m) const {
  requireInside(body_m, "ceiling gap");
  const double plane_z = body_m.z() + vehicle_.rotor_plane_height_m;
  double nearest_m = kInfinity;
  for (const Eigen::Vector2d& offset : vehicle_.rotor_positions_m)
    forEachDiscColumn(grid().frame(), body_m.head<2>() + offset, vehicle_.rotor_radius_m, [&](int i, int j, int) {
      nearest_m = std::min(nearest_m, columnGap(i, j, plane_z, Direction::Up));
      return true;
    });
  return nearest_m;
}

SurfaceGaps Environment::ground(const Eigen::Vector3d& body_m) const {
  requireInside(body_m, "ground gap");
  SurfaceGaps down;
  gaps(body_m, nullptr, &down);
  return down;
}

Environment::CeilingAndGround Environment::ceilingAndGround(const Eigen::Vector3d& body_m) const {
  requireInside(body_m, "ceiling gap");
  CeilingAndGround both;
  gaps(body_m, &both.ceiling, &both.ground);
  return both;
}

void Environment::ceilingAndGroundAlong(const std::vector<Eigen::Vector3d>& bodies_m,
                                        const std::function<void(std::size_t, const CeilingAndGround&)>& visit) const {
  for (const Eigen::Vector3d& body_m : bodies_m) requireInside(body_m, "ceiling gap");
  CeilingAndGround both;
  // The points [begin, end): the whole batch, or one run of it.
  const auto answer = [&](const auto& self, std::size_t begin, std::size_t end) -> void {
    if (begin == end) return;
    const Eigen::Vector3d* const run_m = bodies_m.data() + begin;
    const std::size_t count = end - begin;
    // The columns a disc at any of the points can reach (a voxel of margin against rounding): one
    // free span each, unless the points spread too far apart for that to pay.
    const GridFrame& frame = grid().frame();
    Eigen::Vector2d reach_m = Eigen::Vector2d::Zero();
    for (const Eigen::Vector2d& offset : vehicle_.rotor_positions_m) reach_m = reach_m.cwiseMax(offset.cwiseAbs());
    reach_m.array() += vehicle_.rotor_radius_m + frame.resolution_m();
    Eigen::Vector2d low_m = run_m[0].head<2>(), high_m = low_m;
    for (std::size_t k = 0; k < count; ++k)
      low_m = low_m.cwiseMin(run_m[k].head<2>()), high_m = high_m.cwiseMax(run_m[k].head<2>());
    const int i0 = frame.indexOf(0, low_m.x() - reach_m.x()), i1 = frame.indexOf(0, high_m.x() + reach_m.x());
    const int j0 = frame.indexOf(1, low_m.y() - reach_m.y()), j1 = frame.indexOf(1, high_m.y() + reach_m.y());
    const long width = i1 - i0 + 1, columns = width * (j1 - j0 + 1);
    if (columns > kSpansPerPoint * static_cast<long>(count) + kSpansBeyondPoints) {
      if (count > kRunPoints) {
        // A long motion: runs of consecutive samples, each with the spans of its own columns.
        for (std::size_t run = begin; run < end; run += kRunPoints) self(self, run, std::min(end, run + kRunPoints));
        return;
      }
      for (std::size_t k = 0; k < count; ++k) {
        gaps(run_m[k], &both.ceiling, &both.ground);
        visit(begin + k, both);
      }
      return;
    }
    // A column's free span and what surfaceGap makes of around()'s boundaries inside it.
    struct Span {
      double lo = 1.0, hi = 0.0;  // empty until looked up, and where the height lies in no span
      double above_face_m = 0.0, below_face_m = 0.0;
      bool above_surface = false, below_surface = false, looked_up = false;
      bool operator==(const Span& o) const {
        return lo == o.lo && hi == o.hi && above_face_m == o.above_face_m && below_face_m == o.below_face_m &&
               above_surface == o.above_surface && below_surface == o.below_surface;
      }
      bool holds(double t) const { return lo < t && t < hi; }
      std::array<double, 2> gaps(double z_m) const {
        return {above_surface ? std::abs(above_face_m - z_m) : kInfinity,
                below_surface ? std::abs(below_face_m - z_m) : kInfinity};
      }
    };
    std::vector<Span> spans(columns);
    // Column (i, j), inside the box; looked up at height z_m the first time.
    const auto spanOf = [&](int i, int j, double z_m) -> const Span& {
      Span& span = spans[(j - j0) * width + (i - i0)];
      if (!span.looked_up) {
        span.looked_up = true;
        if (const std::optional<ColumnIndex::FreeSpan> free = columns_->freeSpan(i, j, z_m)) {
          span.lo = free->lo, span.hi = free->hi;
          span.above_face_m = free->around.above.face_m, span.below_face_m = free->around.below.face_m;
          span.above_surface = isSurface(free->around.above), span.below_surface = isSurface(free->around.below);
        }
      }
      return span;
    };
    const auto column_gaps = [&](int i, int j, double z_m) -> std::array<double, 2> {
      if (i >= i0 && i <= i1 && j >= j0 && j <= j1) {  // always, but exact either way
        const Span& span = spanOf(i, j, z_m);
        if (span.holds(columns_->voxelHeight(z_m))) return span.gaps(z_m);
      }
      return searchedColumnGaps(i, j, z_m);
    };
    // A rotor whose disc, at every point, covers columns of one span (every column in the
    // rectangle the discs sweep): at a height inside it each column gives the same gaps, so
    // gaps() needs none of them.
    const double radius = vehicle_.rotor_radius_m, plane_height = vehicle_.rotor_plane_height_m;
    std::vector<const Span*> uniform(vehicle_.rotor_positions_m.size(), nullptr);
    for (std::size_t r = 0; r < uniform.size(); ++r) {
      int ri0 = i1, ri1 = i0, rj0 = j1, rj1 = j0;
      for (std::size_t k = 0; k < count; ++k) {  // as forEachDiscColumn bounds each disc
        const Eigen::Vector2d centre = run_m[k].head<2>() + vehicle_.rotor_positions_m[r];
        ri0 = std::min(ri0, frame.indexOf(0, centre.x() - radius)),
        ri1 = std::max(ri1, frame.indexOf(0, centre.x() + radius));
        rj0 = std::min(rj0, frame.indexOf(1, centre.y() - radius)),
        rj1 = std::max(rj1, frame.indexOf(1, centre.y() + radius));
      }
      if (ri0 < i0 || ri1 > i1 || rj0 < j0 || rj1 > j1) continue;  // never, but exact either way
      const double z_m = run_m[0].z() + plane_height;
      const Span& first = spanOf(ri0, rj0, z_m);
      bool same = first.lo < first.hi;
      for (int j = rj0; j <= rj1 && same; ++j)
        for (int i = ri0; i <= ri1 && same; ++i) same = spanOf(i, j, z_m) == first;
      if (same) uniform[r] = &first;
    }
    const auto uniform_gaps = [&](std::size_t r, double z_m) -> std::optional<std::array<double, 2>> {
      if (!uniform[r] || !uniform[r]->holds(columns_->voxelHeight(z_m))) return std::nullopt;
      return uniform[r]->gaps(z_m);
    };
    for (std::size_t k = 0; k < count; ++k) {
      gaps(run_m[k], &both.ceiling, &both.ground, column_gaps, uniform_gaps);
      visit(begin + k, both);
    }
  };
  answer(answer, 0, bodies_m.size());
}

std::array<double, 2> Environment::searchedColumnGaps(int i, int j, double z_m) const {
  const ColumnIndex::Boundaries boundaries = columns_->around(i, j, z_m);
  return {surfaceGap(boundaries.above, z_m), surfaceGap(boundaries.below, z_m)};
}

void Environment::gaps(const Eigen::Vector3d& body_m, SurfaceGaps* up, SurfaceGaps* down) const {
  gaps(
      body_m, up, down, [this](int i, int j, double z_m) { return searchedColumnGaps(i, j, z_m); },
      [](std::size_t, double) { return std::optional<std::array<double, 2>>(); });
}

template <class ColumnGaps, class UniformGaps>
void Environment::gaps(const Eigen::Vector3d& body_m, SurfaceGaps* up, SurfaceGaps* down, ColumnGaps&& column_gaps,
                       UniformGaps&& uniform_gaps) const {
  const GridFrame& frame = grid().frame();
  const double radius = vehicle_.rotor_radius_m;
  const double disc_area = M_PI * radius * radius;
  const double plane_z = body_m.z() + vehicle_.rotor_plane_height_m;
  // What one direction gathers: over the rotors, and over the columns under one rotor's disc.
  struct Side {
    SurfaceGaps* result = nullptr;
    double reach = 0.0;
    double all_covered = 0.0, all_weighted = 0.0;
    std::array<double, kKeptGaps> kept;  // written before it is read: not cleared on every query
    double lowest = kInfinity, highest = -kInfinity;
  };
  std::array<Side, 2> sides;
  sides[0].result = up, sides[0].reach = radius * options_.ceiling_reach_radii;
  sides[1].result = down, sides[1].reach = radius * options_.ground_reach_radii;
  for (Side& side : sides)
    if (side.result) {
      // Cleared in place: a batch's results keep their rotors' storage from point to point.
      side.result->rotors.clear();
      side.result->rotors.reserve(vehicle_.rotor_positions_m.size());
      side.result->nearest_gap_m = kInfinity, side.result->coverage = 0.0, side.result->mean_gap_m = kInfinity;
    }
  const auto columnGaps = [&](int i, int j) -> std::array<double, 2> {
    if (up && down) return column_gaps(i, j, plane_z);
    return up ? std::array<double, 2>{columnGap(i, j, plane_z, Direction::Up), kInfinity}
              : std::array<double, 2>{kInfinity, columnGap(i, j, plane_z, Direction::Down)};
  };
  for (std::size_t r = 0; r < vehicle_.rotor_positions_m.size(); ++r) {
    const Eigen::Vector2d centre = body_m.head<2>() + vehicle_.rotor_positions_m[r];
    const auto forEachColumn = [&](auto&& visit) {
      forEachDiscColumn(frame, centre, radius, [&](int i, int j, int n) {
        visit(i, j, n);
        return true;
      });
    };
    // Each column's gaps are looked up once and kept for the weighing below (on fine maps, past
    // the first kKeptGaps columns, looked up again there); none when every column under the
    // disc is known to give the same.
    if (const std::optional<std::array<double, 2>> same = uniform_gaps(r, plane_z)) {
      for (int s = 0; s < 2; ++s) sides[s].lowest = sides[s].highest = (*same)[s];
    } else {
      for (Side& side : sides) side.lowest = kInfinity, side.highest = -kInfinity;
      forEachColumn([&](int i, int j, int n) {
        const std::array<double, 2> gap = columnGaps(i, j);
        for (int s = 0; s < 2; ++s) {
          if (n < kKeptGaps) sides[s].kept[n] = gap[s];
          sides[s].lowest = std::min(sides[s].lowest, gap[s]);
          sides[s].highest = std::max(sides[s].highest, gap[s]);
        }
      });
    }
    // Usually every column under the disc gives the same gap (a flat ceiling, or none): then
    // no area is needed. Otherwise weigh each column by its exact share of the disc.
    std::array<double, 2> covered{0.0, 0.0}, weighted{0.0, 0.0};
    std::array<bool, 2> weigh{false, false};
    for (int s = 0; s < 2; ++s) {
      if (!sides[s].result) continue;
      if (sides[s].lowest != sides[s].highest) {
        weigh[s] = true;
      } else if (sides[s].lowest <= sides[s].reach) {
        covered[s] = disc_area;
        weighted[s] = disc_area * sides[s].lowest;
      }
    }
    if (weigh[0] || weigh[1])
      forEachColumn([&](int i, int j, int n) {
        const std::array<double, 2> gap =
            n < kKeptGaps ? std::array<double, 2>{sides[0].kept[n], sides[1].kept[n]} : columnGaps(i, j);
        double area = -1.0;  // the column's share of the disc, once either side needs it
        for (int s = 0; s < 2; ++s) {
          if (!weigh[s] || gap[s] > sides[s].reach) continue;
          if (area < 0.0)
            area = discRectangleOverlap_m2(centre, radius, {frame.faceOf(0, i), frame.faceOf(1, j)},
                                           {frame.faceOf(0, i + 1), frame.faceOf(1, j + 1)});
          covered[s] += area;
          weighted[s] += area * gap[s];
        }
      });
    for (int s = 0; s < 2; ++s) {
      Side& side = sides[s];
      if (!side.result) continue;
      RotorGap rotor{side.lowest, std::min(covered[s] / disc_area, 1.0), kInfinity};
      if (covered[s] > 0.0) rotor.mean_gap_m = weighted[s] / covered[s];
      side.result->nearest_gap_m = std::min(side.result->nearest_gap_m, rotor.nearest_gap_m);
      side.result->coverage += rotor.coverage / vehicle_.rotor_positions_m.size();
      side.all_covered += covered[s];
      side.all_weighted += weighted[s];
      side.result->rotors.push_back(rotor);
    }
  }
  for (Side& side : sides)
    if (side.result && side.all_covered > 0.0) side.result->mean_gap_m = side.all_weighted / side.all_covered;
}

double Environment::clearance_m(const Eigen::Vector3d& body_m) const {
  requireInside(body_m, "clearance");
  return distance_->distance_m(body_m);
}

double Environment::clearanceLowerBound_m(const Eigen::Vector3d& body_m) const {
  requireInside(body_m, "clearance");
  return distance_->lowerBound_m(body_m);
}

double Environment::validReach_m(const Eigen::Vector3d& body_m) const {
  if (!body_m.allFinite() || !contains(body_m)) return 0.0;
  // Within the reach the bounding sphere stays clear of every blocked voxel (the field's lower
  // bound, which counts the box as blocked when unknown space is), and the body centre inside
  // the box (under the free policy the field does not count it). The margin covers rounding.
  const Eigen::AlignedBox3d box = grid().frame().bounds();
  const double inside_m = std::min((body_m - box.min()).minCoeff(), (box.max() - body_m).minCoeff());
  const double reach_m = std::min(distance_->lowerBound_m(body_m) - bounding_sphere_m_, inside_m);
  return std::max(0.0, reach_m - kReachMargin_m);
}

std::optional<Violation> Environment::exactCylinderViolation(const Eigen::Vector3d& body_m) const {
  const double bottom = body_m.z() + vehicle_.inflatedBottom_m();
  const double top = body_m.z() + vehicle_.inflatedTop_m();
  std::optional<Violation> violation;
  anyColumnUnderCylinder(body_m, [&](int i, int j) {
    const auto state = columns_->firstBlocking(i, j, bottom, top, index_->unknownBlocks());
    if (state)
      violation =
          Violation{0, body_m, *state == CellState::Occupied ? ViolationKind::Occupied : ViolationKind::Unknown};
    return state.has_value();
  });
  return violation;
}

std::optional<Violation> Environment::stateViolation(const Eigen::Vector3d& body_m) const {
  if (!body_m.allFinite() || !contains(body_m)) return Violation{0, body_m, ViolationKind::OutsideMap};
  // Fast path: nothing blocked within the sphere around the inflated cylinder.
  if (distance_->lowerBound_m(body_m) > bounding_sphere_m_) return std::nullopt;
  // Second fast path: nothing blocking within the footprint's reach at the cylinder's heights.
  const GridFrame& frame = grid().frame();
  if (!footprint_.mayBlock(frame.indexOf(0, body_m.x()), frame.indexOf(1, body_m.y()),
                           body_m.z() + vehicle_.inflatedBottom_m(), body_m.z() + vehicle_.inflatedTop_m()))
    return std::nullopt;
  return exactCylinderViolation(body_m);
}

std::optional<Violation> Environment::segmentViolation(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                                       double step_m, bool fast_path) const {
  const double length = (to_m - from_m).norm();
  if (!std::isfinite(length)) return Violation{0, from_m, ViolationKind::OutsideMap};
  const long steps = std::max(1L, static_cast<long>(std::ceil(length / step_m)));
  for (long s = 0; s <= steps; ++s) {
    const Eigen::Vector3d state = from_m + (to_m - from_m) * (static_cast<double>(s) / steps);
    std::optional<Violation> violation;
    if (fast_path) {
      violation = stateViolation(state);
    } else if (!contains(state)) {
      violation = Violation{0, state, ViolationKind::OutsideMap};
    } else {
      violation = exactCylinderViolation(state);
    }
    if (violation) return violation;
  }
  return std::nullopt;
}

std::optional<Violation> Environment::motionViolation(const Eigen::Vector3d& from_m,
                                                      const Eigen::Vector3d& to_m) const {
  return segmentViolation(from_m, to_m, options_.motion_step_voxels * grid().frame().resolution_m(), true);
}

double Environment::denseStep_m() const { return kDenseStepVoxels * grid().frame().resolution_m(); }

std::optional<Violation> Environment::checkPathDensely(const std::vector<Eigen::Vector3d>& waypoints_m) const {
  const double step = kDenseStepVoxels * grid().frame().resolution_m();
  if (waypoints_m.size() == 1) return segmentViolation(waypoints_m[0], waypoints_m[0], step, false);
  for (std::size_t s = 0; s + 1 < waypoints_m.size(); ++s) {
    if (auto violation = segmentViolation(waypoints_m[s], waypoints_m[s + 1], step, false)) {
      violation->segment = s;
      return violation;
    }
  }
  return std::nullopt;
}

bool Environment::assumesFree(const Eigen::Vector3d& body_m) const {
  if (index_->unknownSpace().policy == UnknownPolicy::Occupied || !body_m.allFinite() || !contains(body_m))
    return false;
  const double bottom = body_m.z() + vehicle_.inflatedBottom_m();
  const double top = body_m.z() + vehicle_.inflatedTop_m();
  return anyColumnUnderCylinder(body_m, [&](int i, int j) { return index_->assumedFreeOverlaps(i, j, bottom, top); });
}

AssumedFreeStretches Environment::assumedFreeAlong(const std::vector<Eigen::Vector3d>& waypoints_m) const {
  AssumedFreeStretches result;
  if (index_->unknownSpace().policy == UnknownPolicy::Occupied || waypoints_m.empty()) return result;
  const double step = denseStep_m();
  double start_of_segment = 0.0;
  const auto add = [&](double from, double to, const Eigen::Vector3d& from_point, const Eigen::Vector3d& to_point) {
    if (!result.intervals.empty() && result.intervals.back().to_m >= from - 1e-12) {
      result.intervals.back().to_m = to;
      result.intervals.back().to_point_m = to_point;
    } else {
      result.intervals.push_back({from, to, from_point, to_point});
    }
  };
  if (waypoints_m.size() == 1) {
    if (assumesFree(waypoints_m[0])) add(0.0, 0.0, waypoints_m[0], waypoints_m[0]);
    return result;
  }
  for (std::size_t s = 0; s + 1 < waypoints_m.size(); ++s) {
    const Eigen::Vector3d& from = waypoints_m[s];
    const Eigen::Vector3d& to = waypoints_m[s + 1];
    const double length = (to - from).norm();
    if (!std::isfinite(length)) break;
    const long steps = std::max(1L, static_cast<long>(std::ceil(length / step)));
    const double spacing = length / steps;
    for (long n = 0; n <= steps; ++n) {
      const Eigen::Vector3d state = from + (to - from) * (static_cast<double>(n) / steps);
      if (!assumesFree(state)) continue;
      // This state stands for half a step on either side, within the segment.
      const double lo = std::max(0.0, (n - 0.5) * spacing), hi = std::min(length, (n + 0.5) * spacing);
      add(start_of_segment + lo, start_of_segment + hi, from + (to - from) * (length > 0 ? lo / length : 0.0),
          from + (to - from) * (length > 0 ? hi / length : 0.0));
    }
    start_of_segment += length;
  }
  for (const PathInterval& interval : result.intervals) result.length_m += interval.to_m - interval.from_m;
  return result;
}

}  // namespace ceilplan::environment
