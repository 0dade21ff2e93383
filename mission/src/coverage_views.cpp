#include "ceilplan/mission/coverage_views.hpp"

#include "ceilplan/core/parallel_for.hpp"
#include "ceilplan/environment/visibility.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <functional>
#include <future>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>

namespace ceilplan::mission {
namespace {

constexpr double kDegree = M_PI / 180.0;
constexpr double kIndexCell_m = 0.5;          // cell of the element index
constexpr int kRepairLevels = 5;              // distances per repair probe
constexpr int kRepairDirections = 8;          // tilt directions per tilt angle
constexpr int kRepairViewsPerElement = 4;     // probes kept per element the lattice missed
constexpr double kOpenShare = 0.95;           // a straight view seeing this share of its covered part is in the open
constexpr double kPatternLevelShare = 0.5;    // patterns at distance levels this share of the farthest and beyond
constexpr double kObstacleSlackShare = 0.25;  // a lane may stop this share of a covered part short of an obstacle

// Free mode: where no pose covering an element keeps the standoff, the poses kept are those
// within this of the largest clearance among them: 0.1 m, or a quarter of that clearance where
// it is larger. Without the share, a survey station 0.74 m from an abutment lost to oblique
// photos 0.93 m from it, which cover a third as much (three more photos a bay).
double clearanceTolerance_m(double largest_clearance_m) { return std::max(0.1, 0.25 * largest_clearance_m); }

// Elements bucketed on a uniform grid, for "which elements lie in this box".
class ElementIndex {
 public:
  explicit ElementIndex(const RegionSurface& surface) {
    Eigen::AlignedBox3d bounds;
    for (const auto& element : surface.elements) bounds.extend(element.centre_m);
    origin_ = bounds.min();
    for (int axis = 0; axis < 3; ++axis)
      size_[axis] = 1 + static_cast<int>(std::floor((bounds.max()[axis] - origin_[axis]) / kIndexCell_m));
    std::vector<std::uint32_t> cell_of(surface.elements.size());
    offsets_.assign(static_cast<std::size_t>(size_[0]) * size_[1] * size_[2] + 1, 0);
    for (std::size_t e = 0; e < surface.elements.size(); ++e) {
      const Eigen::Vector3d& c = surface.elements[e].centre_m;
      cell_of[e] = static_cast<std::uint32_t>(linear(cellOf(0, c.x()), cellOf(1, c.y()), cellOf(2, c.z())));
      ++offsets_[cell_of[e] + 1];
    }
    for (std::size_t cell = 1; cell < offsets_.size(); ++cell) offsets_[cell] += offsets_[cell - 1];
    members_.resize(surface.elements.size());
    std::vector<std::uint32_t> next(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t e = 0; e < surface.elements.size(); ++e)
      members_[next[cell_of[e]]++] = static_cast<std::uint32_t>(e);
  }

  // Calls visit(element) for every element in the cells the box touches (a superset of the box).
  template <typename Visit>
  void forEachNear(const Eigen::AlignedBox3d& box, Visit&& visit) const {
    int lo[3], hi[3];
    for (int axis = 0; axis < 3; ++axis) {
      lo[axis] = std::max(0, cellOf(axis, box.min()[axis]));
      hi[axis] = std::min(size_[axis] - 1, cellOf(axis, box.max()[axis]));
      if (lo[axis] > hi[axis]) return;
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) {
          const std::size_t cell = linear(i, j, k);
          for (std::uint32_t m = offsets_[cell]; m < offsets_[cell + 1]; ++m) visit(members_[m]);
        }
  }

 private:
  int cellOf(int axis, double coordinate_m) const {
    const double cell = std::floor((coordinate_m - origin_[axis]) / kIndexCell_m);
    return static_cast<int>(std::clamp(cell, -1.0, static_cast<double>(size_[axis])));
  }
  std::size_t linear(int i, int j, int k) const { return (static_cast<std::size_t>(k) * size_[1] + j) * size_[0] + i; }

  Eigen::Vector3d origin_;
  int size_[3];
  std::vector<std::uint32_t> offsets_;
  std::vector<std::uint32_t> members_;
};

// The coverage rule of the header, for one region.
class RegionViewer {
 public:
  // `blocks` (of `grid`), where given, speed the lines of sight up without changing them.
  RegionViewer(const environment::VoxelGrid& grid, const Camera& camera, const CoverageRegion& region,
               const RegionSurface& surface, const environment::FreeBlocks* blocks = nullptr)
      : grid_(grid),
        blocks_(blocks),
        camera_(camera),
        region_(region),
        surface_(surface),
        index_(surface),
        reach_m_(camera.distanceForGsd_m(region.gsd_mm_px)),
        width_tan_(camera.halfWidthTan() * region.widthShare()),
        height_tan_(camera.halfHeightTan() * region.heightShare()),
        cos_max_incidence_(std::cos(region.max_incidence_deg * kDegree)),
        gsd_per_m_(camera.gsd_mm_px(1.0)) {}

  void covered(const CameraPose& pose, std::vector<SeenElement>& out) const {
    out.clear();
    const CameraFrame frame(camera_, pose);
    // Elements meeting the GSD lie within reach_m_, so at depth <= reach_m_: inside the
    // pyramid of the covered part of the image truncated there, whose box is the box of its apex
    // and four far corners.
    Eigen::AlignedBox3d box(frame.position_m());
    for (const double sr : {-1.0, 1.0})
      for (const double su : {-1.0, 1.0})
        box.extend(frame.position_m() +
                   reach_m_ * (frame.forward() + sr * width_tan_ * frame.right() + su * height_tan_ * frame.up()));
    index_.forEachNear(box, [&](std::uint32_t e) {
      SeenElement seen;
      if (test(frame, e, seen)) out.push_back(seen);
    });
    std::sort(out.begin(), out.end(), [](const SeenElement& a, const SeenElement& b) { return a.element < b.element; });
  }

  // Area of the covered part of an image on a flat surface seen straight on from `distance_m`.
  double openArea_m2(double distance_m) const { return 4.0 * distance_m * distance_m * width_tan_ * height_tan_; }

  bool covers(const CameraPose& pose, std::uint32_t element) const {
    SeenElement seen;
    return test(CameraFrame(camera_, pose), element, seen);
  }

 private:
  bool test(const CameraFrame& frame, std::uint32_t e, SeenElement& seen) const {
    const environment::SurfaceElement& element = surface_.elements[e];
    const auto image = frame.project(element.centre_m);
    if (!image || std::abs(image->right_tan) > width_tan_ || std::abs(image->up_tan) > height_tan_ ||
        image->depth_m < camera_.min_focus_m)
      return false;
    const Eigen::Vector3d sight = element.centre_m - frame.position_m();
    const double distance_m = sight.norm();
    const double cos_incidence = -sight.dot(element.normal) / distance_m;
    if (!(cos_incidence >= cos_max_incidence_)) return false;
    // gsd_mm_px(distance, incidence) without the arc cosine: distance x gsd per metre / cos.
    const double gsd = gsd_per_m_ * distance_m / cos_incidence;
    if (gsd > region_.gsd_mm_px) return false;
    // End the sight line just in front of the face, in the free voxel it looks onto.
    const Eigen::Vector3d end = element.centre_m + element.faceNormal() * (0.01 * grid_.frame().resolution_m());
    if (!(blocks_ ? environment::lineOfSight(grid_, *blocks_, frame.position_m(), end)
                  : environment::lineOfSight(grid_, frame.position_m(), end)))
      return false;
    seen = {e, static_cast<float>(gsd), static_cast<float>(std::acos(std::min(1.0, cos_incidence)) / kDegree),
            static_cast<float>(distance_m)};
    return true;
  }

  const environment::VoxelGrid& grid_;
  const environment::FreeBlocks* blocks_;
  const Camera& camera_;
  const CoverageRegion& region_;
  const RegionSurface& surface_;
  ElementIndex index_;
  double reach_m_;
  double width_tan_;
  double height_tan_;
  double cos_max_incidence_;
  double gsd_per_m_;  // GSD at 1 m, straight on
};

// Two unit tangents of the plane square to `normal`, the first along `heading` where it can be.
std::pair<Eigen::Vector3d, Eigen::Vector3d> tangents(const Eigen::Vector3d& normal, const Eigen::Vector3d& heading) {
  const Eigen::Vector3d along = std::abs(normal.dot(heading)) < 0.9 ? heading : Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d t1 = (along - along.dot(normal) * normal).normalized();
  return {t1, normal.cross(t1)};
}

// A straight view of an element from a distance, at a yaw: whether its pose is admissible (a
// pattern's station may stand there), and whether its camera sees the element.
struct StraightView {
  bool stands = false;
  bool sees = false;
};

struct Pose {
  CameraPose pose;
  double clearance_m = 0.0;  // free mode only
  bool raised = false;       // ceiling mode: raised under the structure above
};

// What a pose covers, as a candidate keeps it: the elements' indices and their summary.
struct Cover {
  std::vector<ElementRun> runs;
  CoverSummary summary;

