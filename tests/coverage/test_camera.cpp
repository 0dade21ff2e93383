// The camera model: GSD, footprint and distance range by hand, the pose geometry (yaw from
// north, +90 pitch up, the mount offset turning with the body), presets with sources, and every
// bad field refused by name.

#include "ceilplan/mission/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ceilplan::mission {
namespace {

constexpr double kDegree = M_PI / 180.0;

Camera phantom() { return cameraPreset("phantom4rtk").camera; }

TEST(Camera, GsdIsDistanceTimesPixelPitchOverFocalLength) {
  const Camera camera = phantom();  // 13.2 mm / 5472 px = 2.4123 um pixels, 8.8 mm lens
  EXPECT_NEAR(camera.pixelPitch_mm(), 13.2 / 5472, 1e-12);
  EXPECT_NEAR(camera.gsd_mm_px(10.0), 10000.0 * (13.2 / 5472) / 8.8, 1e-12);  // 2.741 mm/px
  EXPECT_NEAR(camera.gsd_mm_px(10.0, 60.0 * kDegree), 2.0 * camera.gsd_mm_px(10.0), 1e-12);
  EXPECT_NEAR(camera.distanceForGsd_m(camera.gsd_mm_px(3.7)), 3.7, 1e-12);
  EXPECT_NEAR(camera.distanceForGsd_m(camera.gsd_mm_px(3.7, 0.4), 0.4), 3.7, 1e-12);
  // Non-square pixels: the larger pitch rules.
  Camera wide = camera;
  wide.image_height_px = 3000;
  EXPECT_NEAR(wide.pixelPitch_mm(), 8.8 / 3000, 1e-12);
}

TEST(Camera, FootprintFollowsTheFieldOfView) {
  const Camera camera = phantom();
  const Eigen::Vector2d footprint = camera.footprint_m(5.0);
  EXPECT_NEAR(footprint.x(), 5.0 * 13.2 / 8.8, 1e-12);
  EXPECT_NEAR(footprint.y(), 5.0 * 8.8 / 8.8, 1e-12);
  EXPECT_NEAR(camera.halfWidthTan(), 0.75, 1e-12);
}

TEST(Camera, StopsAndSpeedsFollowTheCaptureStyle) {
  Camera camera = phantom();  // photo interval 2 s
  camera.hover_s = 1.0;
  EXPECT_DOUBLE_EQ(camera.stopPerPhoto_s(), 2.0);
  EXPECT_TRUE(std::isinf(camera.maxSpeedForBlur_m_s(1.0)));
  camera.capture = CaptureStyle::OnTheMove;
  camera.exposure_s = 1.0 / 1000;
  camera.blur_limit_px = 0.5;
  EXPECT_DOUBLE_EQ(camera.stopPerPhoto_s(), 0.0);
  EXPECT_NEAR(camera.maxSpeedForBlur_m_s(1.0), 0.5, 1e-12);  // half a 1 mm pixel per ms
}

TEST(Camera, PoseGeometry) {
  Camera camera = phantom();
  camera.mount_offset_m = Eigen::Vector3d(0.2, 0.1, -0.05);  // forward, left, down
  // Heading east (90 deg): forward is +x, left is +y.
  EXPECT_TRUE(cameraPosition(camera, Eigen::Vector3d(1, 2, 3), 90.0).isApprox(Eigen::Vector3d(1.2, 2.1, 2.95), 1e-12));
  // Heading north: forward +y, left -x.
  EXPECT_TRUE(cameraPosition(camera, Eigen::Vector3d(1, 2, 3), 0.0).isApprox(Eigen::Vector3d(0.9, 2.2, 2.95), 1e-12));

  const CameraFrame level(camera, {Eigen::Vector3d::Zero(), 90.0, 0.0});
  EXPECT_TRUE(level.forward().isApprox(Eigen::Vector3d::UnitX(), 1e-12));
  EXPECT_TRUE(level.right().isApprox(-Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE(level.up().isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  const CameraFrame soffit(camera, {Eigen::Vector3d::Zero(), 0.0, 90.0});
  EXPECT_TRUE(soffit.forward().isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
  EXPECT_NEAR(soffit.right().z(), 0.0, 1e-12);  // the width stays level

  // A point 2 m ahead, 0.5 m to the right and 0.3 m up lands at tangents (0.25, 0.15).
  const auto image = level.project(level.position_m() + Eigen::Vector3d(2.0, -0.5, 0.3));
  ASSERT_TRUE(image.has_value());
  EXPECT_NEAR(image->right_tan, 0.25, 1e-12);
  EXPECT_NEAR(image->up_tan, 0.15, 1e-12);
  EXPECT_NEAR(image->depth_m, 2.0, 1e-12);
  EXPECT_FALSE(level.project(level.position_m() - Eigen::Vector3d::UnitX()).has_value());

  const auto [yaw, pitch] = yawPitchOf(Eigen::Vector3d(-1, 0, 1), 0.0);
  EXPECT_NEAR(yaw, 270.0, 1e-9);
  EXPECT_NEAR(pitch, 45.0, 1e-9);
  EXPECT_NEAR(yawPitchOf(Eigen::Vector3d::UnitZ(), 33.0).first, 33.0, 1e-12);  // straight up keeps the level yaw
}

TEST(Camera, EveryPresetIsValidAndCitesItsSource) {
  ASSERT_GE(cameraPresets().size(), 3u);
  for (const CameraPreset& preset : cameraPresets()) {
    EXPECT_NO_THROW(preset.camera.validate()) << preset.camera.name;
    EXPECT_NE(preset.source.find("https://"), std::string::npos) << preset.camera.name;
    EXPECT_EQ(&cameraPreset(preset.camera.name), &preset);
  }
  try {
    cameraPreset("phantom");
    FAIL();
  } catch (const ceilplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("phantom4rtk"), std::string::npos) << e.what();
  }
}

TEST(Camera, RefusesEveryBadFieldByName) {
  const auto refused = [](void (*change)(Camera&), const std::string& field) {
    Camera camera = phantom();
    change(camera);
    try {
      camera.validate();
      ADD_FAILURE() << field << " accepted";
    } catch (const ceilplan::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  refused([](Camera& c) { c.sensor_width_mm = 0.0; }, "sensor_width_mm");
  refused([](Camera& c) { c.sensor_height_mm = NAN; }, "sensor_height_mm");
  refused([](Camera& c) { c.image_width_px = 0; }, "image_width_px");
  refused([](Camera& c) { c.image_height_px = -5; }, "image_height_px");
  refused([](Camera& c) { c.focal_length_mm = INFINITY; }, "focal_length_mm");
  refused([](Camera& c) { c.mount_offset_m.x() = 30.0; }, "mount_offset_m");
  refused([](Camera& c) { c.gimbal_pitch_max_deg = 120.0; }, "gimbal_pitch_deg[1]");
  refused([](Camera& c) { c.gimbal_pitch_min_deg = 40.0; }, "gimbal_pitch_deg");
  refused([](Camera& c) { c.min_focus_m = -1.0; }, "min_focus_m");
  refused([](Camera& c) { c.min_photo_interval_s = 1e9; }, "min_photo_interval_s");
  refused([](Camera& c) { c.exposure_s = 0.0; }, "exposure_s");
  refused([](Camera& c) { c.blur_limit_px = 0.0; }, "blur_limit_px");
}

}  // namespace
}  // namespace ceilplan::mission
