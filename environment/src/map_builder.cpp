#include "ceilplan/environment/map_builder.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/core/parallel_for.hpp"
#include "ceilplan/environment/distance_field.hpp"
#include "ceilplan/environment/voxel_grid.hpp"

#include "map_builder_checks.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <tuple>
#include <utility>

namespace ceilplan::environment {
namespace detail {

void checkImportResolution(double resolution_m) {
  if (!(resolution_m >= kMinImportResolution_m && resolution_m <= kMaxImportResolution_m))
    throw ceilplan::InputError("resolution " + formatNumber(resolution_m) + " m is out of range: use " +
                               formatNumber(kMinImportResolution_m) + " to " + formatNumber(kMaxImportResolution_m) +
                               " m");
}

void requireFinitePoints(const std::vector<Eigen::Vector3d>& points_m, const char* what) {
  for (std::size_t i = 0; i < points_m.size(); ++i)
    if (!points_m[i].allFinite())
      throw ceilplan::InputError(std::string(what) + " " + std::to_string(i) +
                                 " (counting from 0) has a non-finite coordinate " + formatPoint(points_m[i]));
}

GridFrame importFrame(const Eigen::AlignedBox3d& data_m, double margin_m, double resolution_m, const CropBox& crop_m,
                      const char* what) {
  if (!(margin_m >= 0.0) || !std::isfinite(margin_m))
    throw ceilplan::InputError("margin " + formatNumber(margin_m) + " m must be a finite number >= 0");
  const Eigen::AlignedBox3d box_m =
      croppedBox(Eigen::AlignedBox3d(data_m.min().array() - margin_m, data_m.max().array() + margin_m), crop_m, what);
  constexpr double kKeyHalfRange = 32768.0;  // OctoMap keys are 16 bits, centred on coordinate 0
  Index3 origin, size;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::floor(box_m.min()[axis] / resolution_m);
    const double hi = std::floor(box_m.max()[axis] / resolution_m) + 1.0;
    if (lo < -kKeyHalfRange || hi > kKeyHalfRange)
      throw ceilplan::InputError(
          "the data reach " + formatNumber(std::max(std::abs(box_m.min()[axis]), std::abs(box_m.max()[axis]))) +
          " m from the origin on the " + std::string(1, "xyz"[axis]) + " axis, beyond what OctoMap holds at " +
          formatNumber(resolution_m) + " m (" + formatNumber(kKeyHalfRange * resolution_m) +
          " m); move the data near the origin (--crs does) or coarsen the resolution");
    origin[axis] = static_cast<int>(lo);
    size[axis] = static_cast<int>(hi - lo);
  }
  return GridFrame(resolution_m, origin, size);  // refuses a box of more than VoxelGrid::kMaxVoxels
}

Eigen::AlignedBox3d croppedBox(const Eigen::AlignedBox3d& box_m, const CropBox& crop_m, const char* what) {
  if (crop_m.isEmpty()) return box_m;
  const Eigen::AlignedBox3d box = box_m.intersection(crop_m);
  if (box.isEmpty())
    throw ceilplan::InputError(std::string("no ") + what + " lies in the crop box " + formatPoint(crop_m.min()) +
                               " to " + formatPoint(crop_m.max()) + " (uncropped, the map would span " +
                               formatPoint(box_m.min()) + " to " + formatPoint(box_m.max()) + ")");
  return box;
}

std::string cropText(const CropBox& crop_m) {
  return crop_m.isEmpty() ? std::string()
                          : " (cropped to " + formatPoint(crop_m.min()) + " to " + formatPoint(crop_m.max()) + ")";
}

void addVolumeFigures(BuiltMap& built) {
  double occupied = 0.0, free = 0.0;
  for (auto it = built.tree->begin_leafs(), end = built.tree->end_leafs(); it != end; ++it) {
    const double size = it.getSize();
    (built.tree->isNodeOccupied(*it) ? occupied : free) += size * size * size;
  }
  built.figures.emplace_back("occupied_m3", occupied);
  built.figures.emplace_back("free_m3", free);
}

}  // namespace detail

