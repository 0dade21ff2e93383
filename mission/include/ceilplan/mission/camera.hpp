#pragma once
/// @file
/// The inspection camera: a pinhole sensor on a pitch gimbal, fixed to the body at a mount
/// offset. It answers what coverage planning asks of a camera: the ground sample distance (GSD)
/// at a distance and incidence, the footprint, the distance range a required GSD allows, where
/// the camera is for a body pose, and where a point lands in its image. docs/coverage.md, "Camera".

#include "ceilplan/core/error.hpp"

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::mission {

/// Hover: the vehicle stops for every photo. OnTheMove: it shoots while flying, no faster than
/// the motion blur limit allows.
enum class CaptureStyle {
  Hover,     ///< stops for every photo
  OnTheMove  ///< shoots while flying
};

/// The inspection camera (mission key `camera:`, docs/coverage.md): sensor, lens, gimbal range, capture style.
struct Camera {
  std::string name = "custom";    ///< the preset's name, or "custom"
  double sensor_width_mm = 0.0;   ///< along the image width
  double sensor_height_mm = 0.0;  ///< along the image height
  int image_width_px = 0;         ///< pixels across the width
  int image_height_px = 0;        ///< pixels across the height
  double focal_length_mm = 0.0;   ///< lens focal length
  /// Gimbal centre (taken as the optical centre) relative to the body centre, body frame:
  /// x forward, y left, z up.
  Eigen::Vector3d mount_offset_m = Eigen::Vector3d::Zero();
  double gimbal_pitch_min_deg = -90.0;         ///< +90 is straight up, 0 level, -90 straight down
  double gimbal_pitch_max_deg = 90.0;          ///< highest gimbal pitch, degrees
  double min_focus_m = 0.0;                    ///< nearest sharp distance, along the optical axis
  double min_photo_interval_s = 0.0;           ///< shortest time between two photos
  CaptureStyle capture = CaptureStyle::Hover;  ///< hover for each photo, or shoot on the move
  double hover_s = 2.0;                        ///< Hover: time stopped per photo (stop, settle, shoot) [open]
  double exposure_s = 0.001;                   ///< OnTheMove: shutter time
  double blur_limit_px = 0.5;                  ///< OnTheMove: largest motion blur allowed in a photo, pixels

  /// Throws ceilplan::InputError naming the first bad field and its range.
  void validate() const;

  /// Size of one pixel on the sensor: the larger of width / px and height / px (square in
  /// practice; the larger keeps every GSD conservative).
  double pixelPitch_mm() const;
  /// Millimetres of surface per pixel at `distance_m` along the line of sight, on a surface
  /// seen at `incidence_rad` from its normal: distance x pixel pitch / focal length / cos(incidence).
  /// The worst direction of a tilted pixel footprint; conservative off the optical axis too.
  double gsd_mm_px(double distance_m, double incidence_rad = 0.0) const;
  /// The largest distance at which the GSD at `incidence_rad` is at most `gsd_mm_px`.
  double distanceForGsd_m(double gsd_mm_px, double incidence_rad = 0.0) const;
  /// Width and height of the image on a surface square to the optical axis at `distance_m`.
  Eigen::Vector2d footprint_m(double distance_m) const;
  /// Tangents of the half fields of view, across the width and the height.
  double halfWidthTan() const { return 0.5 * sensor_width_mm / focal_length_mm; }
  /// Tangent of the half field of view across the height.
  double halfHeightTan() const { return 0.5 * sensor_height_mm / focal_length_mm; }
  /// Whether the gimbal can point at `pitch_deg` (to within 1e-9 deg).
  bool pitchReachable(double pitch_deg) const;
  /// OnTheMove: the fastest flight at which a photo of GSD `gsd_mm_px` blurs by at most
  /// blur_limit_px: blur_limit_px x GSD / exposure_s. +inf for Hover.
  double maxSpeedForBlur_m_s(double gsd_mm_px) const;
  /// Time the vehicle is stopped for each photo: Hover, the larger of hover_s and the photo
  /// interval; OnTheMove, 0.
  double stopPerPhoto_s() const;
};

/// A body pose and the camera on it. Yaw is the heading in degrees clockwise from north (+y
/// of the map frame; +x is east), as autopilots take it; the gimbal pitches the camera about
/// the body's right axis, so the image's width stays level and its height runs along the
/// heading: flying along the heading, front overlap lies along the image height.
struct CameraPose {
  /// body centre, map frame
  Eigen::Vector3d body_m = Eigen::Vector3d::Zero();
  double yaw_deg = 0.0;           ///< heading, degrees clockwise from north
  double gimbal_pitch_deg = 0.0;  ///< +90 straight up, 0 level, -90 straight down
};

/// Where a camera on a pose is and where it looks: map-frame position and unit axes.
class CameraFrame {
 public:
  /// The camera of `camera` on a body at `pose`.
  CameraFrame(const Camera& camera, const CameraPose& pose);

  /// The optical centre, map frame.
  const Eigen::Vector3d& position_m() const { return position_m_; }
  const Eigen::Vector3d& forward() const { return forward_; }  ///< the optical axis
  const Eigen::Vector3d& right() const { return right_; }      ///< along the image width, level
  const Eigen::Vector3d& up() const { return up_; }            ///< along the image height

  /// Where `point_m` lands in the image, as tangents (right / depth, up / depth), with its depth
  /// along the optical axis; none behind the camera.
  struct ImagePoint {
    double right_tan;  ///< right / depth
    double up_tan;     ///< up / depth
    double depth_m;    ///< along the optical axis
  };
  /// Where `point_m` lands in the image; none behind the camera.
  std::optional<ImagePoint> project(const Eigen::Vector3d& point_m) const;

 private:
  Eigen::Vector3d position_m_, forward_, right_, up_;
};

/// The camera's position for a body at `body_m` heading `yaw_deg`.
Eigen::Vector3d cameraPosition(const Camera& camera, const Eigen::Vector3d& body_m, double yaw_deg);
/// The yaw (heading from north, [0, 360)) and pitch pointing the optical axis along `direction`;
/// a vertical direction keeps `level_yaw_deg`.
std::pair<double, double> yawPitchOf(const Eigen::Vector3d& direction, double level_yaw_deg);

/// A shipped camera: the sensor and lens as their makers publish them.
struct CameraPreset {
  Camera camera;       ///< the camera's sensor and lens
  std::string source;  ///< the published specification it comes from
};
/// The shipped cameras.
const std::vector<CameraPreset>& cameraPresets();
/// Throws ceilplan::InputError listing the presets when `name` is none of them.
const CameraPreset& cameraPreset(const std::string& name);

}  // namespace ceilplan::mission
