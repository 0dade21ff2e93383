#include "unknown_regions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace ceilplan::environment::detail {
namespace {

using Run = ColumnIndex::Run;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// A connected region of unknown voxels (face, edge or corner contact: a region that leaks
// through a diagonal gap belongs to the larger one), grown run by run.
struct Region {
  int i0 = std::numeric_limits<int>::max(), i1 = std::numeric_limits<int>::min();
  int j0 = std::numeric_limits<int>::max(), j1 = std::numeric_limits<int>::min();
  int k0 = std::numeric_limits<int>::max(), k1 = std::numeric_limits<int>::min();  // voxel indices, inclusive
  bool touches_box = false;   // reaches the boundary of the map's box (open to the unmapped outside)
  bool touches_free = false;  // shares a face with known free space
  std::uint64_t voxels = 0;
};

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0u); }
  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<std::uint32_t> parent_;
};

bool inGridUnknown(const Run& run, int size_z) {
  return run.state == CellState::Unknown && run.lo >= 0 && run.hi <= size_z;
}

// Whether the column runs [begin, end) leave a free voxel in [lo, hi).
bool leavesFree(const Run* begin, const Run* end, std::int32_t lo, std::int32_t hi) {
  const Run* run = std::partition_point(begin, end, [lo](const Run& r) { return r.hi <= lo; });
  std::int32_t covered = lo;
  for (; run != end && covered < hi; ++run) {
    if (run->lo > covered) return true;
    covered = std::max(covered, run->hi);
  }
  return covered < hi;
}

// The columns after (i, j) in row order that touch it: each pair of neighbours is met once.
struct Neighbour {
  int di, dj;
  bool shares_face;
};
constexpr Neighbour kLaterNeighbours[] = {{1, 0, true}, {0, 1, true}, {1, 1, false}, {-1, 1, false}};

class RegionLabelling {
 public:
  explicit RegionLabelling(const ColumnIndex& raw) : raw_(raw), frame_(raw.frame()), run_id_(raw.runCount(), kNone) {
    const int size_z = frame_.size()[2];
    for (std::size_t r = 0; r < raw.runCount(); ++r)
      if (inGridUnknown(raw.runs()[r], size_z)) run_id_[r] = count_++;
    free_beside_.assign(count_, false);
    root_.assign(count_, kNone);
  }

  // Labels every in-grid unknown run with its region's root and returns the regions by root.
  std::vector<Region> label() {
    DisjointSets sets(count_);
    const int nx = frame_.size()[0], ny = frame_.size()[1];
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        for (const Neighbour& neighbour : kLaterNeighbours) {
          const int ni = i + neighbour.di, nj = j + neighbour.dj;
          if (ni < 0 || nj >= ny || ni >= nx) continue;
          joinColumns(i, j, ni, nj, sets);
          if (neighbour.shares_face) {
            markFreeBeside(i, j, ni, nj);
            markFreeBeside(ni, nj, i, j);
          }
        }
      }
    std::vector<Region> regions(count_);
    const int size_z = frame_.size()[2];
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const bool edge = i == 0 || j == 0 || i == nx - 1 || j == ny - 1;
        for (const Run* run = raw_.beginRuns(i, j); run != raw_.endRuns(i, j); ++run) {
          const std::uint32_t id = idOf(run);
          if (id == kNone) continue;
          const std::uint32_t root = root_[id] = sets.find(id);
          Region& region = regions[root];
          region.i0 = std::min(region.i0, i);
          region.i1 = std::max(region.i1, i);
          region.j0 = std::min(region.j0, j);
          region.j1 = std::max(region.j1, j);
          region.k0 = std::min(region.k0, run->lo);
          region.k1 = std::max(region.k1, run->hi - 1);
          region.voxels += static_cast<std::uint64_t>(run->hi - run->lo);
          region.touches_box = region.touches_box || edge || run->lo == 0 || run->hi == size_z;
          // Free voxels directly below or above, in the same column.
          region.touches_free =
              region.touches_free || free_beside_[id] || run->lo > (run - 1)->hi || run->hi < (run + 1)->lo;
        }
      }
    return regions;
  }

  std::uint32_t idOf(const Run* run) const { return run_id_[static_cast<std::size_t>(run - raw_.runs().data())]; }
  std::uint32_t rootOf(const Run* run) const {
    const std::uint32_t id = idOf(run);
    return id == kNone ? kNone : root_[id];
  }
  std::uint32_t count() const { return count_; }

 private:
  // Unites the unknown runs of two neighbouring columns that touch, including at an edge or a
  // corner (one voxel apart in height). Both lists are sorted and disjoint: one sweep.
  void joinColumns(int i, int j, int ni, int nj, DisjointSets& sets) {
    const Run *a = raw_.beginRuns(i, j), *a_end = raw_.endRuns(i, j);
    const Run *b = raw_.beginRuns(ni, nj), *b_end = raw_.endRuns(ni, nj);
    while (a != a_end && b != b_end) {
      const std::uint32_t ia = idOf(a), ib = idOf(b);
      if (ia == kNone) {
        ++a;
        continue;
      }
      if (ib == kNone) {
        ++b;
        continue;
      }
      if (a->lo <= b->hi && b->lo <= a->hi) sets.unite(ia, ib);
      if (a->hi < b->hi)
        ++a;
      else
        ++b;
    }
  }

  // Marks the unknown runs of column (i, j) that face a free voxel of column (ni, nj).
  void markFreeBeside(int i, int j, int ni, int nj) {
    for (const Run* run = raw_.beginRuns(i, j); run != raw_.endRuns(i, j); ++run) {
      const std::uint32_t id = idOf(run);
      if (id == kNone || free_beside_[id]) continue;
      if (leavesFree(raw_.beginRuns(ni, nj), raw_.endRuns(ni, nj), run->lo, run->hi)) free_beside_[id] = true;
    }
  }

  const ColumnIndex& raw_;
  GridFrame frame_;
  std::vector<std::uint32_t> run_id_;  // per raw run: its index among the in-grid unknown runs, or kNone
  std::uint32_t count_ = 0;
  std::vector<bool> free_beside_;    // per unknown run: a face neighbour in the next column is free
  std::vector<std::uint32_t> root_;  // per unknown run: its region's root
};

}  // namespace

