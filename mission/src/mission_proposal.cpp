#include "ceilplan/mission/mission_proposal.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/environment/map_builder.hpp"
#include "ceilplan/environment/surface_elements.hpp"
#include "ceilplan/mission/coverage_region.hpp"
#include "ceilplan/mission/coverage_views.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace ceilplan::mission {
namespace {

using environment::CellState;
using environment::Index3;

// The columns searched for a home: one every half metre (at least every voxel).
constexpr double kHomeColumnSpacing_m = 0.5;
// A home has room to climb straight up this far: not under a shelf, a stair or a girder.
constexpr double kHomeClimbRoom_m = 1.5;
// A home stands on the lowest floor or ground: at most this far above the lowest floor any valid
// home was found on (the ground's slope and its scan noise), not on a ledge, a roof or a table.
constexpr double kHomeGroundTolerance_m = 0.5;

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t count) : parent_(count) { std::iota(parent_.begin(), parent_.end(), 0); }
  std::size_t root(std::size_t item) {
    while (parent_[item] != item) item = parent_[item] = parent_[parent_[item]];
    return item;
  }
  void join(std::size_t a, std::size_t b) { parent_[root(a)] = root(b); }

 private:
  std::vector<std::size_t> parent_;
};

// Whether the voxel (i, j, k) is free air for planning: known free, or unknown that the policy assumes free.
bool freeForPlanning(const environment::Environment& environment, int i, int j, int k) {
  const environment::VoxelGrid& grid = environment.grid();
  const CellState state = grid.at(i, j, k);
  if (state == CellState::Free) return true;
  const environment::GridFrame& frame = grid.frame();
  return state == CellState::Unknown &&
         environment.index()->isAssumedFree({frame.centreOf(0, i), frame.centreOf(1, j), frame.centreOf(2, k)});
}

// The height of free air below a down-facing element: from the voxel its face opens onto, down to
// the first voxel that is not free for planning (a floor, the ground, or where the data end).
double roomBelow_m(const environment::Environment& environment, const environment::SurfaceElement& element) {
  const environment::GridFrame& frame = environment.grid().frame();
  static constexpr int kFaceOffset[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const int i = element.voxel[0] + kFaceOffset[element.face][0], j = element.voxel[1] + kFaceOffset[element.face][1];
  const int top = element.voxel[2] + kFaceOffset[element.face][2];
  if (!frame.inside(i, j, top)) return 0.0;
  int k = top;
  while (k >= 0 && freeForPlanning(environment, i, j, k)) --k;
  return (top - k) * frame.resolution_m();
}

// Down-facing elements at least `proposal.min_room_below_m` above the ground (an open mesh's or a
// scan's ground seen from under it is no overhead surface), joined where their voxels touch
// (faces, edges or corners); a region is kept when most of its area has that much free air below
// it (a table's underside has not; a ceiling above a few lamps has, and its faces over the lamps
// are seen obliquely). `elements` gets every down-facing element, low or not.
std::vector<ProposedRegion> overheadRegions(const environment::Environment& environment,
                                            const Eigen::AlignedBox3d& box_m, MissionProposal& proposal,
                                            std::vector<environment::SurfaceElement>& elements) {
  const double min_room_below_m = proposal.min_room_below_m;
  const double lowest_m = std::isfinite(proposal.ground_m) ? proposal.ground_m + min_room_below_m
                                                           : -std::numeric_limits<double>::infinity();
  const environment::VoxelGrid& grid = environment.grid();
  std::vector<environment::SurfaceElement> high;
  proposal.overhead_area_m2 = proposal.too_low_area_m2 = 0.0;
  for (environment::SurfaceElement& element : environment::exposedSurface(grid, box_m)) {
    if (faceKindOf(element.normal) != FaceKind::Down) continue;
    elements.push_back(element);
    proposal.overhead_area_m2 += element.area_m2;
    if (element.centre_m.z() + 1e-9 >= lowest_m)
      high.push_back(element);
    else
      proposal.too_low_area_m2 += element.area_m2;
  }
  const environment::GridFrame& frame = grid.frame();
  std::unordered_map<std::size_t, std::size_t> element_of_voxel;  // one element per voxel is enough to join
  DisjointSets sets(high.size());
  for (std::size_t e = 0; e < high.size(); ++e) {
    const Index3& v = high[e].voxel;
    const auto [it, inserted] = element_of_voxel.emplace(frame.linear(v[0], v[1], v[2]), e);
    if (!inserted) sets.join(e, it->second);
  }
  for (std::size_t e = 0; e < high.size(); ++e) {
    const Index3& v = high[e].voxel;
    for (int di = -1; di <= 1; ++di)
      for (int dj = -1; dj <= 1; ++dj)
        for (int dk = -1; dk <= 1; ++dk) {
          if (!frame.inside(v[0] + di, v[1] + dj, v[2] + dk)) continue;
          const auto neighbour = element_of_voxel.find(frame.linear(v[0] + di, v[1] + dj, v[2] + dk));
          if (neighbour != element_of_voxel.end()) sets.join(e, neighbour->second);
        }
  }
  std::unordered_map<std::size_t, std::size_t> region_of_root;
  std::vector<ProposedRegion> regions;
  std::vector<double> roomy_area_m2;  // per region: of faces with the room below them
  const Eigen::Vector3d half_voxel = Eigen::Vector3d::Constant(frame.resolution_m() / 2.0);
  for (std::size_t e = 0; e < high.size(); ++e) {
    const auto [it, inserted] = region_of_root.emplace(sets.root(e), regions.size());
    if (inserted) {
      regions.emplace_back();
      roomy_area_m2.push_back(0.0);
    }
    ProposedRegion& region = regions[it->second];
    if (roomBelow_m(environment, high[e]) + 1e-9 >= min_room_below_m) roomy_area_m2[it->second] += high[e].area_m2;
    region.box_m.extend(high[e].centre_m - half_voxel);
    region.box_m.extend(high[e].centre_m + half_voxel);
    region.area_m2 += high[e].area_m2;
    ++region.elements;
  }
  std::vector<ProposedRegion> roomy;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    if (2.0 * roomy_area_m2[r] >= regions[r].area_m2)
      roomy.push_back(regions[r]);
    else
      proposal.too_low_area_m2 += regions[r].area_m2;
  }
  regions = std::move(roomy);
  // Largest first; ties by place, so that the order does not depend on the hash map's.
  std::sort(regions.begin(), regions.end(), [](const ProposedRegion& a, const ProposedRegion& b) {
    if (a.area_m2 != b.area_m2) return a.area_m2 > b.area_m2;
    return std::lexicographical_compare(a.box_m.min().data(), a.box_m.min().data() + 3, b.box_m.min().data(),
                                        b.box_m.min().data() + 3);
  });
  return regions;
}

