#include "ceilplan/environment/map_builder.hpp"

#include "ceilplan/environment/distance_field.hpp"
#include "ceilplan/environment/voxel_grid.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/parallel_for.hpp"

#include "map_builder_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <thread>

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
      throw ceilplan::InputError(std::string(what) + " " + std::to_string(i) + " (counting from 0) has a non-finite coordinate " +
                                 formatPoint(points_m[i]));
}

GridFrame importFrame(const Eigen::AlignedBox3d& box_m, double margin_m, double resolution_m) {
  if (!(margin_m >= 0.0) || !std::isfinite(margin_m))
    throw ceilplan::InputError("margin " + formatNumber(margin_m) + " m must be a finite number >= 0");
  constexpr double kKeyHalfRange = 32768.0;  // OctoMap keys are 16 bits, centred on coordinate 0
  Index3 origin, size;
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = std::floor((box_m.min()[axis] - margin_m) / resolution_m);
    const double hi = std::floor((box_m.max()[axis] + margin_m) / resolution_m) + 1.0;
    if (lo < -kKeyHalfRange || hi > kKeyHalfRange)
      throw ceilplan::InputError("the data reach " + formatNumber(std::max(std::abs(box_m.min()[axis]), std::abs(box_m.max()[axis]))) +
                                 " m from the origin on the " + std::string(1, "xyz"[axis]) + " axis, beyond what OctoMap holds at " +
                                 formatNumber(resolution_m) + " m (" + formatNumber(kKeyHalfRange * resolution_m) +
                                 " m); move the data near the origin (--crs does) or coarsen the resolution");
    origin[axis] = static_cast<int>(lo);
    size[axis] = static_cast<int>(hi - lo);
  }
  return GridFrame(resolution_m, origin, size);  // refuses a box of more than VoxelGrid::kMaxVoxels
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

int workerCount() { return std::max(1, static_cast<int>(std::thread::hardware_concurrency())); }

}  // namespace

