#include "ceilplan/mission/camera.hpp"

#include "ceilplan/core/format.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ceilplan::mission {
namespace {

constexpr double kDegree = M_PI / 180.0;

void requireRange(double value, double lo, double hi, const std::string& field, const std::string& unit) {
  if (!(std::isfinite(value) && value >= lo && value <= hi))
    throw ceilplan::InputError("camera '" + field + "' must lie in [" + formatNumber(lo) + ", " + formatNumber(hi) +
                               "] " + unit + ", got " + formatNumber(value));
}

// A preset's published numbers: sensor (mm), image (px), focal length (mm), gimbal pitch range
// (deg, as mounted below the vehicle), closest focus (m), shortest photo interval (s).
struct PresetSpec {
  const char* name;
  double sensor_width_mm, sensor_height_mm;
  int image_width_px, image_height_px;
  double focal_length_mm;
  double pitch_min_deg, pitch_max_deg;
  double min_focus_m, min_photo_interval_s;
  const char* source;
};

// The makers' specification pages, as cited. Values a maker does not publish are marked [open]
// here and in docs/coverage.md, with conservative defaults.
// - DJI Phantom 4 RTK: 1" CMOS (13.2 x 8.8 mm), 5472 x 3648 px, 8.8 mm lens (24 mm equivalent),
//   autofocus from 1 m, gimbal pitch -90 to +30 deg, interval shooting from 2 s.
// - DJI Zenmuse P1 with the DL 35 mm F2.8 LS ASPH lens: full frame 35.9 x 24 mm, 8192 x 5460 px,
//   minimum photo interval 0.7 s, gimbal tilt -125 to +40 deg (the camera points from -90 to
//   +40); the lens's closest focus is not on the sheet: 1 m [open].
// - DJI Zenmuse H20 wide camera: 1/2.3" CMOS (6.17 x 4.55 mm), 4056 x 3040 px, 4.5 mm lens (24 mm
//   equivalent), gimbal tilt -120 to +30 deg; closest focus and shortest interval are not on the
//   sheet: 0.5 m and 1 s [open].
constexpr PresetSpec kPresets[] = {
    {"phantom4rtk", 13.2, 8.8, 5472, 3648, 8.8, -90.0, 30.0, 1.0, 2.0,
     "DJI Phantom 4 RTK specifications, https://www.dji.com/phantom-4-rtk/specs"},
    {"zenmuse_p1_35mm", 35.9, 24.0, 8192, 5460, 35.0, -90.0, 40.0, 1.0, 0.7,
     "DJI Zenmuse P1 specifications, https://enterprise.dji.com/zenmuse-p1/specs"},
    {"zenmuse_h20_wide", 6.17, 4.55, 4056, 3040, 4.5, -90.0, 30.0, 0.5, 1.0,
     "DJI Zenmuse H20 series specifications, https://enterprise.dji.com/zenmuse-h20-series/specs"},
};

std::vector<CameraPreset> makePresets() {
  std::vector<CameraPreset> presets;
  for (const PresetSpec& spec : kPresets) {
    Camera camera;
    camera.name = spec.name;
    camera.sensor_width_mm = spec.sensor_width_mm;
    camera.sensor_height_mm = spec.sensor_height_mm;
    camera.image_width_px = spec.image_width_px;
    camera.image_height_px = spec.image_height_px;
    camera.focal_length_mm = spec.focal_length_mm;
    camera.gimbal_pitch_min_deg = spec.pitch_min_deg;
    camera.gimbal_pitch_max_deg = spec.pitch_max_deg;
    camera.min_focus_m = spec.min_focus_m;
    camera.min_photo_interval_s = spec.min_photo_interval_s;
    presets.push_back({camera, spec.source});
  }
  return presets;
}

}  // namespace

void Camera::validate() const {
  requireRange(sensor_width_mm, 1.0, 100.0, "sensor_width_mm", "mm");
  requireRange(sensor_height_mm, 1.0, 100.0, "sensor_height_mm", "mm");
  if (image_width_px < 16 || image_width_px > 100000)
    throw ceilplan::InputError("camera 'image_width_px' must lie in [16, 100000] px, got " +
                               std::to_string(image_width_px));
  if (image_height_px < 16 || image_height_px > 100000)
    throw ceilplan::InputError("camera 'image_height_px' must lie in [16, 100000] px, got " +
                               std::to_string(image_height_px));
  requireRange(focal_length_mm, 1.0, 1000.0, "focal_length_mm", "mm");
  if (!mount_offset_m.allFinite() || mount_offset_m.cwiseAbs().maxCoeff() > 2.0)
    throw ceilplan::InputError("camera 'mount_offset_m' must be [x, y, z] within 2 m of the body centre, got " +
                               formatPoint(mount_offset_m));
  requireRange(gimbal_pitch_min_deg, -90.0, 90.0, "gimbal_pitch_deg[0]", "deg");
  requireRange(gimbal_pitch_max_deg, -90.0, 90.0, "gimbal_pitch_deg[1]", "deg");
  if (gimbal_pitch_min_deg > gimbal_pitch_max_deg)
    throw ceilplan::InputError("camera 'gimbal_pitch_deg' must be [min, max] with min <= max, got [" +
                               formatNumber(gimbal_pitch_min_deg) + ", " + formatNumber(gimbal_pitch_max_deg) + "]");
  requireRange(min_focus_m, 0.0, 100.0, "min_focus_m", "m");
  requireRange(min_photo_interval_s, 0.0, 600.0, "min_photo_interval_s", "s");
  requireRange(hover_s, 0.0, 600.0, "capture.hover_s", "s");
  requireRange(exposure_s, 1e-6, 1.0, "capture.exposure_s", "s");
  requireRange(blur_limit_px, 0.01, 100.0, "capture.blur_limit_px", "px");
}

