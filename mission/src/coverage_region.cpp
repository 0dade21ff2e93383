#include "ceilplan/mission/coverage_region.hpp"

#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>

namespace ceilplan::mission {
namespace {

const double kSinHalfRight = std::sqrt(0.5);  // sin 45 deg

// Orientation of the triangle (a, b, c): > 0 counter-clockwise.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

bool segmentsCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                   const Eigen::Vector2d& d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

// Distance from p to the segment ab.
double segmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (a + t * ab - p).norm();
}

void requireName(const std::string& name, const char* what) {
  if (name.empty()) throw ceilplan::InputError(std::string("a ") + what + " needs a name");
}

}  // namespace

FaceKind faceKindOf(const Eigen::Vector3d& normal) {
  if (normal.z() < -kSinHalfRight) return FaceKind::Down;
  if (normal.z() > kSinHalfRight) return FaceKind::Up;
  return FaceKind::Side;
}

const char* faceKindName(FaceKind kind) {
  switch (kind) {
    case FaceKind::Down:
      return "down";
    case FaceKind::Side:
      return "side";
    case FaceKind::Up:
      return "up";
  }
  return "?";
}

bool FaceSet::has(FaceKind kind) const {
  return (kind == FaceKind::Down && down) || (kind == FaceKind::Side && side) || (kind == FaceKind::Up && up);
}

std::string FaceSet::describe() const {
  std::string text;
  for (const FaceKind kind : {FaceKind::Down, FaceKind::Side, FaceKind::Up})
    if (has(kind)) text += (text.empty() ? "" : ", ") + std::string(faceKindName(kind));
  return "[" + text + "]";
}

RegionShape RegionShape::makeBox(const Eigen::Vector3d& min_m, const Eigen::Vector3d& max_m) {
  RegionShape shape;
  shape.kind = Kind::Box;
  shape.box = Eigen::AlignedBox3d(min_m, max_m);
  return shape;
}

RegionShape RegionShape::makePrism(std::vector<Eigen::Vector2d> polygon_m, double z_min_m, double z_max_m) {
  RegionShape shape;
  shape.kind = Kind::Prism;
  shape.polygon_m = std::move(polygon_m);
  Eigen::Vector3d lo(0, 0, z_min_m), hi(0, 0, z_max_m);
  if (!shape.polygon_m.empty()) {
    Eigen::Vector2d min2 = shape.polygon_m.front(), max2 = shape.polygon_m.front();
    for (const Eigen::Vector2d& p : shape.polygon_m) {
      min2 = min2.cwiseMin(p);
      max2 = max2.cwiseMax(p);
    }
    lo.head<2>() = min2;
    hi.head<2>() = max2;
  }
  shape.box = Eigen::AlignedBox3d(lo, hi);
  return shape;
}

bool RegionShape::contains(const Eigen::Vector3d& point_m) const {
  if (!box.contains(point_m)) return false;
  if (kind == Kind::Box) return true;
  // Even-odd rule, with points on an edge counted inside.
  const Eigen::Vector2d p = point_m.head<2>();
  bool inside = false;
  const std::size_t n = polygon_m.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Eigen::Vector2d& a = polygon_m[i];
    const Eigen::Vector2d& b = polygon_m[j];
    if (segmentDistance(p, a, b) < 1e-9) return true;
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

void RegionShape::validate(const std::string& what) const {
  if (kind == Kind::Box) {
    if (!box.min().allFinite() || !box.max().allFinite())
      throw ceilplan::InputError(what + ": 'box' corners must be finite");
    if ((box.max() - box.min()).minCoeff() <= 0.0)
      throw ceilplan::InputError(what + ": 'box' must have max > min on every axis, got min " + formatPoint(box.min()) +
                                 ", max " + formatPoint(box.max()));
    return;
  }
  if (polygon_m.size() < 3) throw ceilplan::InputError(what + ": 'prism.polygon' needs at least 3 vertices");
  for (const Eigen::Vector2d& p : polygon_m)
    if (!p.allFinite()) throw ceilplan::InputError(what + ": 'prism.polygon' vertices must be finite");
  if (!std::isfinite(box.min().z()) || !std::isfinite(box.max().z()) || box.max().z() <= box.min().z())
    throw ceilplan::InputError(what + ": 'prism.z' must be [min, max] with max > min, got [" +
                               formatNumber(box.min().z()) + ", " + formatNumber(box.max().z()) + "]");
  double twice_area = 0.0;
  const std::size_t n = polygon_m.size();
  for (std::size_t i = 0; i < n; ++i)
    twice_area += cross(Eigen::Vector2d::Zero(), polygon_m[i], polygon_m[(i + 1) % n]);
  if (std::abs(twice_area) < 1e-9) throw ceilplan::InputError(what + ": 'prism.polygon' encloses no area");
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // neighbours through the closing edge
      if (segmentsCross(polygon_m[i], polygon_m[(i + 1) % n], polygon_m[j], polygon_m[(j + 1) % n]))
        throw ceilplan::InputError(what + ": 'prism.polygon' crosses itself (edges " + std::to_string(i) + " and " +
                                   std::to_string(j) + ")");
    }
}

