// The coverage keys of a mission file: every shipped coverage mission reads, the keys land in
// the model, and each out-of-range value of docs/coverage.md ("Mission keys") and the usual bad
// inputs are refused naming the key, unknown keys with the nearest valid one.

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/spelling.hpp"
#include "ceilplan/io/mission_file.hpp"

#include "run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace ceilplan::io {
namespace {

const std::filesystem::path kCoverageMissions = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps" / "coverage";

const char* const kMission = R"(
camera:
  sensor_width_mm: 13.2
  sensor_height_mm: 8.8
  image_width_px: 5472
  image_height_px: 3648
  focal_length_mm: 8.8
  mount_offset_m: [0.1, 0.0, 0.05]
  gimbal_pitch_deg: [-30, 90]
  min_focus_m: 1.0
  min_photo_interval_s: 2.0
  capture: {style: move, exposure_s: 0.0005, blur_limit_px: 0.4}
surfaces:
  - name: soffit
    box: {min: [0, -4, 5.95], max: [48, 4, 6.05]}
    faces: [down, side]
    gsd_mm_px: 1.5
    overlap: {front: 75, side: 65}
    max_incidence_deg: 40
  - name: pier_face
    prism: {polygon: [[15, -5], [17, -5], [17, 5], [15, 5]], z: [0, 4.2]}
    faces: [side]
    gsd_mm_px: 2.0
contact_grid:
  - {name: deck_thickness, box: {min: [2, -1.2, 5.95], max: [14, 1.2, 6.05]}, faces: [down], spacing_m: 1.0, dwell_s: 10}
)";

// The coverage keys in `yaml` as the mission reader reads them, in a mission with the bridge's
// map and a point target (so a camera alone is a mission too).
mission::Mission readKeys(const std::string& yaml) {
  const std::filesystem::path maps = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps";
  // One directory per test: ctest runs the tests in parallel processes.
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::filesystem::path file = testing::scratchDirectory("coverage_keys_" + test) / "mission.yaml";
  std::ofstream(file) << "map: " << (maps / "bridge.bt").string()
                      << "\nvehicle: " << (maps / "vehicles/quad.yaml").string()
                      << "\nbattery: {capacity_ah: 5.2, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 10.4}\n"
                         "home: [-4.0, 0.0, 0.5]\n"
                         "targets:\n  - {name: deck, point: [6.0, 0.0, 6.0], dwell_s: 20, standoff_m: [0.3, 1.5]}\n"
                      << yaml;
  return readMission(file);
}

std::string errorOf(const std::string& yaml) {
  try {
    readKeys(yaml);
  } catch (const ceilplan::InputError& e) {
    return e.what();
  }
  return "no error";
}

// kMission with `from` replaced by `to`.
std::string with(const std::string& from, const std::string& to) {
  std::string text = kMission;
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("'" + from + "' not in the test mission");
  return text.replace(at, from.size(), to);
}

TEST(CoverageKeys, ReadsEveryKey) {
  const mission::Mission keys = readKeys(kMission);
  ASSERT_TRUE(keys.camera.has_value());
  const mission::Camera& camera = *keys.camera;
  EXPECT_EQ(camera.name, "custom");
  EXPECT_DOUBLE_EQ(camera.sensor_width_mm, 13.2);
  EXPECT_EQ(camera.image_height_px, 3648);
  EXPECT_EQ(camera.mount_offset_m, Eigen::Vector3d(0.1, 0.0, 0.05));
  EXPECT_DOUBLE_EQ(camera.gimbal_pitch_min_deg, -30.0);
  EXPECT_DOUBLE_EQ(camera.gimbal_pitch_max_deg, 90.0);
  EXPECT_DOUBLE_EQ(camera.min_photo_interval_s, 2.0);
  EXPECT_EQ(camera.capture, mission::CaptureStyle::OnTheMove);
  EXPECT_DOUBLE_EQ(camera.exposure_s, 0.0005);
  EXPECT_DOUBLE_EQ(camera.blur_limit_px, 0.4);
  ASSERT_EQ(keys.surfaces.size(), 2u);
  const mission::CoverageRegion& soffit = keys.surfaces[0];
  EXPECT_EQ(soffit.name, "soffit");
  EXPECT_EQ(soffit.shape.kind, mission::RegionShape::Kind::Box);
  EXPECT_EQ(soffit.shape.box.max(), Eigen::Vector3d(48, 4, 6.05));
  EXPECT_TRUE(soffit.faces.down && soffit.faces.side && !soffit.faces.up);
  EXPECT_DOUBLE_EQ(soffit.gsd_mm_px, 1.5);
  EXPECT_DOUBLE_EQ(soffit.overlap_front_pct, 75.0);
  EXPECT_DOUBLE_EQ(soffit.overlap_side_pct, 65.0);
  EXPECT_DOUBLE_EQ(soffit.max_incidence_deg, 40.0);
  const mission::CoverageRegion& pier = keys.surfaces[1];
  EXPECT_EQ(pier.shape.kind, mission::RegionShape::Kind::Prism);
  EXPECT_EQ(pier.shape.polygon_m.size(), 4u);
  EXPECT_DOUBLE_EQ(pier.overlap_front_pct, 70.0);  // defaults
  EXPECT_DOUBLE_EQ(pier.overlap_side_pct, 60.0);
  EXPECT_DOUBLE_EQ(pier.max_incidence_deg, 45.0);
  ASSERT_EQ(keys.contact_grids.size(), 1u);
  EXPECT_DOUBLE_EQ(keys.contact_grids[0].spacing_m, 1.0);
  EXPECT_DOUBLE_EQ(keys.contact_grids[0].dwell_s, 10.0);
  EXPECT_DOUBLE_EQ(keys.contact_grids[0].reach_m, 0.5);
}