double Camera::pixelPitch_mm() const {
  return std::max(sensor_width_mm / image_width_px, sensor_height_mm / image_height_px);
}

double Camera::gsd_mm_px(double distance_m, double incidence_rad) const {
  return distance_m * 1000.0 * pixelPitch_mm() / focal_length_mm / std::cos(incidence_rad);
}

double Camera::distanceForGsd_m(double gsd, double incidence_rad) const {
  return gsd * focal_length_mm * std::cos(incidence_rad) / (1000.0 * pixelPitch_mm());
}

Eigen::Vector2d Camera::footprint_m(double distance_m) const {
  return {2.0 * distance_m * halfWidthTan(), 2.0 * distance_m * halfHeightTan()};
}

bool Camera::pitchReachable(double pitch_deg) const {
  return pitch_deg >= gimbal_pitch_min_deg - 1e-9 && pitch_deg <= gimbal_pitch_max_deg + 1e-9;
}

double Camera::maxSpeedForBlur_m_s(double gsd) const {
  if (capture == CaptureStyle::Hover) return std::numeric_limits<double>::infinity();
  return blur_limit_px * gsd / 1000.0 / exposure_s;
}

double Camera::stopPerPhoto_s() const {
  return capture == CaptureStyle::Hover ? std::max(hover_s, min_photo_interval_s) : 0.0;
}

CameraFrame::CameraFrame(const Camera& camera, const CameraPose& pose) {
  const double yaw = pose.yaw_deg * kDegree, pitch = pose.gimbal_pitch_deg * kDegree;
  position_m_ = cameraPosition(camera, pose.body_m, pose.yaw_deg);
  forward_ = Eigen::Vector3d(std::cos(pitch) * std::sin(yaw), std::cos(pitch) * std::cos(yaw), std::sin(pitch));
  right_ = Eigen::Vector3d(std::cos(yaw), -std::sin(yaw), 0.0);
  up_ = right_.cross(forward_);
}

std::optional<CameraFrame::ImagePoint> CameraFrame::project(const Eigen::Vector3d& point_m) const {
  const Eigen::Vector3d offset = point_m - position_m_;
  const double depth = offset.dot(forward_);
  if (!(depth > 0.0)) return std::nullopt;
  return ImagePoint{offset.dot(right_) / depth, offset.dot(up_) / depth, depth};
}

Eigen::Vector3d cameraPosition(const Camera& camera, const Eigen::Vector3d& body_m, double yaw_deg) {
  const double yaw = yaw_deg * kDegree;
  const Eigen::Vector3d forward(std::sin(yaw), std::cos(yaw), 0.0), left(-std::cos(yaw), std::sin(yaw), 0.0);
  const Eigen::Vector3d& m = camera.mount_offset_m;
  return body_m + forward * m.x() + left * m.y() + Eigen::Vector3d::UnitZ() * m.z();
}

std::pair<double, double> yawPitchOf(const Eigen::Vector3d& direction, double level_yaw_deg) {
  const Eigen::Vector3d d = direction.normalized();
  const double pitch_deg = std::asin(std::clamp(d.z(), -1.0, 1.0)) / kDegree;
  const double horizontal = std::hypot(d.x(), d.y());
  if (horizontal < 1e-9) return {level_yaw_deg, pitch_deg};
  double yaw_deg = std::atan2(d.x(), d.y()) / kDegree;
  if (yaw_deg < 0.0) yaw_deg += 360.0;
  return {yaw_deg, pitch_deg};
}

const std::vector<CameraPreset>& cameraPresets() {
  static const std::vector<CameraPreset> presets = makePresets();
  return presets;
}

const CameraPreset& cameraPreset(const std::string& name) {
  std::string names;
  for (const CameraPreset& preset : cameraPresets()) {
    if (preset.camera.name == name) return preset;
    names += (names.empty() ? "" : ", ") + preset.camera.name;
  }
  throw ceilplan::InputError("unknown camera preset '" + name + "'; choose one of " + names);
}

}  // namespace ceilplan::mission