void CoverageRegion::validate() const {
  requireName(name, "surface region");
  const std::string what = "surface region '" + name + "'";
  shape.validate(what);
  if (faces.empty()) throw ceilplan::InputError(what + ": 'faces' must list at least one of down, side, up");
  if (!(std::isfinite(gsd_mm_px) && gsd_mm_px > 0.0 && gsd_mm_px <= 1000.0))
    throw ceilplan::InputError(what + ": 'gsd_mm_px' must lie in (0, 1000] mm/px, got " + formatNumber(gsd_mm_px));
  for (const auto& [key, value] : {std::pair<const char*, double>{"overlap.front", overlap_front_pct},
                                   std::pair<const char*, double>{"overlap.side", overlap_side_pct}})
    if (!(std::isfinite(value) && value >= 0.0 && value < 100.0))
      throw ceilplan::InputError(what + ": '" + key + "' must lie in [0, 100) %, got " + formatNumber(value));
  if (!(std::isfinite(max_incidence_deg) && max_incidence_deg > 0.0 && max_incidence_deg <= 89.0))
    throw ceilplan::InputError(what + ": 'max_incidence_deg' must lie in (0, 89] deg, got " +
                               formatNumber(max_incidence_deg));
}

void ContactGrid::validate() const {
  requireName(name, "contact grid");
  const std::string what = "contact grid '" + name + "'";
  shape.validate(what);
  if (faces.empty()) throw ceilplan::InputError(what + ": 'faces' must list at least one of down, side, up");
  if (!(std::isfinite(spacing_m) && spacing_m >= 0.05 && spacing_m <= 100.0))
    throw ceilplan::InputError(what + ": 'spacing_m' must lie in [0.05, 100] m, got " + formatNumber(spacing_m));
  if (!(std::isfinite(dwell_s) && dwell_s >= 0.0 && dwell_s <= 3600.0))
    throw ceilplan::InputError(what + ": 'dwell_s' must lie in [0, 3600] s, got " + formatNumber(dwell_s));
  if (!(std::isfinite(reach_m) && reach_m > 0.0 && reach_m <= 5.0))
    throw ceilplan::InputError(what + ": 'reach_m' must lie in (0, 5] m, got " + formatNumber(reach_m));
}

void checkCameraReaches(const Camera& camera, const CoverageRegion& region) {
  const std::string what = "surface region '" + region.name + "'";
  const double reach_m = camera.distanceForGsd_m(region.gsd_mm_px);
  if (reach_m <= camera.min_focus_m)
    throw ceilplan::InputError(what + ": 'gsd_mm_px' " + formatNumber(region.gsd_mm_px) + " needs the camera within " +
                               formatNumber(reach_m, 3) + " m of the surface, not beyond its 'camera.min_focus_m' " +
                               formatNumber(camera.min_focus_m) + " m: ask for a coarser GSD or use a longer lens");
  const double steepest_deg = 90.0 - region.max_incidence_deg;
  for (const FaceKind kind : {FaceKind::Down, FaceKind::Side, FaceKind::Up}) {
    if (!region.faces.has(kind)) continue;
    bool reachable = false;
    std::string need;
    switch (kind) {
      case FaceKind::Down:
        reachable = camera.gimbal_pitch_max_deg >= steepest_deg - 1e-9;
        need = "pitch up to at least " + formatNumber(steepest_deg) + " deg";
        break;
      case FaceKind::Up:
        reachable = camera.gimbal_pitch_min_deg <= -steepest_deg + 1e-9;
        need = "pitch down to at most " + formatNumber(-steepest_deg) + " deg";
        break;
      case FaceKind::Side:
        reachable = camera.gimbal_pitch_max_deg >= -region.max_incidence_deg - 1e-9 &&
                    camera.gimbal_pitch_min_deg <= region.max_incidence_deg + 1e-9;
        need = "a pitch within +-" + formatNumber(region.max_incidence_deg) + " deg";
        break;
    }
    if (!reachable)
      throw ceilplan::InputError(what + ": 'faces' includes " + faceKindName(kind) +
                                 ", but 'camera.gimbal_pitch_deg' [" + formatNumber(camera.gimbal_pitch_min_deg) +
                                 ", " + formatNumber(camera.gimbal_pitch_max_deg) +
                                 "] cannot point at them within 'max_incidence_deg' " +
                                 formatNumber(region.max_incidence_deg) + ": they need " + need);
  }
}

}  // namespace ceilplan::mission