namespace {

Eigen::AlignedBox3d boundsOf(const std::vector<Eigen::Vector3d>& points_m) {
  Eigen::AlignedBox3d box;
  for (const Eigen::Vector3d& point : points_m) box.extend(point);
  return box;
}

void requirePoints(const std::vector<Eigen::Vector3d>& points_m) {
  if (points_m.empty()) throw ceilplan::InputError("the point cloud has no points");
  detail::requireFinitePoints(points_m, "point");
}

// Shortens the segment start -> stop to its part inside `box` (Liang-Barsky); false when none
// is. `cut` tells whether the end was moved.
bool clipToBox(Eigen::Vector3d& start, Eigen::Vector3d& stop, const Eigen::AlignedBox3d& box, bool& cut) {
  const Eigen::Vector3d direction = stop - start;
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (direction[axis] == 0.0) {
      if (start[axis] < box.min()[axis] || start[axis] > box.max()[axis]) return false;
      continue;
    }
    double a = (box.min()[axis] - start[axis]) / direction[axis], b = (box.max()[axis] - start[axis]) / direction[axis];
    if (a > b) std::swap(a, b);
    enter = std::max(enter, a);
    leave = std::min(leave, b);
    if (enter > leave) return false;
  }
  cut = leave < 1.0;
  stop = start + direction * leave;
  start += direction * enter;
  return true;
}

int workerCount() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

// A scan's floors and ceilings have holes: a lamp's or a beam's shadow, a voxel between sparse
// returns. A column in one has a surface on one side only, so between surfaces it would stay
// unknown, a pillar of unknown space standing in a corridor. A column inside a hole of at most two
// voxels across (the columns with a surface above and one below, closed morphologically by a 3 x 3
// square: the outline of what was scanned does not grow, and a gap wider than two voxels stays
// open) takes the highest floor and the lowest ceiling of the columns around it that have both:
// it is free only below every ceiling and above every floor beside it. Returns how many columns
// were closed.
std::size_t closeHolesInSurfaces(std::vector<int>& lowest, std::vector<int>& highest,
                                 const std::vector<int>& occupied_voxels, int nx, int ny) {
  const auto column = [nx](int i, int j) { return std::size_t(j) * nx + i; };
  // A floor and a ceiling: a voxel without a point between the column's lowest and highest
  // point-holding voxels (a wall's column, solid from bottom to top, has none).
  const auto spans = [&](int i, int j) {
    const std::size_t c = column(i, j);
    return highest[c] - lowest[c] + 1 > occupied_voxels[c];
  };
  const auto anyAround = [nx, ny](int i, int j, const auto& test) {
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di)
        if (i + di >= 0 && i + di < nx && j + dj >= 0 && j + dj < ny && test(i + di, j + dj)) return true;
    return false;
  };
  std::vector<char> dilated(std::size_t(nx) * ny, 0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) dilated[column(i, j)] = anyAround(i, j, spans);
  std::vector<std::pair<int, int>> closed;  // (floor, ceiling) per column, or (0, -1): not closed
  closed.assign(std::size_t(nx) * ny, {0, -1});
  std::size_t count = 0;
  for (int j = 1; j + 1 < ny; ++j)
    for (int i = 1; i + 1 < nx; ++i) {
      if (spans(i, j) || anyAround(i, j, [&](int a, int b) { return !dilated[column(a, b)]; })) continue;
      int floor = std::numeric_limits<int>::min(), ceiling = std::numeric_limits<int>::max();
      anyAround(i, j, [&](int a, int b) {
        if (spans(a, b)) {
          floor = std::max(floor, lowest[column(a, b)]);
          ceiling = std::min(ceiling, highest[column(a, b)]);
        }
        return false;
      });
      // Not when the column's own points could fill the span (a wall's column): nothing to free.
      if (ceiling - floor - 1 <= occupied_voxels[column(i, j)]) continue;
      closed[column(i, j)] = {floor, ceiling};
      ++count;
    }
  for (std::size_t c = 0; c < closed.size(); ++c)
    if (closed[c].second >= 0) std::tie(lowest[c], highest[c]) = closed[c];
  return count;
}

}  // namespace

