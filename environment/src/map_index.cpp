#include "ceilplan/environment/map_index.hpp"

#include "unknown_regions.hpp"

#include <algorithm>

namespace ceilplan::environment {
namespace {

UnknownSpace validated(const UnknownSpace& unknown) {
  unknown.validate();
  return unknown;
}

// The map's voxels as a grid; a map too large to index is refused naming its file.
VoxelGrid gridOf(const OccupancyMap& map, const std::function<void(double)>& progress, int workers) {
  try {
    return VoxelGrid::fromTree(map.tree(), progress, workers);
  } catch (const ceilplan::InputError&) {
    rethrowWithContext(map.name() + ": ");
  }
}

}  // namespace

MapIndex::MapIndex(const OccupancyMap& map, const MapIndexOptions& options, const std::function<void(double)>& progress)
    : map_name_(map.name()),
      unknown_(validated(options.unknown)),
      workers_(options.workers),
      grid_(gridOf(
          map,
          [&](double f) {
            if (progress) progress(0.15 * f);
          },
          options.workers)) {
  // Stages by their share of the time on the shipped scenes.
  if (progress) progress(0.15);
  const ColumnIndex raw(grid_, options.workers);
  if (progress) progress(0.25);
  detail::ResolvedRuns resolved = detail::resolveUnknownSpace(raw, unknown_);
  columns_ = std::make_unique<const ColumnIndex>(grid_.frame(), std::move(resolved.offsets), std::move(resolved.runs));
  assumed_offsets_ = std::move(resolved.assumed_offsets);
  assumed_runs_ = std::move(resolved.assumed_runs);
  summary_ = resolved.summary;
  if (progress) progress(0.3);
  distance_ = std::make_unique<const DistanceField>(*columns_, unknownBlocks(), options.workers, [&](double f) {
    if (progress) progress(0.3 + 0.7 * f);
  });
  if (progress) progress(1.0);
}

std::shared_ptr<const MapIndex> MapIndex::build(const OccupancyMap& map, const MapIndexOptions& options,
                                                const std::function<void(double)>& progress) {
  return std::make_shared<const MapIndex>(map, options, progress);
}

const FreeBlocks& MapIndex::freeBlocks() const {
  std::call_once(free_blocks_built_, [this] {
    free_blocks_ = std::make_unique<const FreeBlocks>(grid_, workers_);
    free_blocks_ready_.store(true, std::memory_order_release);
  });
  return *free_blocks_;
}

bool MapIndex::isAssumedFree(const Eigen::Vector3d& point_m) const {
  const GridFrame& frame = grid_.frame();
  const int i = frame.indexOf(0, point_m.x()), j = frame.indexOf(1, point_m.y()), k = frame.indexOf(2, point_m.z());
  if (!frame.inside(i, j, k)) return false;
  const std::size_t c = static_cast<std::size_t>(j) * frame.size()[0] + i;
  const ColumnIndex::Run* begin = assumed_runs_.data() + assumed_offsets_[c];
  const ColumnIndex::Run* end = assumed_runs_.data() + assumed_offsets_[c + 1];
  const ColumnIndex::Run* run = std::partition_point(begin, end, [k](const ColumnIndex::Run& r) { return r.hi <= k; });
  return run != end && run->lo <= k;
}

bool MapIndex::assumedFreeOverlaps(int i, int j, double bottom_m, double top_m) const {
  const GridFrame& frame = grid_.frame();
  if (i < 0 || j < 0 || i >= frame.size()[0] || j >= frame.size()[1] || !(bottom_m < top_m)) return false;
  const std::size_t c = static_cast<std::size_t>(j) * frame.size()[0] + i;
  const ColumnIndex::Run* end = assumed_runs_.data() + assumed_offsets_[c + 1];
  for (const ColumnIndex::Run* run = assumed_runs_.data() + assumed_offsets_[c]; run != end; ++run) {
    if (frame.faceOf(2, run->lo) >= top_m) break;
    if (frame.faceOf(2, run->hi) > bottom_m) return true;
  }
  return false;
}

std::size_t MapIndex::memoryBytes() const {
  return grid_.memoryBytes() + columns_->memoryBytes() + distance_->memoryBytes() +
         (free_blocks_ready_.load(std::memory_order_acquire) ? free_blocks_->memoryBytes() : 0) +
         assumed_offsets_.capacity() * sizeof(std::uint32_t) + assumed_runs_.capacity() * sizeof(ColumnIndex::Run);
}

}  // namespace ceilplan::environment
