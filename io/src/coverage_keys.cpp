#include "coverage_keys.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/point_text.hpp"

#include <algorithm>
#include <set>

namespace ceilplan::io::detail {
namespace {

const Range kCoordinateM = Range::closed(-kMaxPointCoordinate_m, kMaxPointCoordinate_m, "m");

// Reruns a model's own checks, naming where in the file the entry sits.
template <typename Check>
void checked(const Section& at, Check&& check) {
  try {
    check();
  } catch (const InputError& e) {
    at.fail("'" + at.path() + "': " + e.what());
  }
}

mission::FaceSet readFaces(const Section& place) {
  const YAML::Node list = place.required("faces", "down, side and/or up");
  const std::string path = place.keyPath("faces");
  if (!list.IsSequence() || list.size() == 0) place.fail("'" + path + "' must be a non-empty list of down, side, up");
  mission::FaceSet faces;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const std::string kind = place.choiceAt(list[k], path + "[" + std::to_string(k) + "]", {"down", "side", "up"});
    (kind == "down" ? faces.down : kind == "side" ? faces.side : faces.up) = true;
  }
  return faces;
}

// `box: {min, max}` or `prism: {polygon: [[x, y], ...], z: [min, max]}`, exactly one.
mission::RegionShape readShape(const Section& place) {
  if (place.has("box") == place.has("prism"))
    place.fail("'" + place.path() + "' needs exactly one of 'box' {min, max} and 'prism' {polygon, z}");
  if (place.has("box")) {
    const Section box = place.section("box");
    box.allowOnly({"min", "max"});
    return mission::RegionShape::makeBox(box.vector3("min", kCoordinateM), box.vector3("max", kCoordinateM));
  }
  const Section prism = place.section("prism");
  prism.allowOnly({"polygon", "z"});
  const YAML::Node polygon = prism.required("polygon");
  const std::string polygon_path = prism.keyPath("polygon");
  if (!polygon.IsSequence()) prism.fail("'" + polygon_path + "' must be a list of [x, y] vertices");
  std::vector<Eigen::Vector2d> vertices;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const std::vector<double> xy =
        prism.numbersAt(polygon[k], polygon_path + "[" + std::to_string(k) + "]", 2, kCoordinateM);
    vertices.emplace_back(xy[0], xy[1]);
  }
  const std::vector<double> z = prism.numbers("z", 2, kCoordinateM);
  return mission::RegionShape::makePrism(std::move(vertices), z[0], z[1]);
}

// What surfaces and contact grids share: name, box or prism, faces.
void readPlace(const Section& place, std::string& name, mission::RegionShape& shape, mission::FaceSet& faces) {
  name = place.text("name");
  if (name.empty()) place.fail("'" + place.keyPath("name") + "' is empty");
  shape = readShape(place);
  faces = readFaces(place);
}

// Overlap in percent; a value in (0, 1] is a fraction written by mistake.
double readOverlap(const Section& overlap, const std::string& key, double fallback) {
  const double value = overlap.number(key, Range::finite("%"), fallback);
  const std::string path = overlap.keyPath(key);
  if (value > 0.0 && value <= 1.0)
    overlap.fail("'" + path + "' is " + formatNumber(value) +
                 ": overlap is in percent (write 70 for 70 %), and below 100");
  if (value < 0.0 || value >= 100.0)
    overlap.fail("'" + path + "' must lie in [0, 100) %, got " + formatNumber(value) +
                 (value >= 100.0 ? ": photos overlapping 100 % or more never advance" : ""));
  return value;
}

// A non-empty list under `key` of the root, each entry a map read by `read`.
template <typename Read>
void readList(const Section& root, const std::string& key, const std::string& what, Read&& read) {
  const YAML::Node list = root.node()[key];
  if (!list) return;
  if (!list.IsSequence() || list.size() == 0) root.fail("'" + key + "' must be a non-empty list of " + what);
  for (std::size_t k = 0; k < list.size(); ++k)
    read(Section(root.file(), list[k], key + "[" + std::to_string(k) + "]"));
}

}  // namespace

const std::vector<std::string>& coverageKeyNames() {
  static const std::vector<std::string> names{"camera", "surfaces", "contact_grid"};
  return names;
}

