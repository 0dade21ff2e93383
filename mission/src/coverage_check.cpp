#include "ceilplan/mission/coverage_check.hpp"

#include "ceilplan/core/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace ceilplan::mission {
namespace {

constexpr double kDegree = M_PI / 180.0;
// Histogram edges as multiples of the required GSD.
constexpr double kGsdBinShares[] = {0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0, 4.0};

// Whether every node on the way from the camera to a point just in front of the face is known
// free in the tree: the ray's keys (OctoMap excludes the end's), then the end's own.
bool clearInTree(const octomap::OcTree& tree, const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                 octomap::KeyRay& ray) {
  const octomap::point3d from(static_cast<float>(from_m.x()), static_cast<float>(from_m.y()), static_cast<float>(from_m.z()));
  const octomap::point3d to(static_cast<float>(to_m.x()), static_cast<float>(to_m.y()), static_cast<float>(to_m.z()));
  octomap::OcTreeKey end;
  if (!tree.coordToKeyChecked(to, end) || !tree.computeRayKeys(from, to, ray)) return false;
  const auto freeAt = [&](const octomap::OcTreeKey& key) {
    const octomap::OcTreeNode* node = tree.search(key);
    return node != nullptr && !tree.isNodeOccupied(node);
  };
  for (const octomap::OcTreeKey& key : ray)
    if (!freeAt(key)) return false;
  return freeAt(end);
}

}  // namespace

CoverageCheck checkCoverage(const octomap::OcTree& tree, const Camera& camera, const std::vector<CoverageRegion>& regions,
                            const std::vector<RegionSurface>& surfaces,
                            const std::vector<std::vector<std::uint8_t>>& reachable,
                            const std::vector<CameraPose>& photos, int workers) {
  if (surfaces.size() != regions.size() || reachable.size() != regions.size())
    throw ceilplan::InputError("coverage check: one surface and one reachability list per region");
  std::vector<CameraFrame> frames;
  for (const CameraPose& pose : photos) frames.emplace_back(camera, pose);
  const double offset_m = 0.01 * tree.getResolution();

  CoverageCheck check;
  std::atomic<std::size_t> rays{0};
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const CoverageRegion& region = regions[r];
    const RegionSurface& surface = surfaces[r];
    const std::size_t n = surface.elements.size();
    if (reachable[r].size() != n) throw ceilplan::InputError("coverage check: reachability of region '" + region.name + "' has the wrong size");
    RegionCoverageCheck result;
    result.name = region.name;
    result.covered.assign(n, 0);
    result.best_gsd_mm_px.assign(n, std::numeric_limits<float>::infinity());
    result.view_count.assign(n, 0);
    const double cos_max = std::cos(region.max_incidence_deg * kDegree);
    const double wide = camera.halfWidthTan(), high = camera.halfHeightTan();
    const double central_wide = wide * region.widthShare(), central_high = high * region.heightShare();

    parallelFor(n, workers, [&](std::size_t e) {
      const environment::SurfaceElement& element = surface.elements[e];
      const Eigen::Vector3d end = element.centre_m + element.faceNormal() * offset_m;
      octomap::KeyRay ray;
      std::size_t cast = 0;
      for (const CameraFrame& frame : frames) {
        const auto image = frame.project(element.centre_m);
        if (!image || std::abs(image->right_tan) > wide || std::abs(image->up_tan) > high ||
            image->depth_m < camera.min_focus_m)
          continue;
        const Eigen::Vector3d sight = element.centre_m - frame.position_m();
        const double distance_m = sight.norm();
        const double cos_incidence = -sight.dot(element.normal) / distance_m;
        if (cos_incidence <= 0.0) continue;
        ++cast;
        if (!clearInTree(tree, frame.position_m(), end, ray)) continue;
        const double gsd = camera.gsd_mm_px(distance_m, std::acos(std::min(1.0, cos_incidence)));
        result.best_gsd_mm_px[e] = std::min(result.best_gsd_mm_px[e], static_cast<float>(gsd));
        if (gsd > region.gsd_mm_px || cos_incidence < cos_max) continue;
        if (result.view_count[e] < std::numeric_limits<std::uint16_t>::max()) ++result.view_count[e];
        if (std::abs(image->right_tan) <= central_wide && std::abs(image->up_tan) <= central_high) result.covered[e] = 1;
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
