#include "ceilplan/mission/coverage_check.hpp"

#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <map>

namespace ceilplan::mission {
namespace {

constexpr double kDegree = M_PI / 180.0;
// Histogram edges as multiples of the required GSD.
constexpr double kGsdBinShares[] = {0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 4.0};

// The tree's known-free leaves, one bit per voxel over the box of its known leaves, read once:
// a line of sight looks up each of its keys here instead of walking the tree from the root for
// each (OcTree::search), with the same answer (a key in no leaf, or outside the box, is unknown).
class FreeVoxels {
 public:
  explicit FreeVoxels(const octomap::OcTree& tree) {
    const unsigned max_depth = tree.getTreeDepth();
    std::array<unsigned, 3> low{}, high{};
    low.fill(std::numeric_limits<unsigned>::max());
    for (auto leaf = tree.begin_leafs(), end = tree.end_leafs(); leaf != end; ++leaf) {
      const octomap::OcTreeKey& key = leaf.getIndexKey();
      const unsigned span = 1u << (max_depth - leaf.getDepth());
      for (int a = 0; a < 3; ++a) {
        low[a] = std::min<unsigned>(low[a], key[a]);
        high[a] = std::max<unsigned>(high[a], key[a] + span);
      }
    }
    if (low[0] > high[0]) return;  // no leaf: everything unknown
    for (int a = 0; a < 3; ++a) {
      low_[a] = low[a];
      size_[a] = high[a] - low[a];
    }
    bits_.assign((static_cast<std::size_t>(size_[0]) * size_[1] * size_[2] + 63) / 64, 0);
    for (auto leaf = tree.begin_leafs(), end = tree.end_leafs(); leaf != end; ++leaf) {
      if (tree.isNodeOccupied(*leaf)) continue;
      const octomap::OcTreeKey& key = leaf.getIndexKey();
      const unsigned span = 1u << (max_depth - leaf.getDepth());
      for (unsigned z = key[2]; z < key[2] + span; ++z)
        for (unsigned y = key[1]; y < key[1] + span; ++y)
          for (unsigned x = key[0]; x < key[0] + span; ++x) {
            const std::size_t bit = index(x, y, z);
            bits_[bit / 64] |= std::uint64_t{1} << (bit % 64);
          }
    }
  }

  bool free(const octomap::OcTreeKey& key) const {
    if (key[0] < low_[0] || key[1] < low_[1] || key[2] < low_[2] || key[0] >= low_[0] + size_[0] ||
        key[1] >= low_[1] + size_[1] || key[2] >= low_[2] + size_[2])
      return false;
    const std::size_t bit = index(key[0], key[1], key[2]);
    return (bits_[bit / 64] >> (bit % 64)) & 1u;
  }

 private:
  std::size_t index(unsigned x, unsigned y, unsigned z) const {
    return (static_cast<std::size_t>(z - low_[2]) * size_[1] + (y - low_[1])) * size_[0] + (x - low_[0]);
  }