  // Its element indices, ascending, one at a time.
  ElementIterator begin() const { return {runs.data(), 0}; }
  ElementIterator end() const { return {runs.data() + runs.size(), 0}; }
};

// Appends element `e`, above every element of `runs`, to them.
void appendElement(std::vector<ElementRun>& runs, std::uint32_t e) {
  if (!runs.empty() && runs.back().first + runs.back().count == e)
    ++runs.back().count;
  else
    runs.push_back({e, 1});
}

Cover compactCover(const std::vector<SeenElement>& seen, const RegionSurface& surface) {
  Cover cover;
  for (const SeenElement& s : seen) appendElement(cover.runs, s.element);
  cover.runs.shrink_to_fit();
  cover.summary = summariseCover(seen, surface);
  return cover;
}

}  // namespace

// The covers of poses some mode has asked for and not every mode yet, by region and pose.
struct SharedCovers::State {
  struct Key {
    std::string region;
    std::array<double, 5> pose;  // body position, yaw, gimbal pitch

    bool operator==(const Key& other) const { return pose == other.pose && region == other.region; }
  };
  struct KeyHash {
    std::size_t operator()(const Key& key) const {
      std::size_t hash = std::hash<std::string>()(key.region);
      for (const double value : key.pose) hash = hash * 1000003u ^ std::hash<double>()(value);
      return hash;
    }
  };
  struct Entry {
    std::shared_future<std::shared_ptr<const Cover>> cover;
    unsigned asked = 0;  // a bit per mode
  };

  // `pose`'s cover in `region`, found by `find` unless some mode has asked for it first.
  Cover coverOf(FlightMode mode, const std::string& region, const CameraPose& pose,
                const std::function<Cover()>& find) {
    Key key{region, {pose.body_m.x(), pose.body_m.y(), pose.body_m.z(), pose.yaw_deg, pose.gimbal_pitch_deg}};
    std::promise<std::shared_ptr<const Cover>> promise;
    std::shared_future<std::shared_ptr<const Cover>> cover;
    bool finds = false;
    {
      const std::lock_guard<std::mutex> lock(mutex);
      auto [entry, added] = entries.try_emplace(std::move(key));
      if (added) {
        entry->second.cover = promise.get_future().share();
        finds = true;
      }
      cover = entry->second.cover;
      handed += finds ? 0 : 1;
      entry->second.asked |= bit(mode);
      if (entry->second.asked == all) entries.erase(entry);  // the future held here keeps the cover
    }
    if (finds) {
      try {
        promise.set_value(std::make_shared<const Cover>(find()));
      } catch (...) {
        promise.set_exception(std::current_exception());
        throw;
      }
    }
    return *cover.get();
  }

  // `mode` has generated every candidate of `region`: once every mode has, its covers go.
  void finished(FlightMode mode, const std::string& region) {
    const std::lock_guard<std::mutex> lock(mutex);
    if ((finished_modes[region] |= bit(mode)) != all) return;
    for (auto entry = entries.begin(); entry != entries.end();)
      entry = entry->first.region == region ? entries.erase(entry) : std::next(entry);
  }

  static unsigned bit(FlightMode mode) { return 1u << static_cast<unsigned>(mode); }

  unsigned all = 0;
  std::size_t handed = 0;
  mutable std::mutex mutex;
  std::unordered_map<Key, Entry, KeyHash> entries;
  std::map<std::string, unsigned> finished_modes;
};

SharedCovers::SharedCovers(const std::vector<FlightMode>& modes) : state_(std::make_unique<State>()) {
  for (const FlightMode mode : modes) state_->all |= State::bit(mode);
}

SharedCovers::~SharedCovers() = default;

std::size_t SharedCovers::handed() const {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->handed;
}

std::size_t SharedCovers::size() const {
  const std::lock_guard<std::mutex> lock(state_->mutex);
  return state_->entries.size();
}

namespace {

// Camera poses looking at an element, checked against the vehicle and the map.
class PoseMaker {
 public:
  PoseMaker(const environment::Environment& environment, const Camera& camera, const CoverageRegion& region,
            const ViewGenerationOptions& options, double level_yaw_deg)
      : environment_(environment),
        camera_(camera),
        region_(region),
        options_(options),
        level_yaw_deg_(level_yaw_deg),
        required_clearance_m_(environment.vehicle().collision_radius_m + options.free_standoff_m) {}

  const Eigen::Vector3d& heading() const { return heading_; }
  bool free() const { return options_.mode == FlightMode::Free; }
  double requiredClearance_m() const { return required_clearance_m_; }

  double levelYaw_deg() const { return level_yaw_deg_; }

  // The camera at `camera_m` looking at `target_m` (yawed to `level_yaw_deg` when it looks
  // straight up or down): the pose if the gimbal can point there and the body is admissible.
  std::optional<Pose> looking(const Eigen::Vector3d& camera_m, const Eigen::Vector3d& target_m, double level_yaw_deg,
                              std::size_t& tried) const {
    const auto [yaw, pitch] = yawPitchOf(target_m - camera_m, level_yaw_deg);
    if (!camera_.pitchReachable(pitch)) return std::nullopt;
    const Eigen::Vector3d body_m = camera_m - cameraPosition(camera_, Eigen::Vector3d::Zero(), yaw);
    ++tried;
    if (!admissible(body_m)) return std::nullopt;
    return Pose{{body_m, yaw, std::clamp(pitch, camera_.gimbal_pitch_min_deg, camera_.gimbal_pitch_max_deg)},
                free() ? environment_.clearance_m(body_m) : 0.0};
  }

  // Ceiling mode: `pose` raised until the airframe meets the structure above (or 3 m), the
  // camera re-aimed at `aim_m` on the surface of normal `normal`; none unless it rose and still
  // sees the aim within focus, GSD, incidence and gimbal limits.
  std::optional<Pose> raised(const Pose& pose, const Eigen::Vector3d& aim_m, const Eigen::Vector3d& normal,
                             double level_yaw_deg, std::size_t& tried) const {
    const Eigen::Vector3d low = pose.pose.body_m;
    const double resolution_m = environment_.grid().frame().resolution_m();
    const environment::GridFrame& frame = environment_.grid().frame();
    const auto above = environment_.columns().above(frame.indexOf(0, low.x()), frame.indexOf(1, low.y()), low.z());
    double top_m = std::min(low.z() + 3.0, above.face_m - environment_.vehicle().inflatedTop_m());
    if (top_m < low.z() + 0.5 * resolution_m) return std::nullopt;
    const auto at = [&](double z) { return Eigen::Vector3d(low.x(), low.y(), z); };
    ++tried;
    if (!admissible(at(top_m))) {
      double good = low.z(), bad = top_m;
      for (int step = 0; step < 20; ++step) {
        const double middle = 0.5 * (good + bad);
        ++tried;
        (admissible(at(middle)) ? good : bad) = middle;
      }
      top_m = good;
    }
    if (top_m < low.z() + 0.5 * resolution_m) return std::nullopt;
    // Re-aim; a horizontal mount offset moves the camera with the yaw, so settle it twice.
    double yaw = pose.pose.yaw_deg, pitch = pose.pose.gimbal_pitch_deg;
    for (int round = 0; round < 2; ++round)
      std::tie(yaw, pitch) = yawPitchOf(aim_m - cameraPosition(camera_, at(top_m), yaw), level_yaw_deg);
    const Eigen::Vector3d sight = aim_m - cameraPosition(camera_, at(top_m), yaw);
    const double distance_m = sight.norm();
    const double cos_incidence = -sight.dot(normal) / distance_m;
    if (!camera_.pitchReachable(pitch) || distance_m < camera_.min_focus_m ||
        cos_incidence < std::cos(region_.max_incidence_deg * kDegree) ||
        camera_.gsd_mm_px(distance_m, std::acos(std::min(1.0, cos_incidence))) > region_.gsd_mm_px)
      return std::nullopt;
    return Pose{
        {at(top_m), yaw, std::clamp(pitch, camera_.gimbal_pitch_min_deg, camera_.gimbal_pitch_max_deg)}, 0.0, true};
  }

