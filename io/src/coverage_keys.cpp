#include "ceilplan/io/coverage_keys.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/yaml_fields.hpp"

#include <limits>
#include <set>

namespace ceilplan::io {
namespace {

constexpr double kAny = std::numeric_limits<double>::max();  // finite; the model's validate() checks the range

// Reruns a model's own checks, naming where in the file the entry sits.
template <typename Check>
void checked(const std::string& path, Check&& check) {
  try {
    check();
  } catch (const ceilplan::InputError& e) {
    throw ceilplan::InputError("'" + path + "': " + e.what());
  }
}

mission::FaceSet readFaces(const YAML::Node& node, const std::string& path) {
  static const std::vector<std::string> kinds{"down", "side", "up"};
  if (!node.IsSequence() || node.size() == 0)
    throw ceilplan::InputError("'" + path + "' must be a non-empty list of down, side, up");
  mission::FaceSet faces;
  for (std::size_t k = 0; k < node.size(); ++k) {
    const std::string item_path = path + "[" + std::to_string(k) + "]";
    const std::string kind = text(node[k], item_path);
    if (kind == "down")
      faces.down = true;
    else if (kind == "side")
      faces.side = true;
    else if (kind == "up")
      faces.up = true;
    else
      throw ceilplan::InputError("'" + item_path + "' is '" + kind + "', not a face kind (did you mean '" +
                                 nearestKey(kind, kinds) + "'?); choose down, side or up");
  }
  return faces;
}

// `box: {min, max}` or `prism: {polygon: [[x, y], ...], z: [min, max]}`, exactly one.
mission::RegionShape readShape(const YAML::Node& node, const std::string& path) {
  const bool box = static_cast<bool>(node["box"]), prism = static_cast<bool>(node["prism"]);
  if (box == prism)
    throw ceilplan::InputError("'" + path + "' needs exactly one of 'box' {min, max} and 'prism' {polygon, z}");
  if (box) {
    const std::string box_path = keyPath(path, "box");
    requireKnownKeys(node["box"], {"min", "max"}, box_path);
    return mission::RegionShape::makeBox(
        point3(requiredKey(node["box"], "min", box_path), box_path + ".min", kMaxPointCoordinate_m),
        point3(requiredKey(node["box"], "max", box_path), box_path + ".max", kMaxPointCoordinate_m));
  }
  const std::string prism_path = keyPath(path, "prism");
  requireKnownKeys(node["prism"], {"polygon", "z"}, prism_path);
  const YAML::Node polygon = requiredKey(node["prism"], "polygon", prism_path);
  const std::string polygon_path = prism_path + ".polygon";
  if (!polygon.IsSequence()) throw ceilplan::InputError("'" + polygon_path + "' must be a list of [x, y] vertices");
  std::vector<Eigen::Vector2d> vertices;
  for (std::size_t k = 0; k < polygon.size(); ++k) {
    const std::vector<double> xy = numbers(polygon[k], polygon_path + "[" + std::to_string(k) + "]", 2,
                                           -kMaxPointCoordinate_m, kMaxPointCoordinate_m, "m");
    vertices.emplace_back(xy[0], xy[1]);
  }
  const std::vector<double> z = numbers(requiredKey(node["prism"], "z", prism_path), prism_path + ".z", 2,
                                        -kMaxPointCoordinate_m, kMaxPointCoordinate_m, "m");
  return mission::RegionShape::makePrism(std::move(vertices), z[0], z[1]);
}

// What surfaces and contact grids share: name, box or prism, faces.
void readPlace(const YAML::Node& node, const std::string& path, std::string& name, mission::RegionShape& shape,
               mission::FaceSet& faces) {
  name = text(requiredKey(node, "name", path), keyPath(path, "name"));
  shape = readShape(node, path);
  faces = readFaces(requiredKey(node, "faces", path, "down, side and/or up"), keyPath(path, "faces"));
}

// Overlap in percent; a value in (0, 1] is a fraction written by mistake.
double readOverlap(const YAML::Node& node, const std::string& path) {
  const double value = numberIn(node, path, -kAny, kAny, "%");
  if (value > 0.0 && value <= 1.0)
    throw ceilplan::InputError("'" + path + "' is " + formatNumber(value) +
                               ": overlap is in percent (write 70 for 70 %), and below 100");
  if (value < 0.0 || value >= 100.0)
    throw ceilplan::InputError("'" + path + "' must lie in [0, 100) %, got " + formatNumber(value) +
                               (value >= 100.0 ? ": photos overlapping 100 % or more never advance" : ""));
  return value;
}

}  // namespace

const std::vector<std::string>& coverageKeyNames() {
  static const std::vector<std::string> names{"camera", "surfaces", "contact_grid"};
  return names;
}

mission::Camera readCamera(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(
      node,
      {"preset", "sensor_width_mm", "sensor_height_mm", "image_width_px", "image_height_px", "focal_length_mm",
       "mount_offset_m", "gimbal_pitch_deg", "min_focus_m", "min_photo_interval_s", "capture"},
      path);
  mission::Camera camera;
  if (node["preset"]) {
    const std::string name = text(node["preset"], keyPath(path, "preset"));
    std::vector<std::string> names;
    for (const auto& preset : mission::cameraPresets()) names.push_back(preset.camera.name);
    if (std::find(names.begin(), names.end(), name) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      throw ceilplan::InputError("'" + keyPath(path, "preset") + "' is '" + name +
                                 "', no shipped camera (did you mean '" + nearestKey(name, names) +
                                 "'?); presets: " + list);
    }
    camera = mission::cameraPreset(name).camera;
  } else {
    for (const char* key : {"sensor_width_mm", "sensor_height_mm", "image_width_px", "image_height_px",
                            "focal_length_mm", "gimbal_pitch_deg", "min_focus_m"})
      requiredKey(node, key, path, "or give 'preset'");
  }
  const auto number = [&](const char* key, double& field) {
    if (node[key]) field = numberIn(node[key], keyPath(path, key), -kAny, kAny, "");
  };
  const auto pixels = [&](const char* key, int& field) {
    if (node[key]) field = static_cast<int>(integerIn(node[key], keyPath(path, key), 1, 1000000, "px"));
  };
  number("sensor_width_mm", camera.sensor_width_mm);
  number("sensor_height_mm", camera.sensor_height_mm);
  pixels("image_width_px", camera.image_width_px);
  pixels("image_height_px", camera.image_height_px);
  number("focal_length_mm", camera.focal_length_mm);
  number("min_focus_m", camera.min_focus_m);
  number("min_photo_interval_s", camera.min_photo_interval_s);
  if (node["mount_offset_m"]) camera.mount_offset_m = point3(node["mount_offset_m"], keyPath(path, "mount_offset_m"));
  if (node["gimbal_pitch_deg"]) {
    const std::vector<double> pitch =
        numbers(node["gimbal_pitch_deg"], keyPath(path, "gimbal_pitch_deg"), 2, -kAny, kAny, "deg");
    camera.gimbal_pitch_min_deg = pitch[0];
    camera.gimbal_pitch_max_deg = pitch[1];
  }
  if (node["capture"]) {
    const std::string capture_path = keyPath(path, "capture");
    const YAML::Node capture = node["capture"];
    requireKnownKeys(capture, {"style", "hover_s", "exposure_s", "blur_limit_px"}, capture_path);
    const std::string style =
        text(requiredKey(capture, "style", capture_path, "hover or move"), capture_path + ".style");
    if (style == "hover")
      camera.capture = mission::CaptureStyle::Hover;
    else if (style == "move")
      camera.capture = mission::CaptureStyle::OnTheMove;
    else
      throw ceilplan::InputError("'" + capture_path + ".style' is '" + style + "' (did you mean '" +
                                 nearestKey(style, {"hover", "move"}) + "'?); choose hover or move");
    if (capture["hover_s"]) camera.hover_s = numberIn(capture["hover_s"], capture_path + ".hover_s", -kAny, kAny, "");
    if (capture["exposure_s"])
      camera.exposure_s = numberIn(capture["exposure_s"], capture_path + ".exposure_s", -kAny, kAny, "");
    if (capture["blur_limit_px"])
      camera.blur_limit_px = numberIn(capture["blur_limit_px"], capture_path + ".blur_limit_px", -kAny, kAny, "");
  }
  camera.validate();
  return camera;
}

mission::CoverageRegion readSurface(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, {"name", "box", "prism", "faces", "gsd_mm_px", "overlap", "max_incidence_deg"}, path);
  mission::CoverageRegion region;
  readPlace(node, path, region.name, region.shape, region.faces);
  region.gsd_mm_px = numberIn(requiredKey(node, "gsd_mm_px", path), keyPath(path, "gsd_mm_px"), -kAny, kAny, "mm/px");
  if (region.gsd_mm_px <= 0.0)
    throw ceilplan::InputError("'" + keyPath(path, "gsd_mm_px") + "' must be positive, got " +
                               formatNumber(region.gsd_mm_px));
  if (node["overlap"]) {
    const std::string overlap_path = keyPath(path, "overlap");
    requireKnownKeys(node["overlap"], {"front", "side"}, overlap_path);
    if (node["overlap"]["front"])
      region.overlap_front_pct = readOverlap(node["overlap"]["front"], overlap_path + ".front");
    if (node["overlap"]["side"]) region.overlap_side_pct = readOverlap(node["overlap"]["side"], overlap_path + ".side");
  }
  if (node["max_incidence_deg"])
    region.max_incidence_deg =
        numberIn(node["max_incidence_deg"], keyPath(path, "max_incidence_deg"), -kAny, kAny, "deg");
  checked(path, [&] { region.validate(); });
  return region;
}