TEST(CoverageKeys, PresetsAreOverridden) {
  const mission::Mission keys =
      readKeys("camera: {preset: zenmuse_p1_35mm, gimbal_pitch_deg: [-40, 90], min_focus_m: 2}\n");
  EXPECT_EQ(keys.camera->name, "zenmuse_p1_35mm");
  EXPECT_DOUBLE_EQ(keys.camera->focal_length_mm, 35.0);
  EXPECT_DOUBLE_EQ(keys.camera->gimbal_pitch_min_deg, -40.0);
  EXPECT_DOUBLE_EQ(keys.camera->min_focus_m, 2.0);
}

TEST(CoverageKeys, EveryShippedCoverageMissionReads) {
  int missions = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kCoverageMissions)) {
    if (entry.path().extension() != ".yaml") continue;
    ++missions;
    const mission::Mission keys = readMission(entry.path());
    EXPECT_FALSE(keys.surfaces.empty() && keys.contact_grids.empty()) << entry.path();
  }
  EXPECT_EQ(missions, 4);
}

TEST(CoverageKeys, DocumentedBadInputsNameTheKey) {
  // A camera that cannot reach the GSD beyond its minimum focus: 0.2 mm/px needs 0.73 m.
  EXPECT_NE(
      errorOf(with("gsd_mm_px: 1.5", "gsd_mm_px: 0.2")).find("'surfaces[0]': surface region 'soffit': 'gsd_mm_px' 0.2"),
      std::string::npos);
  EXPECT_NE(errorOf(with("gsd_mm_px: 1.5", "gsd_mm_px: 0.2")).find("'camera.min_focus_m' 1 m"), std::string::npos);
  // A region with no surface in it is found with the map: mission::planCoverage (test_coverage_plan).
  // Overlap of 100 % or more.
  EXPECT_NE(
      errorOf(with("front: 75", "front: 100")).find("'surfaces[0].overlap.front' must lie in [0, 100) %, got 100"),
      std::string::npos);
  EXPECT_NE(errorOf(with("side: 65", "side: 0.65")).find("'surfaces[0].overlap.side' is 0.65: overlap is in percent"),
            std::string::npos);
  // GSD <= 0.
  EXPECT_NE(errorOf(with("gsd_mm_px: 1.5", "gsd_mm_px: 0")).find("'surfaces[0].gsd_mm_px' must be positive, got 0"),
            std::string::npos);
  EXPECT_NE(errorOf(with("gsd_mm_px: 1.5", "gsd_mm_px: -2")).find("'surfaces[0].gsd_mm_px' must be positive"),
            std::string::npos);
  // A gimbal that cannot point at the region's faces.
  const std::string gimbal = errorOf(with("gimbal_pitch_deg: [-30, 90]", "gimbal_pitch_deg: [-90, 30]"));
  EXPECT_NE(gimbal.find("'surfaces[0]'"), std::string::npos) << gimbal;
  EXPECT_NE(gimbal.find("'faces' includes down, but 'camera.gimbal_pitch_deg' [-90, 30]"), std::string::npos) << gimbal;
}