  // Poses looking at `aim_m` on the surface of `element` from `distance_m` along its normal,
  // tilted by `tilt_rad` towards each of `directions` tangent directions (one straight view when
  // the tilt is 0), raised too in ceiling mode; a straight view takes `level_yaw_deg`.
  void around(const environment::SurfaceElement& element, const Eigen::Vector3d& aim_m, double distance_m,
              double tilt_rad, int directions, double level_yaw_deg, std::vector<Pose>& out, std::size_t& tried) const {
    const auto [t1, t2] = tangents(element.normal, heading_);
    const int count = tilt_rad == 0.0 ? 1 : directions;
    // At a tilt, the aim seen at the image centre meets the GSD nearer.
    const double reach_m = camera_.distanceForGsd_m(region_.gsd_mm_px, tilt_rad);
    const double d = std::min(distance_m, reach_m);
    if (d < camera_.min_focus_m) return;
    for (int k = 0; k < count; ++k) {
      const double phi = 2.0 * M_PI * k / count;
      const Eigen::Vector3d direction =
          element.normal * std::cos(tilt_rad) + (t1 * std::cos(phi) + t2 * std::sin(phi)) * std::sin(tilt_rad);
      const auto pose = looking(aim_m + d * direction, aim_m, level_yaw_deg, tried);
      if (!pose) continue;
      if (seesAim(*pose, aim_m) && reachable(*pose)) out.push_back(*pose);
      if (!free())
        if (const auto up = raised(*pose, aim_m, element.normal, level_yaw_deg, tried);
            up && seesAim(*up, aim_m) && reachable(*up))
          out.push_back(*up);
    }
  }

  // The straight view of `element` from `distance_m`: whether its pose is admissible (in free mode
  // only where it keeps the standoff), and whether its camera sees the element.
  StraightView straight(const environment::SurfaceElement& element, double distance_m, double level_yaw_deg) const {
    std::size_t tried = 0;
    const Eigen::Vector3d camera_m = element.centre_m + distance_m * element.normal;
    const auto pose = looking(camera_m, element.centre_m, level_yaw_deg, tried);
    const Eigen::Vector3d end =
        element.centre_m + element.faceNormal() * (0.01 * environment_.grid().frame().resolution_m());
    return {pose && (!free() || pose->clearance_m >= required_clearance_m_),
            environment::lineOfSight(environment_.grid(), blocks(), camera_m, end)};
  }

  void setHeading(double yaw_deg) {
    heading_ = Eigen::Vector3d(std::sin(yaw_deg * kDegree), std::cos(yaw_deg * kDegree), 0.0);
  }

 private:
  // Whether the optical axis meets the surface at its aim (an occupied voxel behind it) through
  // known free space: the centre of the image shows what the map vouches for, not what lies
  // behind unknown voxels or a gap in the surface (visibility.hpp). Checked along the axis and
  // along four parallels kSightTube_m from it, so that an axis grazing a voxel's edge, or an aim
  // on the edge of a face, does not pass only at full precision: photos.csv rounds positions to
  // 1 mm and angles to 0.01 degrees, which moves an axis by at most about 1.2 mm at its aim, and
  // parallels 3 mm out vouch for every axis within 2.1 mm. A wider tube refuses good views on
  // curved surfaces (1 cm: 24 % more photos on the tunnel's crown).
  bool seesAim(const Pose& pose, const Eigen::Vector3d& aim_m) const {
    constexpr double kSightTube_m = 0.003;
    const environment::VoxelGrid& grid = environment_.grid();
    const environment::GridFrame& frame = grid.frame();
    const Eigen::Vector3d camera_m = cameraPosition(camera_, pose.pose.body_m, pose.pose.yaw_deg);
    const Eigen::Vector3d axis = (aim_m - camera_m).normalized();
    // A quarter voxel along the axis: in front of the aim's face, and into the voxel behind it.
    const Eigen::Vector3d step = 0.25 * frame.resolution_m() * axis;
    const Eigen::Vector3d across = axis.unitOrthogonal();
    const Eigen::Vector3d other = axis.cross(across);
    const Eigen::Vector3d offsets[] = {Eigen::Vector3d::Zero(), kSightTube_m * across, -kSightTube_m * across,
                                       kSightTube_m * other, -kSightTube_m * other};
    for (const Eigen::Vector3d& offset : offsets) {
      const Eigen::Vector3d behind = aim_m + offset + step;
      if (grid.at(frame.indexOf(0, behind.x()), frame.indexOf(1, behind.y()), frame.indexOf(2, behind.z())) !=
              environment::CellState::Occupied ||
          !environment::lineOfSight(grid, blocks(), camera_m + offset, aim_m + offset - step))
        return false;
    }
    return true;
  }

  const environment::FreeBlocks& blocks() const { return environment_.index()->freeBlocks(); }

  // Asked of finished poses only: the test costs motion checks.
  bool reachable(const Pose& pose) const { return !options_.reachable || options_.reachable(pose.pose.body_m); }

  bool admissible(const Eigen::Vector3d& body_m) const {
    return environment_.contains(body_m) && environment_.isStateValid(body_m) &&
           environment_.ceilingGapAtLeast(body_m, options_.min_ceiling_gap_m);
  }