// Whether the body at `body_m` is a valid state that relies on no assumption about unknown space.
bool validInKnownFreeSpace(const environment::Environment& environment, const Eigen::Vector3d& body_m) {
  return environment.contains(body_m) && environment.isStateValid(body_m) && !environment.assumesFree(body_m);
}

// How far `body_m` lies above the nearest occupied voxel below it; NaN when there is none.
double heightAboveFloor(const environment::VoxelGrid& grid, const Eigen::Vector3d& body_m) {
  const environment::GridFrame& frame = grid.frame();
  const int i = frame.indexOf(0, body_m.x()), j = frame.indexOf(1, body_m.y());
  for (int k = frame.indexOf(2, body_m.z()); k >= 0; --k)
    if (grid.at(i, j, k) == CellState::Occupied) return body_m.z() - frame.faceOf(2, k + 1);
  return std::nan("");
}

struct HomeCandidate {
  Eigen::Vector3d body_m;
  double floor_m;
  double height_m;
};

// Column (i, j)'s floor: the lowest top of an occupied voxel with free air above it tall enough for
// the vehicle with its margins (a pocket under a scan's ground is no floor). A home on it at
// `options`'s heights, in known free space, that the vehicle reaches straight up from the floor
// and leaves climbing straight up; none when that floor has none (under or beside a table, a
// shelf): a higher floor of the column (the table top) is no home.
std::optional<HomeCandidate> columnHome(const environment::Environment& environment, const ProposalOptions& options,
                                        int i, int j) {
  const environment::VoxelGrid& grid = environment.grid();
  const environment::GridFrame& frame = grid.frame();
  const double resolution_m = frame.resolution_m();
  const environment::VehicleGeometry& vehicle = environment.vehicle();
  const int layers = frame.size()[2];
  const int least_free_voxels =
      static_cast<int>(std::ceil((vehicle.inflatedTop_m() - vehicle.inflatedBottom_m()) / resolution_m - 1e-9));
  for (int k = 1; k < layers; ++k) {
    if (grid.at(i, j, k) != CellState::Free || grid.at(i, j, k - 1) != CellState::Occupied) continue;
    int free_voxels = 0;
    while (k + free_voxels < layers && grid.at(i, j, k + free_voxels) == CellState::Free) ++free_voxels;
    if (free_voxels < least_free_voxels) continue;
    const double floor_m = frame.faceOf(2, k);
    // Within the free air on this floor: above the table under which it stands is another floor.
    // Landed on the floor, half a voxel up: the vehicle rises from there to the home and on.
    const Eigen::Vector3d standing(frame.centreOf(0, i), frame.centreOf(1, j),
                                   floor_m - vehicle.inflatedBottom_m() + resolution_m / 2.0);
    const double max_height_m =
        std::min(options.max_home_height_m, free_voxels * resolution_m - vehicle.inflatedTop_m());
    for (double height_m = options.min_home_height_m; height_m <= max_height_m + 1e-9; height_m += resolution_m) {
      const Eigen::Vector3d body(frame.centreOf(0, i), frame.centreOf(1, j), floor_m + height_m);
      const Eigen::Vector3d above = body + Eigen::Vector3d(0.0, 0.0, kHomeClimbRoom_m);
      if (validInKnownFreeSpace(environment, standing) && validInKnownFreeSpace(environment, body) &&
          validInKnownFreeSpace(environment, above) && environment.isMotionValid(standing, above))
        return HomeCandidate{body, floor_m, height_m};
    }
    return std::nullopt;
  }
  return std::nullopt;
}