  std::array<unsigned, 3> low_{}, size_{};
  std::vector<std::uint64_t> bits_;
};

// Whether every node on the way from the camera to a point just in front of the face is known
// free in the tree: the ray's keys (OctoMap excludes the end's), then the end's own.
bool clearInTree(const octomap::OcTree& tree, const FreeVoxels& free, const Eigen::Vector3d& from_m,
                 const Eigen::Vector3d& to_m, octomap::KeyRay& ray) {
  const octomap::point3d from(static_cast<float>(from_m.x()), static_cast<float>(from_m.y()),
                              static_cast<float>(from_m.z()));
  const octomap::point3d to(static_cast<float>(to_m.x()), static_cast<float>(to_m.y()), static_cast<float>(to_m.z()));
  octomap::OcTreeKey end;
  if (!tree.coordToKeyChecked(to, end) || !tree.computeRayKeys(from, to, ray)) return false;
  for (const octomap::OcTreeKey& key : ray)
    if (!free.free(key)) return false;
  return free.free(end);
}

// A photo that sees an element in its frame, facing it, beyond the minimum focus.
struct Sight {
  const CameraFrame* frame;
  double gsd_mm_px;
};

// Elements grouped by the cube of kTile_m they lie in, so that a photo is tested only against
// the groups its frustum may reach.
constexpr double kTile_m = 1.0;

struct Tile {
  Eigen::Vector3d centre_m;
  std::vector<std::size_t> elements;
};

std::vector<Tile> tilesOf(const RegionSurface& surface) {
  std::map<std::array<long, 3>, std::vector<std::size_t>> cells;
  for (std::size_t e = 0; e < surface.elements.size(); ++e) {
    const Eigen::Vector3d& c = surface.elements[e].centre_m;
    cells[{std::lround(std::floor(c.x() / kTile_m)), std::lround(std::floor(c.y() / kTile_m)),
           std::lround(std::floor(c.z() / kTile_m))}]
        .push_back(e);
  }
  std::vector<Tile> tiles;
  tiles.reserve(cells.size());
  for (auto& [cell, elements] : cells)
    tiles.push_back(
        {(Eigen::Vector3d(cell[0], cell[1], cell[2]) + Eigen::Vector3d::Constant(0.5)) * kTile_m, std::move(elements)});
  return tiles;
}

// Whether some point within `radius_m` of `centre_m` may land in the frame (within the
// half-width and half-height tangents, at least `min_depth_m` deep): false only when the whole
// ball lies beyond one of the frustum's planes, so no element of a tile it holds is lost.
bool mayProject(const CameraFrame& frame, double wide, double high, double min_depth_m, const Eigen::Vector3d& centre_m,
                double radius_m) {
  const Eigen::Vector3d d = centre_m - frame.position_m();
  if (d.dot(frame.forward()) + radius_m < min_depth_m) return false;
  for (const Eigen::Vector3d& outward :
       {Eigen::Vector3d(frame.right() - wide * frame.forward()),
        Eigen::Vector3d(-frame.right() - wide * frame.forward()), Eigen::Vector3d(frame.up() - high * frame.forward()),
        Eigen::Vector3d(-frame.up() - high * frame.forward())})
    if (outward.dot(d) > radius_m * outward.norm()) return false;
  return true;
}

}  // namespace

CoverageCheck checkCoverage(const octomap::OcTree& tree, const Camera& camera,
                            const std::vector<CoverageRegion>& regions, const std::vector<RegionSurface>& surfaces,
                            const std::vector<std::vector<std::uint8_t>>& reachable,
                            const std::vector<CameraPose>& photos, int workers) {
  if (surfaces.size() != regions.size() || reachable.size() != regions.size())
    throw ceilplan::InputError("coverage check: one surface and one reachability list per region");
  std::vector<CameraFrame> frames;
  frames.reserve(photos.size());
  for (const CameraPose& pose : photos) frames.emplace_back(camera, pose);
  const double offset_m = 0.01 * tree.getResolution();
  const FreeVoxels free(tree);

  CoverageCheck check;
  std::atomic<std::size_t> rays{0};
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const CoverageRegion& region = regions[r];
    const RegionSurface& surface = surfaces[r];
    const std::size_t n = surface.elements.size();
    if (reachable[r].size() != n)
      throw ceilplan::InputError("coverage check: reachability of region '" + region.name + "' has the wrong size");
    RegionCoverageCheck result;
    result.name = region.name;
    result.covered.assign(n, 0);
    result.best_gsd_mm_px.assign(n, std::numeric_limits<float>::infinity());
    result.view_count.assign(n, 0);
    const double cos_max = std::cos(region.max_incidence_deg * kDegree);
    const double wide = camera.halfWidthTan(), high = camera.halfHeightTan();
    const double central_wide = wide * region.widthShare(), central_high = high * region.heightShare();

    const std::vector<Tile> tiles = tilesOf(surface);
    // A tile's ball holds its cube; the margin keeps elements on its faces and rounding inside.
    const double tile_radius_m = 0.5 * std::sqrt(3.0) * kTile_m + 1e-6;
    parallelFor(tiles.size(), workers, [&](std::size_t t) {
      std::vector<const CameraFrame*> near;
      for (const CameraFrame& frame : frames)
        if (mayProject(frame, wide, high, camera.min_focus_m, tiles[t].centre_m, tile_radius_m)) near.push_back(&frame);
      octomap::KeyRay ray;
      std::size_t cast = 0;
      std::vector<Sight> finer;  // per element, the sights outside the limits
      for (const std::size_t e : tiles[t].elements) {
        const environment::SurfaceElement& element = surface.elements[e];
        const Eigen::Vector3d end = element.centre_m + element.faceNormal() * offset_m;
        finer.clear();
        float& best = result.best_gsd_mm_px[e];
        for (const CameraFrame* frame : near) {
          const auto image = frame->project(element.centre_m);
          if (!image || std::abs(image->right_tan) > wide || std::abs(image->up_tan) > high ||
              image->depth_m < camera.min_focus_m)
            continue;
          const Eigen::Vector3d sight = element.centre_m - frame->position_m();
          const double distance_m = sight.norm();
          const double cos_incidence = -sight.dot(element.normal) / distance_m;
          if (cos_incidence <= 0.0) continue;
          const double gsd = camera.gsd_mm_px(distance_m, std::acos(std::min(1.0, cos_incidence)));
          if (gsd > region.gsd_mm_px || cos_incidence < cos_max) {
            finer.push_back({frame, gsd});
            continue;
          }
          // Within the limits, every photo counts (view_count) and may cover: cast each.
          ++cast;
          if (!clearInTree(tree, free, frame->position_m(), end, ray)) continue;
          best = std::min(best, static_cast<float>(gsd));
          if (result.view_count[e] < std::numeric_limits<std::uint16_t>::max()) ++result.view_count[e];
          if (std::abs(image->right_tan) <= central_wide && std::abs(image->up_tan) <= central_high)
            result.covered[e] = 1;
        }
        // Outside them a photo can only lower the best GSD: finest first, until one is clear or
        // none is finer than the best already found (the same best GSD as casting them all).
        std::sort(finer.begin(), finer.end(), [](const Sight& a, const Sight& b) { return a.gsd_mm_px < b.gsd_mm_px; });
        for (const Sight& sight : finer) {
          if (static_cast<float>(sight.gsd_mm_px) >= best) break;
          ++cast;
          if (!clearInTree(tree, free, sight.frame->position_m(), end, ray)) continue;
          best = static_cast<float>(sight.gsd_mm_px);
          break;
        }
      }
      rays += cast;
    });

    for (const double share : kGsdBinShares) result.gsd_bin_edges_mm_px.push_back(share * region.gsd_mm_px);
    result.gsd_bin_area_m2.assign(result.gsd_bin_edges_mm_px.size(), 0.0);
    double gsd_area = 0.0;
    for (std::size_t e = 0; e < n; ++e) {
      const double area = surface.elements[e].area_m2;
      result.area_m2 += area;
      (reachable[r][e] ? result.reachable_area_m2 : result.unreachable_area_m2) += area;
      if (result.covered[e]) {
        result.covered_area_m2 += area;
        if (reachable[r][e]) result.covered_reachable_area_m2 += area;
        gsd_area += area * result.best_gsd_mm_px[e];
      }
      if (!std::isfinite(result.best_gsd_mm_px[e])) {
        result.unseen_area_m2 += area;
        continue;
      }
      const auto bin = std::upper_bound(result.gsd_bin_edges_mm_px.begin(), result.gsd_bin_edges_mm_px.end(),
                                        static_cast<double>(result.best_gsd_mm_px[e]));
      result.gsd_bin_area_m2[std::max<std::ptrdiff_t>(0, bin - result.gsd_bin_edges_mm_px.begin() - 1)] += area;
    }
    result.mean_gsd_mm_px = result.covered_area_m2 > 0.0 ? gsd_area / result.covered_area_m2 : 0.0;
    check.regions.push_back(std::move(result));
  }
  check.rays = rays;
  return check;
}

std::vector<Eigen::Vector3d> uncoveredCentres(const RegionSurface& surface, const RegionCoverageCheck& check) {
  std::vector<Eigen::Vector3d> centres;
  for (std::size_t e = 0; e < surface.elements.size(); ++e)
    if (!check.covered[e]) centres.push_back(surface.elements[e].centre_m);
  return centres;
}

}  // namespace ceilplan::mission