ResolvedRuns resolveUnknownSpace(const ColumnIndex& raw, const UnknownSpace& unknown) {
  const GridFrame& frame = raw.frame();
  const int size_z = frame.size()[2];
  const double voxel_m3 = std::pow(frame.resolution_m(), 3);
  ResolvedRuns resolved;

  std::vector<bool> assumed_region;  // fill: per region root, whether it is a pocket to fill
  std::optional<RegionLabelling> labelling;
  if (unknown.policy == UnknownPolicy::Fill) {
    labelling.emplace(raw);
    const std::vector<Region> regions = labelling->label();
    assumed_region.resize(regions.size(), false);
    const double resolution = frame.resolution_m();
    for (std::uint32_t root = 0; root < regions.size(); ++root) {
      const Region& region = regions[root];
      if (region.voxels == 0) continue;  // not a root
      ++resolved.summary.regions;
      const int longest = std::max({region.i1 - region.i0, region.j1 - region.j0, region.k1 - region.k0}) + 1;
      // A relative tolerance, so a pocket exactly fill_max_m long counts at any resolution.
      const bool small = longest * resolution <= unknown.fill_max_m * (1.0 + 1e-9);
      if (!region.touches_box && region.touches_free && small) {
        assumed_region[root] = true;
        ++resolved.summary.filled_regions;
      }
    }
  }

  const std::size_t columns = static_cast<std::size_t>(frame.size()[0]) * frame.size()[1];
  resolved.offsets.reserve(columns + 1);
  resolved.runs.reserve(raw.runCount());
  resolved.assumed_offsets.reserve(columns + 1);
  for (std::size_t c = 0; c < columns; ++c) {
    resolved.offsets.push_back(static_cast<std::uint32_t>(resolved.runs.size()));
    resolved.assumed_offsets.push_back(static_cast<std::uint32_t>(resolved.assumed_runs.size()));
    const Run* end = raw.runs().data() + raw.offsets()[c + 1];
    for (const Run* run = raw.runs().data() + raw.offsets()[c]; run != end; ++run) {
      bool assumed = false;
      if (inGridUnknown(*run, size_z)) {
        resolved.summary.unknown_volume_m3 += (run->hi - run->lo) * voxel_m3;
        assumed = unknown.policy == UnknownPolicy::Free ||
                  (unknown.policy == UnknownPolicy::Fill && assumed_region[labelling->rootOf(run)]);
      }
      if (assumed) {
        resolved.assumed_runs.push_back(*run);
        resolved.summary.assumed_free_volume_m3 += (run->hi - run->lo) * voxel_m3;
      } else {
        resolved.runs.push_back(*run);
      }
    }
  }
  resolved.offsets.push_back(static_cast<std::uint32_t>(resolved.runs.size()));
  resolved.assumed_offsets.push_back(static_cast<std::uint32_t>(resolved.assumed_runs.size()));
  resolved.runs.shrink_to_fit();
  return resolved;
}

}  // namespace ceilplan::environment::detail