// A home in every column (every half metre, inside the crop) that has one.
std::vector<HomeCandidate> homeCandidates(const environment::Environment& environment, const ProposalOptions& options,
                                          const ProgressCallback& progress) {
  const environment::GridFrame& frame = environment.grid().frame();
  const int stride = std::max(1, static_cast<int>(std::lround(kHomeColumnSpacing_m / frame.resolution_m())));
  std::vector<HomeCandidate> candidates;
  const Index3& size = frame.size();
  for (int i = 0; i < size[0]; i += stride) {
    if (progress) progress("proposing a home", static_cast<double>(i) / size[0]);
    for (int j = 0; j < size[1]; j += stride) {
      const Eigen::Vector2d column(frame.centreOf(0, i), frame.centreOf(1, j));
      if (options.crop_m && (column.x() < options.crop_m->min().x() || column.x() > options.crop_m->max().x() ||
                             column.y() < options.crop_m->min().y() || column.y() > options.crop_m->max().y()))
        continue;
      if (const std::optional<HomeCandidate> home = columnHome(environment, options, i, j)) candidates.push_back(*home);
    }
  }
  if (progress) progress("proposing a home", 1.0);
  return candidates;
}

// The ground: the lowest floor a home can stand on; NaN when there is none.
double groundOf(const std::vector<HomeCandidate>& candidates) {
  double ground_m = std::nan("");
  for (const HomeCandidate& candidate : candidates)
    if (!(candidate.floor_m >= ground_m)) ground_m = candidate.floor_m;
  return ground_m;
}

// On the ground (within kHomeGroundTolerance_m of it), as close (horizontally) to `towards_m` as
// there is: a ledge, a roof or a table top is no home.
std::optional<HomeCandidate> proposeHome(const std::vector<HomeCandidate>& candidates, double ground_m,
                                         const Eigen::Vector2d& towards_m) {
  std::optional<HomeCandidate> best;
  double best_distance_m = std::numeric_limits<double>::infinity();
  for (const HomeCandidate& candidate : candidates) {
    const double distance_m = (candidate.body_m.head<2>() - towards_m).norm();
    if (candidate.floor_m <= ground_m + kHomeGroundTolerance_m && distance_m < best_distance_m) {
      best = candidate;
      best_distance_m = distance_m;
    }
  }
  return best;
}

}  // namespace

double proposalStandoff_m(const Camera& camera, double gsd_mm_px) {
  const double free_standoff_m = ViewGenerationOptions{}.free_standoff_m;
  return std::max(camera.min_focus_m, std::min(free_standoff_m, camera.distanceForGsd_m(gsd_mm_px)));
}

void ProposalOptions::validate() const {
  if (crop_m) environment::validateCrop(*crop_m);
  if (home_m && !home_m->allFinite()) throw ceilplan::InputError("home: give three finite coordinates");
  if (!(std::isfinite(min_region_area_m2) && min_region_area_m2 >= 0.0))
    throw ceilplan::InputError("min_region_area_m2 " + formatNumber(min_region_area_m2) + ": a finite area >= 0");
  if (max_regions < 1 || max_regions > 100)
    throw ceilplan::InputError("max_regions " + std::to_string(max_regions) + ": use 1 to 100");
  if (!(standoff_m > 0.0 && standoff_m <= 100.0))
    throw ceilplan::InputError("standoff " + formatNumber(standoff_m) + " m: use more than 0 and at most 100 m");
  for (const double height_m : {min_home_height_m, max_home_height_m})
    if (!(height_m > 0.0 && height_m <= 100.0))
      throw ceilplan::InputError("home height " + formatNumber(height_m) + " m: use more than 0 and at most 100 m");
  if (min_home_height_m > max_home_height_m)
    throw ceilplan::InputError("home heights: the least (" + formatNumber(min_home_height_m) +
                               " m) is above the greatest (" + formatNumber(max_home_height_m) + " m)");
}