TEST(CoverageKeys, UnknownKeysNameTheNearestValidOne) {
  // The one reader's wording (io/src/yaml_reader.hpp), as for every other key of the mission file.
  EXPECT_NE(errorOf(with("gsd_mm_px: 1.5", "gsd_mm: 1.5"))
                .find("unknown key 'surfaces[0].gsd_mm'; did you mean 'gsd_mm_px'?"),
            std::string::npos);
  EXPECT_NE(
      errorOf(with("min_focus_m", "min_focus")).find("unknown key 'camera.min_focus'; did you mean 'min_focus_m'?"),
      std::string::npos);
  EXPECT_NE(errorOf(with("overlap: {front", "overlap: {frnot"))
                .find("unknown key 'surfaces[0].overlap.frnot'; did you mean 'front'?"),
            std::string::npos);
  EXPECT_NE(errorOf(with("spacing_m", "spaceing_m")).find("'contact_grid[0].spaceing_m'; did you mean 'spacing_m'"),
            std::string::npos);
  EXPECT_NE(errorOf(with("faces: [down, side]", "faces: [dwn, side]"))
                .find("'surfaces[0].faces[0]' must be one of down, side, up, got 'dwn'; did you mean 'down'?"),
            std::string::npos);
  EXPECT_NE(errorOf(with("style: move", "style: hoover")).find("did you mean 'hover'"), std::string::npos);
  EXPECT_NE(errorOf("camera: {preset: phantom4}\n").find("did you mean 'phantom4rtk'"), std::string::npos);
  EXPECT_EQ(closestMatch("GSD_MM_PX", {"gsd_mm_px", "name"}), "gsd_mm_px");
  EXPECT_EQ(closestMatch("nmae", {"faces", "name"}), "name");  // a swap of neighbours is one edit
}

TEST(CoverageKeys, NumbersAreCheckedWithTheirRanges) {
  EXPECT_NE(errorOf(with("sensor_width_mm: 13.2", "sensor_width_mm: .nan"))
                .find("'camera.sensor_width_mm' must be a finite number"),
            std::string::npos);
  EXPECT_NE(
      errorOf(with("sensor_width_mm: 13.2", "sensor_width_mm: wide")).find("'camera.sensor_width_mm' must be a number"),
      std::string::npos);
  EXPECT_NE(errorOf(with("sensor_width_mm: 13.2", "sensor_width_mm: 0"))
                .find("camera 'sensor_width_mm' must lie in [1, 100] mm"),
            std::string::npos);
  EXPECT_NE(errorOf(with("image_width_px: 5472", "image_width_px: 54.5"))
                .find("'camera.image_width_px' must be a whole number"),
            std::string::npos);
  EXPECT_NE(
      errorOf(with("max_incidence_deg: 40", "max_incidence_deg: 95")).find("'max_incidence_deg' must lie in (0, 89]"),
      std::string::npos);
  EXPECT_NE(errorOf(with("mount_offset_m: [0.1, 0.0, 0.05]", "mount_offset_m: [0.1, 0.0]"))
                .find("'camera.mount_offset_m' must be a list of 3 numbers"),
            std::string::npos);
  EXPECT_NE(
      errorOf(with("dwell_s: 10", "dwell_s: -1")).find("'contact_grid[0]': contact grid 'deck_thickness': 'dwell_s'"),
      std::string::npos);
  EXPECT_NE(errorOf(with("[15, 5]], z: [0, 4.2]", "[15, 5]], z: [4.2, 0]")).find("'prism.z' must be [min, max]"),
            std::string::npos);
  EXPECT_NE(errorOf(with("box: {min: [0, -4, 5.95], max: [48, 4, 6.05]}", ""))
                .find("'surfaces[0]' needs exactly one of 'box'"),
            std::string::npos);
}

TEST(CoverageKeys, MissingAndRepeatedKeys) {
  EXPECT_NE(
      errorOf(with("  focal_length_mm: 8.8\n", "")).find("missing key 'camera.focal_length_mm' (or give 'preset')"),
      std::string::npos);
  EXPECT_NE(errorOf(with("- name: pier_face", "- name: soffit")).find("'surfaces[1].name' repeats 'soffit'"),
            std::string::npos);
  EXPECT_NE(errorOf("surfaces:\n  - {name: a, box: {min: [0, 0, 0], max: [1, 1, 1]}, faces: [down], gsd_mm_px: 1}")
                .find("missing key 'camera'"),
            std::string::npos);
  EXPECT_NE(errorOf("surfaces: []").find("'surfaces' must be a non-empty list"), std::string::npos);
  EXPECT_NE(errorOf("camera: [1, 2]").find("'camera' must be a map"), std::string::npos);
}

}  // namespace
}  // namespace ceilplan::io