mission::Camera readCamera(const Section& node) {
  node.allowOnly({"preset", "sensor_width_mm", "sensor_height_mm", "image_width_px", "image_height_px",
                  "focal_length_mm", "mount_offset_m", "gimbal_pitch_deg", "min_focus_m", "min_photo_interval_s",
                  "capture"});
  mission::Camera camera;
  if (node.has("preset")) {
    std::vector<std::string> names;
    for (const auto& preset : mission::cameraPresets()) names.push_back(preset.camera.name);
    camera = mission::cameraPreset(node.choice("preset", names, "")).camera;
  } else {
    for (const char* key : {"sensor_width_mm", "sensor_height_mm", "image_width_px", "image_height_px",
                            "focal_length_mm", "gimbal_pitch_deg", "min_focus_m"})
      node.required(key, "or give 'preset'");
  }
  const auto number = [&](const char* key, double& field, const char* unit) {
    field = node.number(key, Range::finite(unit), field);
  };
  const auto pixels = [&](const char* key, int& field) {
    field = static_cast<int>(node.integer(key, 1, 1000000, field));
  };
  number("sensor_width_mm", camera.sensor_width_mm, "mm");
  number("sensor_height_mm", camera.sensor_height_mm, "mm");
  pixels("image_width_px", camera.image_width_px);
  pixels("image_height_px", camera.image_height_px);
  number("focal_length_mm", camera.focal_length_mm, "mm");
  number("min_focus_m", camera.min_focus_m, "m");
  number("min_photo_interval_s", camera.min_photo_interval_s, "s");
  if (node.has("mount_offset_m")) {
    const std::vector<double> offset = node.numbers("mount_offset_m", 3, kCoordinateM);
    camera.mount_offset_m = {offset[0], offset[1], offset[2]};
  }
  if (node.has("gimbal_pitch_deg")) {
    const std::vector<double> pitch = node.numbers("gimbal_pitch_deg", 2, Range::finite("deg"));
    camera.gimbal_pitch_min_deg = pitch[0];
    camera.gimbal_pitch_max_deg = pitch[1];
  }
  if (const std::optional<Section> capture = node.optionalSection("capture")) {
    capture->allowOnly({"style", "hover_s", "exposure_s", "blur_limit_px"});
    capture->required("style", "hover or move");
    camera.capture = capture->choice("style", {"hover", "move"}, "") == "hover" ? mission::CaptureStyle::Hover
                                                                                : mission::CaptureStyle::OnTheMove;
    camera.hover_s = capture->number("hover_s", Range::finite("s"), camera.hover_s);
    camera.exposure_s = capture->number("exposure_s", Range::finite("s"), camera.exposure_s);
    camera.blur_limit_px = capture->number("blur_limit_px", Range::finite("px"), camera.blur_limit_px);
  }
  checked(node, [&] { camera.validate(); });
  return camera;
}

mission::CoverageRegion readSurface(const Section& node) {
  node.allowOnly({"name", "box", "prism", "faces", "gsd_mm_px", "overlap", "max_incidence_deg"});
  mission::CoverageRegion region;
  readPlace(node, region.name, region.shape, region.faces);
  region.gsd_mm_px = node.number("gsd_mm_px", Range::finite("mm/px"));
  if (region.gsd_mm_px <= 0.0)
    node.fail("'" + node.keyPath("gsd_mm_px") + "' must be positive, got " + formatNumber(region.gsd_mm_px));
  if (const std::optional<Section> overlap = node.optionalSection("overlap")) {
    overlap->allowOnly({"front", "side"});
    region.overlap_front_pct = readOverlap(*overlap, "front", region.overlap_front_pct);
    region.overlap_side_pct = readOverlap(*overlap, "side", region.overlap_side_pct);
  }
  region.max_incidence_deg = node.number("max_incidence_deg", Range::finite("deg"), region.max_incidence_deg);
  checked(node, [&] { region.validate(); });
  return region;
}

mission::ContactGrid readContactGrid(const Section& node) {
  node.allowOnly({"name", "box", "prism", "faces", "spacing_m", "dwell_s", "reach_m"});
  mission::ContactGrid grid;
  readPlace(node, grid.name, grid.shape, grid.faces);
  grid.spacing_m = node.number("spacing_m", Range::finite("m"));
  grid.dwell_s = node.number("dwell_s", Range::finite("s"));
  grid.reach_m = node.number("reach_m", Range::finite("m"), grid.reach_m);
  checked(node, [&] { grid.validate(); });
  return grid;
}

CoverageKeys readCoverageKeys(const Section& root) {
  CoverageKeys keys;
  if (const std::optional<Section> camera = root.optionalSection("camera")) keys.camera = readCamera(*camera);
  std::set<std::string> names;
  const auto unique = [&](const Section& place, const std::string& name) {
    if (!names.insert(name).second)
      place.fail("'" + place.keyPath("name") + "' repeats '" + name +
                 "': surfaces and contact grids need distinct names");
  };
  std::vector<Section> surfaces;
  readList(root, "surfaces", "regions", [&](const Section& node) {
    keys.surfaces.push_back(readSurface(node));
    unique(node, keys.surfaces.back().name);
    surfaces.push_back(node);
  });
  if (!keys.surfaces.empty()) {
    if (!keys.camera) root.fail("missing key 'camera' (surfaces are photographed: give a 'preset' or the sensor keys)");
    for (std::size_t k = 0; k < keys.surfaces.size(); ++k)
      checked(surfaces[k], [&] { mission::checkCameraReaches(*keys.camera, keys.surfaces[k]); });
  }
  readList(root, "contact_grid", "grids", [&](const Section& node) {
    keys.contact_grids.push_back(readContactGrid(node));
    unique(node, keys.contact_grids.back().name);
  });
  return keys;
}

}  // namespace ceilplan::io::detail