MissionProposal proposeMission(const environment::Environment& environment, const ProposalOptions& options,
                               const ProgressCallback& progress) {
  options.validate();
  const environment::VoxelGrid& grid = environment.grid();
  if (options.home_m) {
    if (!environment.contains(*options.home_m))
      throw ceilplan::InputError("the given home " + formatPoint(*options.home_m) + " lies outside the map " +
                                 formatPoint(grid.frame().bounds().min()) + " to " +
                                 formatPoint(grid.frame().bounds().max()));
    if (const auto violation = environment.stateViolation(*options.home_m))
      throw ceilplan::InputError("the given home " + formatPoint(*options.home_m) +
                                 " is no valid position: " + violation->describe());
    if (environment.assumesFree(*options.home_m))
      throw ceilplan::InputError("the given home " + formatPoint(*options.home_m) +
                                 " overlaps unknown space: take off where the scan saw free space");
  }
  const Eigen::AlignedBox3d box_m = options.crop_m ? *options.crop_m : grid.frame().bounds();
  MissionProposal proposal;
  const environment::VehicleGeometry& vehicle = environment.vehicle();
  proposal.min_room_below_m = options.standoff_m + vehicle.inflatedTop_m() - vehicle.inflatedBottom_m();
  const std::vector<HomeCandidate> homes = homeCandidates(environment, options, progress);
  proposal.ground_m = groundOf(homes);
  std::vector<environment::SurfaceElement> elements;
  if (progress) progress("finding overhead surfaces", 0.0);
  std::vector<ProposedRegion> regions = overheadRegions(environment, box_m, proposal, elements);
  if (progress) progress("finding overhead surfaces", 1.0);
  const std::string where = options.crop_m
                                ? " inside the crop " + formatPoint(box_m.min()) + " to " + formatPoint(box_m.max())
                                : std::string(" in the map");
  if (elements.empty())
    throw ceilplan::InputError("no down-facing surface with known free space below it" + where +
                               ": a scan without sensor origins may have no known free space (" + docPage("import.md") +
                               ")");
  if (regions.empty())
    throw ceilplan::InputError("no down-facing surface" + where + " has " + formatNumber(proposal.min_room_below_m, 3) +
                               " m of free space below it, the vehicle's height with its margins and a standoff of " +
                               formatNumber(options.standoff_m, 3) + " m: the camera cannot photograph any from below");
  for (ProposedRegion& region : regions) {
    if (region.area_m2 >= options.min_region_area_m2 &&
        proposal.regions.size() < static_cast<std::size_t>(options.max_regions)) {
      region.name = "overhead_" + std::to_string(proposal.regions.size() + 1);
      proposal.regions.push_back(region);
    } else {
      ++proposal.dropped_regions;
      proposal.dropped_area_m2 += region.area_m2;
    }
  }
  for (ProposedRegion& region : proposal.regions)
    for (const environment::SurfaceElement& element : elements)
      if (region.box_m.contains(element.centre_m)) region.box_area_m2 += element.area_m2;
  if (proposal.regions.empty())
    throw ceilplan::InputError("no overhead region of at least " + formatNumber(options.min_region_area_m2) + " m2" +
                               where + " (the largest has " + formatNumber(regions.front().area_m2, 3) +
                               " m2): lower the least region area");

  if (options.home_m) {
    proposal.home_m = *options.home_m;
    proposal.home_given = true;
    proposal.home_height_m = heightAboveFloor(grid, *options.home_m);
    return proposal;
  }
  Eigen::Vector2d centroid_m = Eigen::Vector2d::Zero();
  double area_m2 = 0.0;
  for (const ProposedRegion& region : proposal.regions) {
    centroid_m += region.area_m2 * region.box_m.center().head<2>();
    area_m2 += region.area_m2;
  }
  centroid_m /= area_m2;
  const std::optional<HomeCandidate> home = proposeHome(homes, proposal.ground_m, centroid_m);
  if (!home)
    throw ceilplan::InputError("no valid home in known free space " + formatNumber(options.min_home_height_m) + " to " +
                               formatNumber(options.max_home_height_m) + " m above a floor" + where +
                               ": give one (--home X,Y,Z)");
  proposal.home_m = home->body_m;
  proposal.home_height_m = home->height_m;
  return proposal;
}

}  // namespace ceilplan::mission
