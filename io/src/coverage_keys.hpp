#pragma once
// The coverage keys of a mission file: `camera:`, `surfaces:` and `contact_grid:` (documented in
// docs/coverage.md, "Mission keys"), read with the mission file's strict reader (yaml_reader.hpp):
// every error is one line "FILE: ..." naming the key, unknown keys with the nearest valid one.
// Private to io/: io::readMission puts them in mission::Mission.

#include "yaml_reader.hpp"

#include "ceilplan/mission/camera.hpp"
#include "ceilplan/mission/coverage_region.hpp"

#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io::detail {

/// A mission file's coverage keys as read: camera, surfaces and contact grids.
struct CoverageKeys {
  std::optional<mission::Camera> camera;            ///< key `camera:`
  std::vector<mission::CoverageRegion> surfaces;    ///< key `surfaces:`
  std::vector<mission::ContactGrid> contact_grids;  ///< key `contact_grids:`
};

/// The top-level keys read here: "camera", "surfaces", "contact_grid".
const std::vector<std::string>& coverageKeyNames();

// `camera:` either `preset: NAME` (mission::cameraPresets) with any key below overriding it, or
// sensor_width_mm, sensor_height_mm, image_width_px, image_height_px, focal_length_mm,
// gimbal_pitch_deg [min, max] and min_focus_m; optional mount_offset_m [x, y, z] (0),
// min_photo_interval_s (0), capture {style: hover | move, hover_s, exposure_s, blur_limit_px}.
mission::Camera readCamera(const Section& camera);

// One `surfaces:` entry: name, box {min, max} or prism {polygon, z}, faces, gsd_mm_px,
// overlap {front, side} in percent (default 70, 60), max_incidence_deg (default 45).
mission::CoverageRegion readSurface(const Section& surface);

// One `contact_grid:` entry: name, box or prism, faces, spacing_m, dwell_s, reach_m (default 0.5).
mission::ContactGrid readContactGrid(const Section& grid);

// The three keys of a mission's root map, each optional, checked together: surfaces need a
// camera; names are unique over surfaces and contact grids; the camera can inspect every
// surface (mission::checkCameraReaches). Other keys of the root are not looked at.
CoverageKeys readCoverageKeys(const Section& root);

}  // namespace ceilplan::io::detail