mission::ContactGrid readContactGrid(const YAML::Node& node, const std::string& path) {
  requireKnownKeys(node, {"name", "box", "prism", "faces", "spacing_m", "dwell_s", "reach_m"}, path);
  mission::ContactGrid grid;
  readPlace(node, path, grid.name, grid.shape, grid.faces);
  grid.spacing_m = numberIn(requiredKey(node, "spacing_m", path), keyPath(path, "spacing_m"), -kAny, kAny, "m");
  grid.dwell_s = numberIn(requiredKey(node, "dwell_s", path), keyPath(path, "dwell_s"), -kAny, kAny, "s");
  if (node["reach_m"]) grid.reach_m = numberIn(node["reach_m"], keyPath(path, "reach_m"), -kAny, kAny, "m");
  checked(path, [&] { grid.validate(); });
  return grid;
}

CoverageKeys readCoverageKeys(const YAML::Node& root) {
  CoverageKeys keys;
  if (root["camera"]) keys.camera = readCamera(root["camera"], "camera");
  std::set<std::string> names;
  const auto unique = [&](const std::string& name, const std::string& path) {
    if (!names.insert(name).second)
      throw ceilplan::InputError("'" + path + ".name' repeats '" + name +
                                 "': surfaces and contact grids need distinct names");
  };
  if (const YAML::Node list = root["surfaces"]) {
    if (!list.IsSequence() || list.size() == 0)
      throw ceilplan::InputError("'surfaces' must be a non-empty list of regions");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string path = "surfaces[" + std::to_string(k) + "]";
      keys.surfaces.push_back(readSurface(list[k], path));
      unique(keys.surfaces.back().name, path);
    }
    if (!keys.camera)
      throw ceilplan::InputError(
          "missing key 'camera' (surfaces are photographed: give a 'preset' or the sensor keys)");
    for (std::size_t k = 0; k < keys.surfaces.size(); ++k)
      checked("surfaces[" + std::to_string(k) + "]",
              [&] { mission::checkCameraReaches(*keys.camera, keys.surfaces[k]); });
  }
  if (const YAML::Node list = root["contact_grid"]) {
    if (!list.IsSequence() || list.size() == 0)
      throw ceilplan::InputError("'contact_grid' must be a non-empty list of grids");
    for (std::size_t k = 0; k < list.size(); ++k) {
      const std::string path = "contact_grid[" + std::to_string(k) + "]";
      keys.contact_grids.push_back(readContactGrid(list[k], path));
      unique(keys.contact_grids.back().name, path);
    }
  }
  return keys;
}

}  // namespace ceilplan::io