void SensorOrigins::validate(std::size_t point_count) const {
  if (first_point.size() != origin_m.size())
    throw ceilplan::InputError("sensor origins: " + std::to_string(first_point.size()) + " scan starts for " +
                               std::to_string(origin_m.size()) + " origins");
  if (origin_m.empty()) throw ceilplan::InputError("sensor origins: no origin given");
  if (first_point.front() != 0)
    throw ceilplan::InputError("sensor origins: the first scan must start at point 0, not " + std::to_string(first_point.front()));
  for (std::size_t s = 0; s < origin_m.size(); ++s) {
    if (!origin_m[s].allFinite())
      throw ceilplan::InputError("sensor origins: scan " + std::to_string(s) + " has a non-finite origin " + formatPoint(origin_m[s]));
    if (first_point[s] >= point_count)
      throw ceilplan::InputError("sensor origins: scan " + std::to_string(s) + " starts at point " + std::to_string(first_point[s]) +
                                 " but the cloud has " + std::to_string(point_count) + " points");
    if (s > 0 && first_point[s] <= first_point[s - 1])
      throw ceilplan::InputError("sensor origins: scan " + std::to_string(s) + " starts at point " + std::to_string(first_point[s]) +
                                 ", not after scan " + std::to_string(s - 1) + " (" + std::to_string(first_point[s - 1]) + ")");
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
  Eigen::AlignedBox3d box = boundsOf(points_m);
  for (const Eigen::Vector3d& origin : origins.origin_m) box.extend(origin);
  detail::importFrame(box, 0.0, resolution);  // refuses what could not be held, before the tree grows

  // Scans whose origins share a voxel go in together: one insertion per sensor position, even
  // when the origins file gives every point its own.
  auto tree = std::make_unique<octomap::OcTree>(resolution);
  std::map<std::array<octomap::key_type, 3>, std::vector<std::size_t>> groups;  // ordered: a reproducible insertion order
  for (std::size_t s = 0; s < origins.origin_m.size(); ++s) {
    const Eigen::Vector3d& o = origins.origin_m[s];
    const octomap::OcTreeKey key = tree->coordToKey(o.x(), o.y(), o.z());
    groups[{key[0], key[1], key[2]}].push_back(s);
  }
  const auto scanEnd = [&](std::size_t s) { return s + 1 < origins.first_point.size() ? origins.first_point[s + 1] : points_m.size(); };
  const double max_range = options.max_range_m > 0.0 ? options.max_range_m : -1.0;

  std::size_t inserted = 0;
  for (const auto& [key, scans] : groups) {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    std::size_t count = 0;
    for (std::size_t s : scans) {
      const std::size_t n = scanEnd(s) - origins.first_point[s];
      origin += origins.origin_m[s] * double(n);
      count += n;
    }
    origin /= double(count);
    octomap::Pointcloud cloud;
    cloud.reserve(count);
    for (std::size_t s : scans)
      for (std::size_t i = origins.first_point[s]; i < scanEnd(s); ++i)
        cloud.push_back(float(points_m[i].x()), float(points_m[i].y()), float(points_m[i].z()));
    tree->insertPointCloud(cloud, octomap::point3d(float(origin.x()), float(origin.y()), float(origin.z())), max_range,
                           /*lazy_eval=*/true, /*discretize=*/true);
    inserted += count;
    if (progress) progress(0.9 * double(inserted) / double(points_m.size()));
  }

  // A return marks its voxel occupied for good: rays grazing a thin wall from other positions
  // would otherwise wear it away to free.
  const float occupied_log_odds = tree->getClampingThresMaxLog();
  std::size_t returns = 0;
  for (std::size_t s = 0; s < origins.origin_m.size(); ++s)
    for (std::size_t i = origins.first_point[s]; i < scanEnd(s); ++i) {
      if (max_range > 0.0 && (points_m[i] - origins.origin_m[s]).norm() > max_range) continue;
      tree->setNodeValue(tree->coordToKey(points_m[i].x(), points_m[i].y(), points_m[i].z()), occupied_log_odds, true);
      ++returns;
    }
  tree->updateInnerOccupancy();
  tree->toMaxLikelihood();
  tree->prune();
  if (progress) progress(1.0);

  BuiltMap built;
  built.tree = std::move(tree);
  built.free_space = "carved by ray casting from " + std::to_string(groups.size()) + " sensor position" +
                     (groups.size() == 1 ? "" : "s") + " (OctoMap insertPointCloud, max range " +
                     (max_range > 0.0 ? formatNumber(max_range) + " m" : std::string("none")) +
                     "): space a ray crossed is free, a voxel holding a return is occupied, the rest is unknown";
  built.figures = {{"points", double(points_m.size())},
                   {"scans", double(origins.origin_m.size())},
                   {"sensor_positions", double(groups.size())},
                   {"returns_within_range", double(returns)}};
  detail::addVolumeFigures(built);
  return built;
}

BuiltMap mapFromPointsAlone(const std::vector<Eigen::Vector3d>& points_m, const PointAssumptionOptions& options,
                            const std::function<void(double)>& progress) {
  const double resolution = options.resolution_m;
  detail::checkImportResolution(resolution);
  requirePoints(points_m);
  if (!(options.free_distance_m >= 0.0) || !std::isfinite(options.free_distance_m))
    throw ceilplan::InputError("free distance " + formatNumber(options.free_distance_m) + " m must be a finite number >= 0");
  const GridFrame frame = detail::importFrame(boundsOf(points_m), options.margin_m, resolution);

  VoxelGrid grid(frame);
  for (const Eigen::Vector3d& point : points_m)
    grid.set(frame.indexOf(0, point.x()), frame.indexOf(1, point.y()), frame.indexOf(2, point.z()), CellState::Occupied);
  if (progress) progress(0.1);
  const DistanceField distance(grid, /*unknown_is_blocked=*/false);
  if (progress) progress(0.4);
  const double free_distance = options.free_distance_m;
  parallelFor(
      static_cast<std::size_t>(frame.size()[2]), workerCount(),
      [&](std::size_t layer) {
        const int k = static_cast<int>(layer);
        for (int j = 0; j < frame.size()[1]; ++j)
          for (int i = 0; i < frame.size()[0]; ++i) {
            if (grid.at(i, j, k) == CellState::Occupied) continue;
            const Eigen::Vector3d centre(frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k));
            if (distance.lowerBound_m(centre) > free_distance || distance.distance_m(centre) > free_distance)
              grid.set(i, j, k, CellState::Free);
          }
      },
      progress ? std::function<void(double)>([&](double f) { progress(0.4 + 0.4 * f); }) : std::function<void(double)>());

  BuiltMap built;
  built.tree = toOcTree(grid);
  if (progress) progress(1.0);
  built.free_space = "assumed, no sensor origins: voxels holding a point are occupied; every other voxel of the points' bounding box" +
                     (options.margin_m > 0.0 ? " grown by " + formatNumber(options.margin_m) + " m" : std::string()) +
                     " whose centre lies farther than " + formatNumber(free_distance) +
                     " m from them is free; the rest is unknown";
  built.figures = {{"points", double(points_m.size())}, {"free_distance_m", free_distance}};
  detail::addVolumeFigures(built);
  return built;
}

}  // namespace ceilplan::environment