  const environment::Environment& environment_;
  const Camera& camera_;
  const CoverageRegion& region_;
  const ViewGenerationOptions& options_;
  double level_yaw_deg_;
  double required_clearance_m_;
  Eigen::Vector3d heading_ = Eigen::Vector3d::UnitY();
};

// One seed of the lattice: an element viewed from one distance.
struct Seed {
  std::uint32_t element;
  double distance_m;
  Eigen::Vector3d aim_m;  // on the element's face plane
  double level_yaw_deg;   // a straight up or down view's yaw
  int tiling = -1;        // the pattern tiling it belongs to, if any
  bool across = false;    // a pattern across the region's heading: its views are for the tilings only
  double tilt_rad = 0.0;  // an oblique row's seed: only its views tilted by this much
};

// A pattern tiling's flat patch, as seeds are generated (Tiling::patch).
using TilingPatches = std::vector<std::uint32_t>;

// How far the flat patch of an element's face extends from its centre along `direction` (unit,
// in the face's plane), up to `limit_m`: faces of the same orientation, in the same plane,
// exposed and inside the region, one voxel after the other.
double flatExtent(const environment::VoxelGrid& grid, const RegionShape& shape,
                  const environment::SurfaceElement& element, const Eigen::Vector3d& direction, double limit_m) {
  const environment::GridFrame& frame = grid.frame();
  const double r = frame.resolution_m();
  const Eigen::Vector3d n = element.faceNormal();
  for (double s = r; s <= limit_m + 0.5 * r; s += r) {
    const Eigen::Vector3d face = element.centre_m + direction * s;
    const Eigen::Vector3d behind = face - 0.5 * r * n, front = face + 0.5 * r * n;
    if (!shape.contains(face) ||
        grid.at(frame.indexOf(0, behind.x()), frame.indexOf(1, behind.y()), frame.indexOf(2, behind.z())) !=
            environment::CellState::Occupied ||
        grid.at(frame.indexOf(0, front.x()), frame.indexOf(1, front.y()), frame.indexOf(2, front.z())) !=
            environment::CellState::Free)
      return std::min(limit_m, s - 0.5 * r);
  }
  return limit_m;
}

// The shift along `direction` that keeps a covered span of half-width `half_m` centred on the
// element inside its flat patch: none in the open, inwards at an edge, centred on a strip
// narrower than the span.
double snapShift(double ahead_m, double behind_m, double half_m) {
  if (ahead_m + behind_m <= 2.0 * half_m) return 0.5 * (ahead_m - behind_m);
  if (ahead_m < half_m) return ahead_m - half_m;
  if (behind_m < half_m) return half_m - behind_m;
  return 0.0;
}

// The axes of a straight view of each face direction (0 +x, 1 -x, ..., 5 -z), yawed along the
// region's heading when vertical.
std::vector<CameraFrame> straightFrames(const Camera& camera, double heading_deg) {
  std::vector<CameraFrame> frames;
  for (int face = 0; face < 6; ++face) {
    const auto [yaw, pitch] = yawPitchOf(-environment::faceAxisNormal(face), heading_deg);
    frames.emplace_back(camera, CameraPose{-cameraPosition(camera, Eigen::Vector3d::Zero(), yaw), yaw, pitch});
  }
  return frames;
}

// The flat patches of a surface: elements with their face's own normal, joined to the
// neighbouring faces of the same orientation in the same plane (4-connected). Elements of
// inclined surfaces (a smoothed normal) belong to no patch.
std::vector<std::vector<std::uint32_t>> flatPatches(const environment::VoxelGrid& grid, const RegionSurface& surface) {
  const environment::GridFrame& frame = grid.frame();
  const auto key = [&](const environment::Index3& voxel, int face) {
    return static_cast<std::uint64_t>(frame.linear(voxel[0], voxel[1], voxel[2])) * 6 + face;
  };
  std::unordered_map<std::uint64_t, std::uint32_t> index;
  for (std::uint32_t e = 0; e < surface.elements.size(); ++e) {
    const auto& element = surface.elements[e];
    if (element.normal.isApprox(element.faceNormal())) index.emplace(key(element.voxel, element.face), e);
  }
  std::vector<std::uint8_t> done(surface.elements.size(), 0);
  std::vector<std::vector<std::uint32_t>> patches;
  for (std::uint32_t start = 0; start < surface.elements.size(); ++start) {
    if (done[start] || !index.count(key(surface.elements[start].voxel, surface.elements[start].face))) continue;
    std::vector<std::uint32_t> patch{start};
    done[start] = 1;
    for (std::size_t next = 0; next < patch.size(); ++next) {
      const auto& element = surface.elements[patch[next]];
      const int normal_axis = element.face / 2;
      for (int axis = 0; axis < 3; ++axis) {
        if (axis == normal_axis) continue;
        for (const int step : {-1, 1}) {
          environment::Index3 voxel = element.voxel;
          voxel[axis] += step;
          if (!frame.inside(voxel[0], voxel[1], voxel[2])) continue;
          const auto found = index.find(key(voxel, element.face));
          if (found == index.end() || done[found->second]) continue;
          done[found->second] = 1;
          patch.push_back(found->second);
        }
      }
    }
    std::sort(patch.begin(), patch.end());
    patches.push_back(std::move(patch));
  }
  return patches;
}

using StraightTest = std::function<StraightView(std::uint32_t element, double distance_m, double level_yaw_deg)>;

// The parts of a patch (element lists) that straight views at one distance and yaw can tile. An
// element is tileable when its own straight view's camera sees it and a station may stand within
// half the covered part of it (`half_cells`, in cells, in the image axes: `cells_of` gives each
// element's cell). The 4-connected groups of tileable elements, at least a quarter of a covered
// part each, where there are two or more: an obstacle under part of a patch (a pier cap under a
// deck bay) splits it, and each part is tiled on its own, anchored to the obstacle's edges as to
// the patch's; what lies over the obstacle is left to tilted views. Else the whole patch, as an
// unobstructed one: an obstacle at its edge (an abutment's or a wall's face) does not split it.
std::vector<std::vector<std::uint32_t>> openParts(const std::vector<std::uint32_t>& patch,
                                                  const std::vector<std::pair<long, long>>& cells_of,
                                                  const std::vector<StraightView>& views,
                                                  const std::pair<long, long>& half_cells) {
  long i0 = LONG_MAX, j0 = LONG_MAX, i1 = LONG_MIN, j1 = LONG_MIN;
  for (const auto& [i, j] : cells_of) {
    i0 = std::min(i0, i);
    j0 = std::min(j0, j);
    i1 = std::max(i1, i);
    j1 = std::max(j1, j);
  }
  // Stations per cell, summed (a summed-area table with a zero first row and column).
  const long width = i1 - i0 + 2, height = j1 - j0 + 2;
  std::vector<int> sums(static_cast<std::size_t>(width * height), 0);
  const auto sum = [&](long i, long j) -> int& { return sums[static_cast<std::size_t>(j * width + i)]; };
  for (std::size_t k = 0; k < patch.size(); ++k)
    if (views[k].stands) sum(cells_of[k].first - i0 + 1, cells_of[k].second - j0 + 1) += 1;
  for (long j = 1; j < height; ++j)
    for (long i = 1; i < width; ++i) sum(i, j) += sum(i - 1, j) + sum(i, j - 1) - sum(i - 1, j - 1);
  const auto stationsIn = [&](long ia, long ja, long ib, long jb) {  // cells [ia, ib] x [ja, jb], clipped
    ia = std::max(ia - i0, 0L);
    ja = std::max(ja - j0, 0L);
    ib = std::min(ib - i0 + 1, width - 1);
    jb = std::min(jb - j0 + 1, height - 1);
    if (ia >= ib || ja >= jb) return 0;
    return sum(ib, jb) - sum(ia, jb) - sum(ib, ja) + sum(ia, ja);
  };
  std::vector<std::uint8_t> open(patch.size(), 0);
  for (std::size_t k = 0; k < patch.size(); ++k) {
    const auto [i, j] = cells_of[k];
    open[k] = views[k].sees &&
              stationsIn(i - half_cells.first, j - half_cells.second, i + half_cells.first, j + half_cells.second) > 0;
  }
  if (std::all_of(open.begin(), open.end(), [](std::uint8_t o) { return o != 0; })) return {patch};
  // Parts smaller than a quarter of a covered part are no parts.
  const std::size_t min_elements = static_cast<std::size_t>(half_cells.first * half_cells.second);
  std::map<std::pair<long, long>, std::size_t> at;  // cell -> index into patch, tileable elements only
  for (std::size_t k = 0; k < patch.size(); ++k)
    if (open[k]) at.emplace(cells_of[k], k);
  std::vector<std::uint8_t> done(patch.size(), 0);
  std::vector<std::vector<std::uint32_t>> parts;
  for (std::size_t start = 0; start < patch.size(); ++start) {
    if (!open[start] || done[start]) continue;
    std::vector<std::size_t> queue{start};
    done[start] = 1;
    for (std::size_t next = 0; next < queue.size(); ++next) {
      const auto [i, j] = cells_of[queue[next]];
      for (const auto& [di, dj] : {std::pair<long, long>{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const auto found = at.find({i + di, j + dj});
        if (found == at.end() || done[found->second]) continue;
        done[found->second] = 1;
        queue.push_back(found->second);
      }
    }
    if (queue.size() < min_elements) continue;  // a sliver: left to the oblique rows and the lattice
    std::vector<std::uint32_t> part;
    part.reserve(queue.size());
    for (const std::size_t k : queue) part.push_back(patch[k]);
    std::sort(part.begin(), part.end());
    parts.push_back(std::move(part));
  }
  // An obstacle at a patch's edge (a wall the stations keep off) does not split it.
  if (parts.size() < 2) return {patch};
  return parts;
}

// Free mode: a pattern's station whose straight view does not keep the standoff (beside a pier
// cap or an abutment) moves back along the image axes on which it ends its part's rows, a voxel at
// a time and at most `limits_m` (per axis; 0 where it is no end station), to the first place
// where it does, aimed at the part's element nearest there; none if no such place. Its covered
// part then falls short of the obstacle by as much, which the oblique rows and the lattice cover,
// instead of the station being dropped and its row's end left to smaller photos.
template <typename NearestTo, typename Stands>
std::optional<std::pair<Eigen::Vector2d, std::uint32_t>> stationThatStands(const Eigen::Vector2d& at,
                                                                           const Eigen::Vector2d& back,
                                                                           const Eigen::Vector2d& limits_m,
                                                                           double step_m, const NearestTo& nearest_to,
                                                                           const Stands& stands) {
  for (int axis = 0; axis < 2; ++axis)
    for (double moved_m = step_m; moved_m <= limits_m[axis] + 1e-9; moved_m += step_m) {
      Eigen::Vector2d moved = at;
      moved[axis] += moved_m * back[axis];
      const std::uint32_t element = nearest_to(moved);
      if (stands(element)) return std::make_pair(moved, element);
    }
  return std::nullopt;
}

// The pattern: per flat patch, distance level (those at least half the farthest) and image orientation, a lawnmower
// tiling of the patch's extent in the straight view's image axes, lanes and stations evenly spaced with the first and
// last covering parts ending at the patch's edges, as a survey tool lays out passes. Each station aims at its point on
// the patch's plane; stations over no element of the patch are dropped. Up and down faces are tiled both with the
// image's height along the region's heading and across it: which one needs fewer stations depends on how the patch's
// sides divide by the covered part's (a 3.8 x 2.4 m deck bay takes 5 x 2 photos one way and 3 x 3 the other at
// 1 mm/px). Where an obstacle keeps straight views from part of the patch, each part they can see is tiled on its
// own (openParts). Each tiling is numbered; `tiling_patch` receives its patch.
std::vector<Seed> patternSeeds(const environment::VoxelGrid& grid, const Camera& camera, const CoverageRegion& region,
                               const RegionSurface& surface, const std::vector<double>& levels, double heading_deg,
                               const StraightTest& sees_straight, bool standoff_stations, int workers,
                               TilingPatches& tiling_patch, std::vector<std::uint32_t>& hidden) {
  const double r = grid.frame().resolution_m();
  const double yaws_deg[2] = {heading_deg, std::fmod(heading_deg + 90.0, 360.0)};
  const std::vector<CameraFrame> frames[2] = {straightFrames(camera, yaws_deg[0]), straightFrames(camera, yaws_deg[1])};
  std::vector<Seed> seeds;
  const std::vector<std::vector<std::uint32_t>> patches = flatPatches(grid, surface);
  for (std::uint32_t p = 0; p < patches.size(); ++p) {
    const std::vector<std::uint32_t>& patch = patches[p];
    const auto& first = surface.elements[patch.front()];
    const bool vertical = first.face >= 4;  // faces 4 and 5 are +z and -z
    // A vertical straight view's camera and body do not move with its yaw unless the mount offset
    // is horizontal: the second orientation's views are then the first's, and are not tested again.
    const bool yaw_free = vertical && camera.mount_offset_m.x() == 0.0 && camera.mount_offset_m.y() == 0.0;
    std::vector<std::vector<StraightView>> level_views(levels.size());
    for (int orientation = 0; orientation < (vertical ? 2 : 1); ++orientation) {
      const CameraFrame& straight = frames[orientation][first.face];
      const auto imageAxes = [&](std::uint32_t e) {
        return Eigen::Vector2d(surface.elements[e].centre_m.dot(straight.right()),
                               surface.elements[e].centre_m.dot(straight.up()));
      };
      // The patch's faces in image-axis voxel units (face centres lie mid-voxel: floor is exact).
      std::vector<std::pair<long, long>> cells_of;
      cells_of.reserve(patch.size());
      for (const std::uint32_t e : patch) {
        const Eigen::Vector2d at = imageAxes(e);
        cells_of.emplace_back(static_cast<long>(std::floor(at.x() / r)), static_cast<long>(std::floor(at.y() / r)));
      }
      Eigen::Vector2d patch_lo = Eigen::Vector2d::Constant(INFINITY), patch_hi = -patch_lo;
      for (const std::uint32_t e : patch) {
        patch_lo = patch_lo.cwiseMin(imageAxes(e));
        patch_hi = patch_hi.cwiseMax(imageAxes(e));
      }
      patch_lo -= Eigen::Vector2d::Constant(0.5 * r);
      patch_hi += Eigen::Vector2d::Constant(0.5 * r);
      const double plane = first.centre_m.dot(straight.forward());
      for (std::size_t level = 0; level < levels.size(); ++level) {
        const double d = levels[level];
        if (d < kPatternLevelShare * levels.front()) continue;
        std::vector<StraightView>& views = level_views[level];
        if (orientation == 0 || !yaw_free) {
          views.assign(patch.size(), StraightView{});
          parallelFor(patch.size(), workers,
                      [&](std::size_t k) { views[k] = sees_straight(patch[k], d, yaws_deg[orientation]); });
        }
        const int tiling = static_cast<int>(tiling_patch.size());
        tiling_patch.push_back(p);
        const Eigen::Vector2d span(2.0 * d * camera.halfWidthTan() * region.widthShare(),
                                   2.0 * d * camera.halfHeightTan() * region.heightShare());
        const std::pair<long, long> half_cells(std::lround(0.5 * span.x() / r), std::lround(0.5 * span.y() / r));
        const std::vector<std::vector<std::uint32_t>> parts = openParts(patch, cells_of, views, half_cells);
        if (orientation == 0 && d == levels.front() && parts.size() != 1) {
          // What no part of the farthest level holds (over the obstacle) gets oblique rows.
          std::vector<std::uint8_t> in_part(surface.elements.size(), 0);
          for (const auto& part : parts)
            for (const std::uint32_t e : part) in_part[e] = 1;
          for (const std::uint32_t e : patch)
            if (!in_part[e]) hidden.push_back(e);
        }
        for (const std::vector<std::uint32_t>& part : parts) {
          Eigen::Vector2d lo = Eigen::Vector2d::Constant(INFINITY), hi = -lo;
          std::set<std::pair<long, long>> cells;
          for (const std::uint32_t e : part) {
            const Eigen::Vector2d at = imageAxes(e);
            lo = lo.cwiseMin(at);
            hi = hi.cwiseMax(at);
            cells.emplace(std::lround(at.x() / r), std::lround(at.y() / r));
          }
          lo -= Eigen::Vector2d::Constant(0.5 * r);
          hi += Eigen::Vector2d::Constant(0.5 * r);
          // Per image axis: stations `count`, the first at `first`, `step` apart.
          int count[2];
          double first[2], step[2];
          for (int axis = 0; axis < 2; ++axis) {
            const double length_m = hi[axis] - lo[axis];
            count[axis] = std::max(1, static_cast<int>(std::ceil(length_m / span[axis] - 1e-9)));
            first[axis] = count[axis] == 1 ? 0.5 * (lo[axis] + hi[axis]) : lo[axis] + 0.5 * span[axis];
            step[axis] = count[axis] == 1 ? 0.0 : (length_m - span[axis]) / (count[axis] - 1);
            // A part that ends at an obstacle on one side only may stop short of it by a share of a
            // covered part: the oblique rows from beside the obstacle cover that strip anyway, and a
            // station fewer per lane is saved (a 3.3 m part takes 4 photos of 0.82 m, not 5).
            const bool low_open = lo[axis] > patch_lo[axis] + 0.5 * r, high_open = hi[axis] < patch_hi[axis] - 0.5 * r;
            if (low_open != high_open && count[axis] > 1 &&
                (count[axis] - 1) * span[axis] >= length_m - kObstacleSlackShare * span[axis]) {
              --count[axis];
              step[axis] = low_open ? -span[axis] : span[axis];
              first[axis] = low_open ? hi[axis] - 0.5 * span[axis] : lo[axis] + 0.5 * span[axis];
            }
          }
          for (int j = 0; j < count[1]; ++j)
            for (int i = 0; i < count[0]; ++i) {
              Eigen::Vector2d at;
              const int index[2] = {i, j};
              for (int axis = 0; axis < 2; ++axis) at[axis] = first[axis] + step[axis] * index[axis];
              // The nearest face of the part within a voxel, else no station here.
              bool found = false;
              for (long dj = -1; dj <= 1 && !found; ++dj)
                for (long di = -1; di <= 1 && !found; ++di)
                  found = cells.count({std::lround(at.x() / r) + di, std::lround(at.y() / r) + dj}) > 0;
              if (!found) continue;
              const auto nearestTo = [&](const Eigen::Vector2d& point) {
                std::uint32_t nearest = part.front();
                double best = INFINITY;
                for (const std::uint32_t e : part) {
                  const double offset = (imageAxes(e) - point).squaredNorm();
                  if (offset < best) {
                    best = offset;
                    nearest = e;
                  }
                }
                return nearest;
              };
              std::uint32_t nearest = nearestTo(at);
              if (standoff_stations && !sees_straight(nearest, d, yaws_deg[orientation]).stands) {
                // Back towards the part's inside, along the axes on which this station ends a row.
                Eigen::Vector2d back = Eigen::Vector2d::Zero(), limits_m = Eigen::Vector2d::Zero();
                for (int axis = 0; axis < 2; ++axis)
                  if (count[axis] > 1 && (index[axis] == 0 || index[axis] == count[axis] - 1)) {
                    back[axis] = index[axis] == 0 ? 1.0 : -1.0;
                    if (step[axis] < 0.0) back[axis] = -back[axis];
                    limits_m[axis] = kObstacleSlackShare * span[axis];
                  }
                std::tie(at, nearest) = stationThatStands(at, back, limits_m, r, nearestTo, [&](std::uint32_t e) {
                                          return sees_straight(e, d, yaws_deg[orientation]).stands;
                                        }).value_or(std::make_pair(at, nearest));
              }
              seeds.push_back({nearest, d,
                               at.x() * straight.right() + at.y() * straight.up() + plane * straight.forward(),
                               yaws_deg[orientation], tiling, orientation == 1});
            }
        }
      }
    }
  }
  return seeds;
}

// Oblique rows over what straight views cannot reach (the strip of a deck bay over a pier cap):
// over the hidden elements, cells a quarter of the short side of the farthest level's covered
// part, each aimed at from beside by views tilted towards the four tangent directions, at half
// to nine tenths of the incidence limit, from as far as the GSD allows at the covered part's far
// edge and nearer. The selection takes the rows that cover the strip with fewest photos.
std::vector<Seed> obliqueSeeds(const environment::VoxelGrid& grid, const Camera& camera, const CoverageRegion& region,
                               const RegionSurface& surface, const std::vector<std::uint32_t>& hidden, double far_m,
                               double heading_deg) {
  const double width_tan = camera.halfWidthTan() * region.widthShare();
  const double height_tan = camera.halfHeightTan() * region.heightShare();
  const double cell_m = std::max(2.0 * grid.frame().resolution_m(), 0.5 * far_m * std::min(width_tan, height_tan));
  std::map<std::tuple<int, long, long, long>, std::uint32_t> cells;  // one element per cell, the first
  for (const std::uint32_t e : hidden) {
    const Eigen::Vector3d& c = surface.elements[e].centre_m;
    cells.emplace(
        std::make_tuple(surface.elements[e].face, static_cast<long>(std::floor(c.x() / cell_m)),
                        static_cast<long>(std::floor(c.y() / cell_m)), static_cast<long>(std::floor(c.z() / cell_m))),
        e);
  }
  std::vector<Seed> seeds;
  for (const auto& entry : cells) {
    const std::uint32_t e = entry.second;
    for (const double share : {0.5, 0.6, 0.7, 0.8, 0.9}) {
      const double tilt_rad = region.max_incidence_deg * share * kDegree;
      // The far edge of the covered part lies at the tilt plus its half height: its GSD bounds the distance.
      const double edge_rad = std::min(tilt_rad + std::atan(height_tan), 89.0 * kDegree);
      const double reach_m = camera.distanceForGsd_m(region.gsd_mm_px, edge_rad) * std::cos(edge_rad - tilt_rad);
      for (const double factor : {1.0, 0.9, 0.8, 0.7})
        seeds.push_back({e, factor * reach_m, surface.elements[e].centre_m, heading_deg, -1, false, tilt_rad});
    }
  }
  return seeds;
}

// The lattice: per distance level, cells the size of `share` x the covered part of an image
// seen straight on, laid in each face direction's image axes (the right and up axes of the
// straight view, whose yaw follows the region's heading), so that views one cell pitch apart
// tile the surface; per cell, the element nearest its centre. Cells are at least two voxels and a
// quarter of the farthest level's covered part: the slivers nearer views would cover are left to
// the repairs.
std::vector<Seed> latticeSeeds(const environment::VoxelGrid& grid, const Camera& camera, const CoverageRegion& region,
                               const RegionSurface& surface, const std::vector<double>& levels, double share,
                               double heading_deg) {
  // Cells no smaller than two voxels, nor than a quarter of the farthest level's covered part.
  const double far_m = levels.front();
  const double min_cell_m = std::max(
      2.0 * grid.frame().resolution_m(),
      0.25 * 2.0 * far_m *
          std::min(camera.halfWidthTan() * region.widthShare(), camera.halfHeightTan() * region.heightShare()));
  const std::vector<CameraFrame> frames = straightFrames(camera, heading_deg);
  std::vector<Seed> seeds;
  for (const double d : levels) {
    const double width_m = std::max(min_cell_m, share * 2.0 * d * camera.halfWidthTan() * region.widthShare());
    const double height_m = std::max(min_cell_m, share * 2.0 * d * camera.halfHeightTan() * region.heightShare());
    const double depth_m = std::min(width_m, height_m);
    std::map<std::tuple<int, long, long, long>, std::pair<double, std::uint32_t>> best;
    for (std::uint32_t e = 0; e < surface.elements.size(); ++e) {
      const auto& element = surface.elements[e];
      const CameraFrame& straight = frames[element.face];
      const Eigen::Vector3d scaled(element.centre_m.dot(straight.right()) / width_m,
                                   element.centre_m.dot(straight.up()) / height_m,
                                   element.centre_m.dot(straight.forward()) / depth_m);
      const Eigen::Vector3d cell = scaled.array().floor();
      const double offset = (scaled - cell - Eigen::Vector3d::Constant(0.5)).squaredNorm();
      const auto key = std::make_tuple(element.face, static_cast<long>(cell.x()), static_cast<long>(cell.y()),
                                       static_cast<long>(cell.z()));
      const auto found = best.find(key);
      if (found == best.end() || offset < found->second.first) best[key] = {offset, e};
    }
    std::vector<std::uint32_t> chosen;
    chosen.reserve(best.size());
    for (const auto& entry : best) chosen.push_back(entry.second.second);
    std::sort(chosen.begin(), chosen.end());
    // Each seed's aim, snapped to the edges of its flat patch; one seed per distinct aim.
    const double half_width_m = d * camera.halfWidthTan() * region.widthShare();
    const double half_height_m = d * camera.halfHeightTan() * region.heightShare();
    std::map<std::tuple<long, long, long>, bool> aims;
    for (const std::uint32_t e : chosen) {
      const auto& element = surface.elements[e];
      Eigen::Vector3d aim = element.centre_m;
      if (element.normal.isApprox(element.faceNormal())) {
        const CameraFrame& straight = frames[element.face];
        for (const auto& [axis, half] : {std::pair<Eigen::Vector3d, double>{straight.right(), half_width_m},
                                         std::pair<Eigen::Vector3d, double>{straight.up(), half_height_m}}) {
          const double ahead = flatExtent(grid, region.shape, element, axis, half + half);
          const double behind = flatExtent(grid, region.shape, element, -axis, half + half);
          aim += axis * snapShift(ahead, behind, half);
        }
      }
      const auto key =
          std::make_tuple(std::lround(aim.x() * 1e3), std::lround(aim.y() * 1e3), std::lround(aim.z() * 1e3));
      if (aims.emplace(key, true).second) seeds.push_back({e, d, aim, heading_deg});
    }
  }
  return seeds;
}

// Whether any camera might cover `element` (RegionViewer's rule): its line of sight walks
// face-connected voxels, all free, from the camera's to the one in front of the face, each
// meeting the segment; the segment lies within the cone of the incidence limit around the normal
// (within a hundredth of a voxel, the sight's end), and the camera is at least the minimum focus
// away. Searches those voxels (centres within the cone widened by a half diagonal and that
// hundredth) from the face outwards for one that far: where none is, no pose covers the element,
// and the repairs need not probe it (a slot too thin to look into).
bool mayBeSeen(const environment::VoxelGrid& grid, const environment::SurfaceElement& element, double max_incidence_deg,
               double min_focus_m) {
  const environment::GridFrame& frame = grid.frame();
  const double r = frame.resolution_m();
  const double half_diagonal_m = 0.5 * std::sqrt(3.0) * r;
  const double margin_m = half_diagonal_m + 0.02 * r;
  const double cos_max = std::cos(max_incidence_deg * kDegree), sin_max = std::sin(max_incidence_deg * kDegree);
  const Eigen::Vector3d end = element.centre_m + element.faceNormal() * (0.01 * r);
  const environment::Index3 start{frame.indexOf(0, end.x()), frame.indexOf(1, end.y()), frame.indexOf(2, end.z())};
  if (grid.at(start[0], start[1], start[2]) != environment::CellState::Free) return false;
  std::unordered_map<std::size_t, bool> seen{{frame.linear(start[0], start[1], start[2]), true}};
  std::vector<environment::Index3> queue{start};
  for (std::size_t next = 0; next < queue.size(); ++next)
    for (int axis = 0; axis < 3; ++axis)
      for (const int step : {-1, 1}) {
        environment::Index3 voxel = queue[next];
        voxel[axis] += step;
        if (grid.at(voxel[0], voxel[1], voxel[2]) != environment::CellState::Free ||
            !seen.emplace(frame.linear(voxel[0], voxel[1], voxel[2]), true).second)
          continue;
        const Eigen::Vector3d w =
            Eigen::Vector3d(frame.centreOf(0, voxel[0]), frame.centreOf(1, voxel[1]), frame.centreOf(2, voxel[2])) -
            element.centre_m;
        const double along = w.dot(element.normal);
        // A lower bound on the distance to the cone outside it (its exact value off the apex).
        if ((w - along * element.normal).norm() * cos_max - along * sin_max > margin_m) continue;
        if (w.norm() >= min_focus_m - half_diagonal_m) return true;
        queue.push_back(voxel);
      }
  return false;
}

// Free mode: keep a pose where it keeps the standoff, or where it is of largest clearance
// (within a tolerance) among the poses covering one of its elements that no standoff-keeping
// pose covers. Every element stays covered.
std::vector<bool> freeModeKeep(const std::vector<Pose>& poses, const std::vector<Cover>& covered,
                               std::size_t element_count, double required_clearance_m) {
  std::vector<std::uint8_t> fits(element_count, 0);
  std::vector<double> best(element_count, -1.0);
  for (std::size_t v = 0; v < poses.size(); ++v)
    for (const std::uint32_t element : covered[v]) {
      if (poses[v].clearance_m >= required_clearance_m) fits[element] = 1;
      best[element] = std::max(best[element], poses[v].clearance_m);
    }
  std::vector<bool> keep(poses.size(), false);
  for (std::size_t v = 0; v < poses.size(); ++v) {
    if (poses[v].clearance_m >= required_clearance_m) {
      keep[v] = true;
      continue;
    }
    keep[v] = std::any_of(covered[v].begin(), covered[v].end(), [&](std::uint32_t element) {
      return !fits[element] && poses[v].clearance_m >= best[element] - clearanceTolerance_m(best[element]);
    });
  }
  return keep;
}

}  // namespace

CoverSummary summariseCover(const std::vector<SeenElement>& covered, const RegionSurface& surface) {
  CoverSummary summary;
  for (const SeenElement& seen : covered) {
    const double a = surface.elements[seen.element].area_m2;
    summary.area_m2 += a;
    summary.distance_m += a * seen.distance_m;
    summary.gsd_mm_px += a * seen.gsd_mm_px;
    summary.finest_gsd_mm_px = std::min(summary.finest_gsd_mm_px, static_cast<double>(seen.gsd_mm_px));
  }
  summary.distance_m /= summary.area_m2;
  summary.gsd_mm_px /= summary.area_m2;
  return summary;
}

std::vector<ElementRun> elementRuns(const std::vector<std::uint32_t>& ascending) {
  std::vector<ElementRun> runs;
  for (const std::uint32_t e : ascending) appendElement(runs, e);
  return runs;
}

void CandidateViews::add(const CameraPose& pose, const std::vector<ElementRun>& covered, const CoverSummary& summary) {
  poses.push_back(pose);
  runs.insert(runs.end(), covered.begin(), covered.end());
  offsets.push_back(static_cast<std::uint32_t>(runs.size()));
  summaries.push_back(summary);
}

std::vector<double> distanceLevels(const Camera& camera, const CoverageRegion& region, int levels, double room_m) {
  checkCameraReaches(camera, region);
  // Seen straight on, a flat surface at the corner of the covered part of the image lies
  // farther than its centre by 1 / cos(a) and is seen at incidence a, so its GSD is larger by
  // 1 / cos^2(a) = 1 + tw^2 + th^2: the farthest level keeps the whole covered part within the GSD.
  const double tw = camera.halfWidthTan() * region.widthShare(), th = camera.halfHeightTan() * region.heightShare();
  const double reach_m = camera.distanceForGsd_m(region.gsd_mm_px) / (1.0 + tw * tw + th * th);
  const double near_m = std::min(reach_m, camera.min_focus_m * 1.001 + 1e-3);
  const double far_m = std::max(near_m, std::min(reach_m, room_m));
  std::vector<double> distances;
  const int count = std::max(1, levels);
  distances.reserve(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k)
    distances.push_back(count == 1 ? far_m : far_m * std::pow(near_m / far_m, static_cast<double>(k) / (count - 1)));
  return distances;
}

double roomInFront_m(const environment::Environment& environment, const Camera& camera, const RegionSurface& surface,
                     double far_m) {
  const environment::VoxelGrid& grid = environment.grid();
  const environment::GridFrame& frame = grid.frame();
  const environment::VehicleGeometry& vehicle = environment.vehicle();
  const double step_m = 0.5 * frame.resolution_m();
  std::vector<double> rooms;
  rooms.reserve(surface.elements.size());
  for (const environment::SurfaceElement& element : surface.elements) {
    // Beyond a camera at distance d the inflated airframe reaches along the normal: the body sits
    // the mount offset back (the offset turns with the yaw, hence its horizontal length), then the
    // cylinder's bottom or top and its radius, projected.
    const Eigen::Vector3d& n = element.normal;
    const double horizontal = std::sqrt(std::max(0.0, 1.0 - n.z() * n.z()));
    const double extent_m = std::abs(n.z()) * (n.z() < 0.0 ? -vehicle.inflatedBottom_m() : vehicle.inflatedTop_m()) +
                            horizontal * vehicle.inflatedRadius_m() - n.z() * camera.mount_offset_m.z() +
                            horizontal * camera.mount_offset_m.head<2>().norm();
    const double longest_m = far_m + extent_m;  // beyond it the room is at least far_m
    double run_m = step_m;
    for (; run_m < longest_m; run_m += step_m) {
      const Eigen::Vector3d p = element.centre_m + run_m * n;
      if (grid.at(frame.indexOf(0, p.x()), frame.indexOf(1, p.y()), frame.indexOf(2, p.z())) !=
          environment::CellState::Free)
        break;
    }
    rooms.push_back(std::min(run_m, longest_m) - extent_m);
  }
  if (rooms.empty()) return far_m;
  std::nth_element(rooms.begin(), rooms.begin() + rooms.size() / 2, rooms.end());
  return rooms[rooms.size() / 2];
}

double regionHeading(const RegionSurface& surface) {
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double area = 0.0;
  for (const auto& element : surface.elements) {
    mean += element.area_m2 * element.centre_m.head<2>();
    area += element.area_m2;
  }
  mean /= area;
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const auto& element : surface.elements) {
    const Eigen::Vector2d d = element.centre_m.head<2>() - mean;
    scatter += element.area_m2 * d * d.transpose();
  }
  // Major axis of the horizontal scatter (closed form for a symmetric 2 x 2 matrix).
  const double angle = 0.5 * std::atan2(2.0 * scatter(0, 1), scatter(0, 0) - scatter(1, 1));  // from +x
  double heading = 90.0 - angle / kDegree;                                                    // from north, clockwise
  heading = std::fmod(heading + 360.0, 180.0);
  return std::abs(heading - 180.0) < 1e-9 ? 0.0 : heading;
}

std::vector<SeenElement> coveredElements(const environment::VoxelGrid& grid, const Camera& camera,
                                         const CoverageRegion& region, const RegionSurface& surface,
                                         const CameraPose& pose) {
  std::vector<SeenElement> covered;
  RegionViewer(grid, camera, region, surface).covered(pose, covered);
  return covered;
}

CandidateViews generateCandidateViews(const environment::Environment& environment, const Camera& camera,
                                      const CoverageRegion& region, const RegionSurface& surface,
                                      const ViewGenerationOptions& options) {
  // The GSD's levels, and where the room in front of the surface is shorter than the farthest of
  // them (a coarse GSD under a low deck), the same number of levels within the room as well.
  std::vector<double> levels = distanceLevels(camera, region, options.distance_levels);
  const double room_m = roomInFront_m(environment, camera, surface, levels.front());
  if (room_m < levels.front()) {
    for (const double d : distanceLevels(camera, region, options.distance_levels, room_m))
      if (std::none_of(levels.begin(), levels.end(), [d](double level) { return std::abs(level - d) < 1e-6; }))
        levels.push_back(d);
    std::sort(levels.begin(), levels.end(), std::greater<double>());
  }
  const double heading = regionHeading(surface);
  PoseMaker maker(environment, camera, region, options, heading);
  maker.setHeading(heading);
  const RegionViewer viewer(environment.grid(), camera, region, surface, &environment.index()->freeBlocks());
  const double tilt = std::min(region.max_incidence_deg * options.tilt_share, 60.0) * kDegree;

  // The lattice: every seed's poses and what each covers, in seed order whatever the workers.
  // Pattern seeds first: the selection breaks ties by candidate index.
  TilingPatches tiling_patch;
  const StraightTest sees_straight = [&](std::uint32_t e, double d, double yaw_deg) {
    return maker.straight(surface.elements[e], d, yaw_deg);
  };
  std::vector<std::uint32_t> hidden;
  std::vector<Seed> seeds = patternSeeds(environment.grid(), camera, region, surface, levels, heading, sees_straight,
                                         maker.free(), options.workers, tiling_patch, hidden);
  // Oblique rows only over what some camera may see: a slot too thin to look into (the air over a
  // diaphragm or a bearing) would take candidates no photo can use.
  std::vector<std::uint8_t> may_be_seen(hidden.size(), 0);
  parallelFor(hidden.size(), options.workers, [&](std::size_t k) {
    may_be_seen[k] =
        mayBeSeen(environment.grid(), surface.elements[hidden[k]], region.max_incidence_deg, camera.min_focus_m);
  });
  std::vector<std::uint32_t> hidden_seen;
  for (std::size_t k = 0; k < hidden.size(); ++k)
    if (may_be_seen[k]) hidden_seen.push_back(hidden[k]);
  const std::vector<Seed> oblique =
      obliqueSeeds(environment.grid(), camera, region, surface, hidden_seen, levels.front(), heading);
  seeds.insert(seeds.end(), oblique.begin(), oblique.end());
  const std::vector<Seed> lattice =
      latticeSeeds(environment.grid(), camera, region, surface, levels, options.seed_spacing_share, heading);
  seeds.insert(seeds.end(), lattice.begin(), lattice.end());
  SharedCovers::State* shared = options.shared_covers ? &options.shared_covers->state() : nullptr;
  std::vector<std::vector<Pose>> seed_poses(seeds.size());
  std::vector<std::vector<Cover>> seed_covered(seeds.size());
  std::vector<std::size_t> seed_tried(seeds.size(), 0);
  std::vector<std::size_t> seed_straight(seeds.size(), 0);  // poses of the straight view, raised included
  parallelFor(
      seeds.size(), options.workers,
      [&](std::size_t s) {
        const auto& element = surface.elements[seeds[s].element];
        const double d = seeds[s].distance_m;
        std::vector<SeenElement> seen;
        const auto find = [&](const Pose& pose) {
          viewer.covered(pose.pose, seen);
          return compactCover(seen, surface);
        };
        // Raised poses are ceiling mode's own: the other modes never ask for them.
        const auto cover = [&](const Pose& pose) {
          seed_covered[s].push_back(
              shared && !pose.raised ? shared->coverOf(options.mode, region.name, pose.pose, [&] { return find(pose); })
                                     : find(pose));
        };
        if (seeds[s].tilt_rad > 0.0) {
          maker.around(element, seeds[s].aim_m, d, seeds[s].tilt_rad, 4, seeds[s].level_yaw_deg, seed_poses[s],
                       seed_tried[s]);
          for (const Pose& pose : seed_poses[s]) cover(pose);
          return;
        }
        maker.around(element, seeds[s].aim_m, d, 0.0, 1, seeds[s].level_yaw_deg, seed_poses[s], seed_tried[s]);
        const std::size_t straight = seed_poses[s].size();
        seed_straight[s] = straight;
        double straight_area_m2 = 0.0;
        for (std::size_t p = 0; p < straight; ++p) {
          cover(seed_poses[s][p]);
          if (p == 0) straight_area_m2 = seed_covered[s].back().summary.area_m2;
        }
        // Tilted views where the straight one is not admissible or sees less than its whole
        // covered part (an edge, an occluder, a narrow strip): in the open they add nothing.
        if (straight == 0 || straight_area_m2 < kOpenShare * viewer.openArea_m2(d)) {
          maker.around(element, seeds[s].aim_m, d, tilt, 4, seeds[s].level_yaw_deg, seed_poses[s], seed_tried[s]);
          for (std::size_t p = straight; p < seed_poses[s].size(); ++p) cover(seed_poses[s][p]);
        }
      },
      options.progress);
  if (shared) shared->finished(options.mode, region.name);

  CandidateViews views;
  views.stats.seeds = seeds.size();
  std::vector<Pose> poses;
  std::vector<Cover> covered;
  std::vector<int> pose_tiling;           // per pose, the tiling it is a station of (its straight view), or -1
  std::vector<std::uint8_t> pose_across;  // per pose, 1 if from a pattern across the heading
  for (std::size_t s = 0; s < seeds.size(); ++s) {
    views.stats.poses_tried += seed_tried[s];
    for (std::size_t p = 0; p < seed_poses[s].size(); ++p)
      if (!seed_covered[s][p].runs.empty()) {
        // The tiling's station is the straight view itself, if it was admissible (not a raised
        // or a tilted view).
        const bool station = p < seed_straight[s] && !seed_poses[s][p].raised;
        pose_tiling.push_back(station ? seeds[s].tiling : -1);
        pose_across.push_back(seeds[s].across ? 1 : 0);
        poses.push_back(seed_poses[s][p]);
        covered.push_back(std::move(seed_covered[s][p]));
      }
    std::vector<Cover>().swap(seed_covered[s]);
  }

  // Repairs: probe every element the lattice left uncovered from denser distances and tilts (the
  // views across the heading aside: a cover without them must find its own).
  std::vector<std::uint8_t> reached(surface.elements.size(), 0);
  for (std::size_t v = 0; v < covered.size(); ++v)
    if (!pose_across[v])
      for (const std::uint32_t element : covered[v]) reached[element] = 1;
  std::vector<double> repair_levels = distanceLevels(camera, region, kRepairLevels);
  for (std::uint32_t e = 0; e < surface.elements.size(); ++e) {
    if (reached[e]) continue;
    const auto& element = surface.elements[e];
    if (!mayBeSeen(environment.grid(), element, region.max_incidence_deg, camera.min_focus_m)) continue;
    std::vector<Pose> probes;
    for (const double d : repair_levels)
      for (const double share : {0.0, 0.3, 0.6, 0.95}) {
        const double probe_tilt = std::min(region.max_incidence_deg * share, 80.0) * kDegree;
        maker.around(element, element.centre_m, d, probe_tilt, kRepairDirections, maker.levelYaw_deg(), probes,
                     views.stats.poses_tried);
      }
    views.stats.repair_probes += probes.size();
    std::vector<Pose> seeing;
    for (const Pose& probe : probes)
      if (viewer.covers(probe.pose, e)) seeing.push_back(probe);
    if (seeing.empty()) continue;
    if (maker.free()) {
      // Standoff-keeping probes if any, else those of largest clearance.
      double best = -1.0;
      for (const Pose& p : seeing) best = std::max(best, p.clearance_m);
      const double floor_m =
          best >= maker.requiredClearance_m() ? maker.requiredClearance_m() : best - clearanceTolerance_m(best);
      seeing.erase(std::remove_if(seeing.begin(), seeing.end(), [&](const Pose& p) { return p.clearance_m < floor_m; }),
                   seeing.end());
    }
    // A few probes spread over the list (farthest first, as generated), for the selection to choose.
    const std::size_t keep = std::min<std::size_t>(kRepairViewsPerElement, seeing.size());
    for (std::size_t k = 0; k < keep; ++k) {
      const Pose& probe = seeing[k * seeing.size() / keep];
      std::vector<SeenElement> list;
      viewer.covered(probe.pose, list);
      if (list.empty()) continue;
      for (const SeenElement& seen : list) reached[seen.element] = 1;
      poses.push_back(probe);
      covered.push_back(compactCover(list, surface));
      pose_tiling.push_back(-1);
      pose_across.push_back(0);
      ++views.stats.repair_views;
    }
  }

  const std::vector<bool> keep =
      maker.free() ? freeModeKeep(poses, covered, surface.elements.size(), maker.requiredClearance_m())
                   : std::vector<bool>(poses.size(), true);
  for (std::size_t v = 0; v < covered.size(); ++v)
    for (const std::uint32_t element : covered[v]) reached[element] = 1;
  views.tilings.resize(tiling_patch.size());
  for (std::size_t t = 0; t < tiling_patch.size(); ++t) views.tilings[t].patch = tiling_patch[t];
  // Each list is released as it is copied: the region's lists are held once, not twice.
  std::size_t total = 0;
  for (std::size_t v = 0; v < poses.size(); ++v)
    if (keep[v]) total += covered[v].runs.size();
  views.runs.reserve(total);
  for (std::size_t v = 0; v < poses.size(); ++v) {
    if (keep[v]) {
      if (pose_tiling[v] >= 0) views.tilings[pose_tiling[v]].views.push_back(static_cast<std::uint32_t>(views.size()));
      views.tiling_only.push_back(pose_across[v]);
      views.add(poses[v].pose, covered[v].runs, covered[v].summary);
    }
    std::vector<ElementRun>().swap(covered[v].runs);
  }
  views.tilings.erase(std::remove_if(views.tilings.begin(), views.tilings.end(),
                                     [](const Tiling& tiling) { return tiling.views.empty(); }),
                      views.tilings.end());
  views.reachable = std::move(reached);
  return views;
}

}  // namespace ceilplan::mission