void validateCrop(const CropBox& crop_m) {
  if (crop_m.min() == CropBox().min() && crop_m.max() == CropBox().max()) return;  // the default: no crop
  if (!crop_m.min().allFinite() || !crop_m.max().allFinite())
    throw ceilplan::InputError("a crop box needs finite corners, not " + formatPoint(crop_m.min()) + " to " +
                               formatPoint(crop_m.max()));
  for (int axis = 0; axis < 3; ++axis)
    if (!(crop_m.min()[axis] < crop_m.max()[axis]))
      throw ceilplan::InputError("a crop box's " + std::string(1, "xyz"[axis]) + " minimum (" +
                                 formatNumber(crop_m.min()[axis]) + ") must be below its maximum (" +
                                 formatNumber(crop_m.max()[axis]) + ")");
}

void SensorOrigins::validate(std::size_t point_count) const {
  if (first_point.size() != origin_m.size())
    throw ceilplan::InputError("sensor origins: " + std::to_string(first_point.size()) + " scan starts for " +
                               std::to_string(origin_m.size()) + " origins");
  if (origin_m.empty()) throw ceilplan::InputError("sensor origins: no origin given");
  if (first_point.front() != 0)
    throw ceilplan::InputError("sensor origins: the first scan must start at point 0, not " +
                               std::to_string(first_point.front()));
  for (std::size_t s = 0; s < origin_m.size(); ++s) {
    if (!origin_m[s].allFinite())
      throw ceilplan::InputError("sensor origins: scan " + std::to_string(s) + " has a non-finite origin " +
                                 formatPoint(origin_m[s]));
    if (first_point[s] >= point_count)
      throw ceilplan::InputError("sensor origins: scan " + std::to_string(s) + " starts at point " +
                                 std::to_string(first_point[s]) + " but the cloud has " + std::to_string(point_count) +
                                 " points");
    if (s > 0 && first_point[s] <= first_point[s - 1])
      throw ceilplan::InputError("sensor origins: scan " + std::to_string(s) + " starts at point " +
                                 std::to_string(first_point[s]) + ", not after scan " + std::to_string(s - 1) + " (" +
                                 std::to_string(first_point[s - 1]) + ")");
  }
}

std::vector<Eigen::Vector3d> SensorOrigins::perPoint(std::size_t point_count) const {
  std::vector<Eigen::Vector3d> result(point_count);
  for (std::size_t s = 0; s < origin_m.size(); ++s) {
    const std::size_t end = s + 1 < first_point.size() ? first_point[s + 1] : point_count;
    std::fill(result.begin() + first_point[s], result.begin() + end, origin_m[s]);
  }
  return result;
}

std::size_t dropNonFinitePoints(std::vector<Eigen::Vector3d>& points_m, SensorOrigins* origins) {
  std::vector<std::size_t> kept_before_scan;  // points kept before each scan's first point
  std::size_t scan = 0, kept = 0;
  for (std::size_t i = 0; i < points_m.size(); ++i) {
    while (origins && scan < origins->first_point.size() && origins->first_point[scan] == i) {
      kept_before_scan.push_back(kept);
      ++scan;
    }
    if (points_m[i].allFinite()) points_m[kept++] = points_m[i];
  }
  const std::size_t dropped = points_m.size() - kept;
  points_m.resize(kept);
  if (origins) {
    // Renumber the scans; a scan left with no point disappears.
    SensorOrigins renumbered;
    for (std::size_t s = 0; s < kept_before_scan.size(); ++s) {
      const std::size_t end = s + 1 < kept_before_scan.size() ? kept_before_scan[s + 1] : kept;
      if (end == kept_before_scan[s]) continue;
      renumbered.first_point.push_back(kept_before_scan[s]);
      renumbered.origin_m.push_back(origins->origin_m[s]);
    }
    *origins = std::move(renumbered);
  }
  return dropped;
}

BuiltMap carveFromScans(const std::vector<Eigen::Vector3d>& points_m, const SensorOrigins& origins,
                        const RayCarvingOptions& options, const std::function<void(double)>& progress) {
  const double resolution = options.resolution_m;
  detail::checkImportResolution(resolution);
  requirePoints(points_m);
  origins.validate(points_m.size());
  if (!std::isfinite(options.max_range_m))
    throw ceilplan::InputError("max range must be a finite number of metres (0 for none)");
  validateCrop(options.crop_m);
  const double max_range = options.max_range_m > 0.0 ? options.max_range_m : std::numeric_limits<double>::infinity();
  const CropBox& crop = options.crop_m;
  const std::size_t scans = origins.origin_m.size();
  const auto scanOf = [&](std::size_t point) {
    return static_cast<std::size_t>(std::upper_bound(origins.first_point.begin(), origins.first_point.end(), point) -
                                    origins.first_point.begin()) -
           1;
  };
  const auto inRange = [&](std::size_t i, std::size_t scan) {
    return (points_m[i] - origins.origin_m[scan]).norm() <= max_range;
  };
  const auto kept = [&](std::size_t i, std::size_t scan) {
    return inRange(i, scan) && (crop.isEmpty() || crop.contains(points_m[i]));
  };

  // The box holds the returns kept and the origins, inside the crop: far returns do not grow it.
  Eigen::AlignedBox3d box;
  std::size_t within_range = 0, returns = 0;
  for (std::size_t i = 0, scan = 0; i < points_m.size(); ++i) {
    while (scan + 1 < scans && origins.first_point[scan + 1] <= i) ++scan;
    within_range += inRange(i, scan);
    if (kept(i, scan)) {
      box.extend(points_m[i]);
      ++returns;
    }
  }
  if (returns == 0)
    throw ceilplan::InputError(
        "no return lies within " +
        (std::isfinite(max_range) ? formatNumber(max_range) + " m of its origin" : std::string()) +
        (std::isfinite(max_range) && !crop.isEmpty() ? " and " : "") +
        (crop.isEmpty() ? std::string() : "the crop box" + detail::cropText(crop)));
  for (const Eigen::Vector3d& origin : origins.origin_m) box.extend(origin);
  // Refused here, before anything is allocated.
  const GridFrame frame = detail::importFrame(box, 0.0, resolution, crop, "return");

  // Rays are traced with OctoMap's own voxel traversal (computeRayKeys, the one insertPointCloud
  // uses) on both cores into a dense grid; insertPointCloud itself hashes every crossed voxel on
  // one core and took minutes for a few million points (docs/import.md). The rule is the same
  // as its maximum-likelihood result: crossed voxels are free, voxels holding a return occupied.
  const std::size_t voxels = frame.voxelCount();
  const std::unique_ptr<std::atomic<std::uint8_t>[]> crossed(new std::atomic<std::uint8_t>[voxels]());
  const octomap::OcTree keys(resolution);  // only its key arithmetic is used, read-only from every thread
  // Rays leave the box (to far or cropped returns, from origins outside the crop): only the
  // voxels inside it are marked.
  const auto mark = [&](const octomap::OcTreeKey& key) {
    constexpr int kKeyOffset = 32768;  // OctoMap key of global voxel index 0
    const int i = int(key[0]) - kKeyOffset - frame.origin()[0], j = int(key[1]) - kKeyOffset - frame.origin()[1],
              k = int(key[2]) - kKeyOffset - frame.origin()[2];
    if (frame.inside(i, j, k)) crossed[frame.linear(i, j, k)].store(1, std::memory_order_relaxed);
  };
  Eigen::AlignedBox3d frame_box_m;
  for (int axis = 0; axis < 3; ++axis) {
    frame_box_m.min()[axis] = frame.faceOf(axis, 0);
    frame_box_m.max()[axis] = frame.faceOf(axis, frame.size()[axis]);
  }
  constexpr std::size_t kPointsPerTask = 16384;
  const std::size_t tasks = (points_m.size() + kPointsPerTask - 1) / kPointsPerTask;
  parallelFor(
      tasks, workerCount(),
      [&](std::size_t task) {
        // A ray crosses fewer voxels than KeyRay's default capacity (100 000): the frame's
        // diagonal stays below that within VoxelGrid::kMaxVoxels and OctoMap's key range.
        octomap::KeyRay ray;
        const std::size_t begin = task * kPointsPerTask, end = std::min(begin + kPointsPerTask, points_m.size());
        for (std::size_t i = begin, scan = scanOf(begin); i < end; ++i) {
          while (scan + 1 < scans && origins.first_point[scan + 1] <= i) ++scan;
          const Eigen::Vector3d& origin = origins.origin_m[scan];
          const double length = (points_m[i] - origin).norm();
          const bool truncated = length > max_range;
          Eigen::Vector3d start = origin;
          Eigen::Vector3d stop =
              truncated ? Eigen::Vector3d(origin + (points_m[i] - origin) * (max_range / length)) : points_m[i];
          bool cut = false;  // the ray leaves the box before its end
          if (!clipToBox(start, stop, frame_box_m, cut)) continue;
          if (!keys.computeRayKeys(octomap::point3d(float(start.x()), float(start.y()), float(start.z())),
                                   octomap::point3d(float(stop.x()), float(stop.y()), float(stop.z())), ray))
            continue;
          for (const octomap::OcTreeKey& key : ray) mark(key);
          if (truncated || cut) mark(keys.coordToKey(stop.x(), stop.y(), stop.z()));
        }
      },
      progress ? std::function<void(double)>([&](double f) { progress(0.7 * f); }) : std::function<void(double)>());

  VoxelGrid grid(frame);
  for (std::size_t v = 0; v < voxels; ++v)
    if (crossed[v].load(std::memory_order_relaxed)) {
      const Index3 i = frame.unlinear(v);
      grid.set(i[0], i[1], i[2], CellState::Free);
    }
  // A return marks its voxel occupied whatever other rays crossed it: rays grazing a thin wall
  // from other positions would otherwise wear it away. A return just outside the crop but in a
  // voxel of the map counts too: that voxel is not free.
  for (std::size_t i = 0, scan = 0; i < points_m.size(); ++i) {
    while (scan + 1 < scans && origins.first_point[scan + 1] <= i) ++scan;
    const Index3 v = {frame.indexOf(0, points_m[i].x()), frame.indexOf(1, points_m[i].y()),
                      frame.indexOf(2, points_m[i].z())};
    if (inRange(i, scan) && frame.inside(v[0], v[1], v[2])) grid.set(v[0], v[1], v[2], CellState::Occupied);
  }
  if (progress) progress(0.8);

  BuiltMap built;
  built.tree = toOcTree(grid);
  if (progress) progress(1.0);
  built.free_space = "carved by ray casting from " + std::to_string(scans) + " sensor origin" +
                     (scans == 1 ? "" : "s") + " (max range " +
                     (std::isfinite(max_range) ? formatNumber(max_range) + " m" : std::string("none")) + ")" +
                     detail::cropText(crop) + " along " + std::to_string(points_m.size()) + " ray" +
                     (points_m.size() == 1 ? "" : "s") +
                     ": space a ray crossed is free, a voxel holding a return is occupied, space no ray crossed is "
                     "unknown: an obstacle for planning unless --unknown free or fill";
  built.figures = {
      {"points", double(points_m.size())}, {"scans", double(scans)}, {"returns_within_range", double(within_range)}};
  if (!crop.isEmpty()) built.figures.emplace_back("returns_in_crop", double(returns));
  detail::addVolumeFigures(built);
  return built;
}

AssumedFreeRegion assumedFreeRegionFromName(const std::string& name) {
  if (name == "between") return AssumedFreeRegion::BetweenSurfaces;
  if (name == "box") return AssumedFreeRegion::WholeBox;
  throw ceilplan::InputError("unknown free region '" + name + "': use between or box");
}

BuiltMap mapFromPointsAlone(const std::vector<Eigen::Vector3d>& points_m, const PointAssumptionOptions& options,
                            const std::function<void(double)>& progress) {
  const double resolution = options.resolution_m;
  detail::checkImportResolution(resolution);
  requirePoints(points_m);
  if (!(options.free_distance_m >= 0.0) || !std::isfinite(options.free_distance_m))
    throw ceilplan::InputError("free distance " + formatNumber(options.free_distance_m) +
                               " m must be a finite number >= 0");
  validateCrop(options.crop_m);
  const CropBox& crop = options.crop_m;
  Eigen::AlignedBox3d box;
  std::size_t in_crop = 0;
  for (const Eigen::Vector3d& point : points_m)
    if (crop.isEmpty() || crop.contains(point)) {
      box.extend(point);
      ++in_crop;
    }
  if (in_crop == 0) detail::croppedBox(boundsOf(points_m), crop, "point");  // says where the points are
  const GridFrame frame = detail::importFrame(box, options.margin_m, resolution, crop, "point");

  // A point just outside the crop, in a voxel of the map, still makes that voxel occupied.
  VoxelGrid grid(frame);
  for (const Eigen::Vector3d& point : points_m) {
    const Index3 v = {frame.indexOf(0, point.x()), frame.indexOf(1, point.y()), frame.indexOf(2, point.z())};
    if (frame.inside(v[0], v[1], v[2])) grid.set(v[0], v[1], v[2], CellState::Occupied);
  }
  if (progress) progress(0.1);
  // Each column's lowest and highest point-holding voxel: between them the cloud has a surface
  // above and one below (AssumedFreeRegion::BetweenSurfaces).
  const int nx = frame.size()[0], ny = frame.size()[1], nz = frame.size()[2];
  std::vector<int> lowest(std::size_t(nx) * ny, nz), highest(std::size_t(nx) * ny, -1);
  std::vector<int> occupied_voxels(std::size_t(nx) * ny, 0);
  const bool between = options.region == AssumedFreeRegion::BetweenSurfaces;
  if (between)
    for (int k = 0; k < nz; ++k)
      for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
          if (grid.at(i, j, k) == CellState::Occupied) {
            const std::size_t column = std::size_t(j) * nx + i;
            lowest[column] = std::min(lowest[column], k);
            highest[column] = k;
            ++occupied_voxels[column];
          }
  const std::size_t closed_columns = between ? closeHolesInSurfaces(lowest, highest, occupied_voxels, nx, ny) : 0;
  const DistanceField distance(grid, /*unknown_is_blocked=*/false);
  if (progress) progress(0.4);
  const double free_distance = options.free_distance_m;
  parallelFor(
      static_cast<std::size_t>(frame.size()[2]), workerCount(),
      [&](std::size_t layer) {
        const int k = static_cast<int>(layer);
        for (int j = 0; j < ny; ++j)
          for (int i = 0; i < nx; ++i) {
            if (grid.at(i, j, k) == CellState::Occupied) continue;
            const std::size_t column = std::size_t(j) * nx + i;
            if (between && !(lowest[column] < k && k < highest[column])) continue;
            const Eigen::Vector3d centre(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
            if (distance.lowerBound_m(centre) > free_distance || distance.distance_m(centre) > free_distance)
              grid.set(i, j, k, CellState::Free);
          }
      },
      progress ? std::function<void(double)>([&](double f) { progress(0.4 + 0.4 * f); })
               : std::function<void(double)>());

  BuiltMap built;
  built.tree = toOcTree(grid);
  if (progress) progress(1.0);
  const std::string box_text =
      "the points' bounding box" +
      (options.margin_m > 0.0 ? " grown by " + formatNumber(options.margin_m) + " m" : std::string()) +
      detail::cropText(crop);
  std::string line = "assumed, no sensor origins: voxels holding a point are occupied; every other voxel of " +
                     box_text + (between ? " with a point above and below it in its column" : "");
  line += free_distance > 0.0 ? " whose centre lies farther than " + formatNumber(free_distance) +
                                    " m from them is free; the rest is unknown: an obstacle for planning unless "
                                    "--unknown free or fill, and no ceiling is seen through that band"
                              : " is free";
  line += between ? "; beyond the scanned surfaces (outside walls, beside the structure) the cloud says nothing, "
                    "so that space is unknown"
                  : ", behind walls and beside the structure too: planning may use space the scan never saw";
  if (closed_columns > 0)
    line +=
        "; holes of up to two voxels across in a scanned floor or ceiling take the floor and ceiling around "
        "them (" +
        std::to_string(closed_columns) + (closed_columns == 1 ? " column)" : " columns)");
  built.free_space = line;
  built.figures = {{"points", double(points_m.size())}, {"free_distance_m", free_distance}};
  if (!crop.isEmpty()) built.figures.emplace_back("points_in_crop", double(in_crop));
  if (between) built.figures.emplace_back("columns_closed_across_holes", double(closed_columns));
  detail::addVolumeFigures(built);
  return built;
}

}  // namespace ceilplan::environment
