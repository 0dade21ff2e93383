#include "ceilplan/io/dji_wpml.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/io/atomic_file.hpp"
#include "ceilplan/io/autopilot_export.hpp"

#include <minizip/zip.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace ceilplan::io {
namespace {

constexpr const char* kKmlNamespace = "http://www.opengis.net/kml/2.2";
constexpr const char* kWpmlNamespace = "http://www.dji.com/wpmz/1.0.2";

// Heading in WPML's range, (-180, 180].
double signedHeading(double heading_deg) {
  const double h = std::remainder(heading_deg, 360.0);
  return h <= -180.0 ? h + 360.0 : h;
}

std::string number(double value, int decimals = 6) {
  std::string text = formatFixed(value, decimals);
  // Trim trailing zeros for readability: "2.500000" -> "2.5".
  if (text.find('.') != std::string::npos) {
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
  }
  return text == "-0" ? "0" : text;
}

// DJI's ranges (WPML template.kml and common elements tables, docs/flying.md).
constexpr double kMinSpeed_m_s = 1.0, kMaxSpeed_m_s = 15.0;  // waypointSpeed, autoFlightSpeed, globalTransitionalSpeed
constexpr double kMinTakeOffSecurityHeight_m = 1.2;          // takeOffSecurityHeight with a remote controller

// Everything both files are written from.
struct Plan {
  Plan(const mission::SortieRoute& r, const mission::GeodeticOrigin& o, const DjiWpmlOptions& opts)
      : route(r), origin(o), options(opts), home_geodetic(toGeodetic(o, r.home_m)) {}

  const mission::SortieRoute& route;
  const mission::GeodeticOrigin& origin;
  const DjiWpmlOptions& options;
  Eigen::Vector3d home_geodetic;
  std::vector<Eigen::Vector3d> positions_m;  // per waypoint as flown: the last at the landing height
  std::vector<Eigen::Vector3d> geodetic;     // of positions_m
  std::vector<double> headings_deg;          // in effect
  std::vector<double> pitches_deg;           // in effect
  std::vector<double> speeds_m_s;            // waypointSpeed as written
  double cruise_speed_m_s = 0.0;             // autoFlightSpeed and globalTransitionalSpeed as written
  double takeoff_security_height_m = 0.0;
  std::vector<DjiClamp> clamps;

  // `value` within [min, max]; a value outside is recorded as clamped.
  double within(double value, double min, double max, std::size_t waypoint, const char* element) {
    const double written = std::clamp(value, min, max);
    if (written != value) clamps.push_back({route.sortie, waypoint, element, value, written});
    return written;
  }
};

class Writer {
 public:
  explicit Writer(const Plan& plan) : plan_(plan) {}

  std::string document(bool is_template) {
    tinyxml2::XMLPrinter xml;
    xml_ = &xml;
    action_group_id_ = 0;
    xml.PushHeader(false, true);
    xml.OpenElement("kml");
    xml.PushAttribute("xmlns", kKmlNamespace);
    xml.PushAttribute("xmlns:wpml", kWpmlNamespace);
    xml.OpenElement("Document");
    if (is_template) text("wpml:author", "ceilplan");  // creation information: template.kml only
    missionConfig();
    xml.OpenElement("Folder");
    if (is_template) {
      templateFolderHeader();
    } else {
      waylinesFolderHeader();
    }
    for (std::size_t k = 0; k < plan_.route.waypoints.size(); ++k) placemark(k, is_template);
    xml.CloseElement();  // Folder
    xml.CloseElement();  // Document
    xml.CloseElement();  // kml
    xml_ = nullptr;
    return xml.CStr();
  }

 private:
  void text(const char* element, const std::string& value) {
    xml_->OpenElement(element);
    xml_->PushText(value.c_str());
    xml_->CloseElement();
  }
  void element(const char* name, const std::function<void()>& children) {
    xml_->OpenElement(name);
    children();
    xml_->CloseElement();
  }

  bool relative() const { return plan_.options.height_mode == DjiHeightMode::RelativeToTakeoff; }
  double heightAboveTakeoff(std::size_t k) const { return plan_.positions_m[k].z() - plan_.route.home_m.z(); }
  double seaLevelHeight(std::size_t k) const { return plan_.geodetic[k].z(); }
  double ellipsoidHeight(std::size_t k) const {
    return seaLevelHeight(k) + plan_.options.geoid_separation_m.value_or(0.0);
  }

  void missionConfig() {
    const DjiWpmlOptions& o = plan_.options;
    element("wpml:missionConfig", [&] {
      // Climb straight up to the first waypoint's height, then fly level to it.
      text("wpml:flyToWaylineMode", "safely");
      text("wpml:finishAction", o.finish_action);
      text("wpml:exitOnRCLost", "executeLostAction");
      text("wpml:executeRCLostAction", o.rc_lost_action);
      text("wpml:takeOffSecurityHeight", number(plan_.takeoff_security_height_m, 3));
      text("wpml:takeOffRefPoint", number(plan_.home_geodetic.x(), 9) + "," + number(plan_.home_geodetic.y(), 9) + "," +
                                       number(plan_.home_geodetic.z(), 3));
      text("wpml:globalTransitionalSpeed", number(plan_.cruise_speed_m_s, 3));
      text("wpml:globalRTHHeight", number(o.rth_height_m, 3));
      element("wpml:droneInfo", [&] {
        text("wpml:droneEnumValue", std::to_string(o.drone_enum));
        text("wpml:droneSubEnumValue", std::to_string(o.drone_sub_enum));
      });
      element("wpml:payloadInfo", [&] {
        text("wpml:payloadEnumValue", std::to_string(o.payload_enum));
        text("wpml:payloadPositionIndex", std::to_string(o.payload_position));
      });
    });
  }

  // Straight to the point and stop there: no corner is cut (damping distance and straight-line
  // flags apply only to the turning modes, and are left out).
  static constexpr const char* kTurnMode = "toPointAndStopWithDiscontinuityCurvature";

  void templateFolderHeader() {
    text("wpml:templateType", "waypoint");
    text("wpml:templateId", "0");
    element("wpml:waylineCoordinateSysParam", [&] {
      text("wpml:coordinateMode", "WGS84");
      text("wpml:heightMode", relative() ? "relativeToStartPoint" : "EGM96");
    });
    text("wpml:autoFlightSpeed", number(plan_.cruise_speed_m_s, 3));
    text("wpml:globalHeight", number(relative() ? heightAboveTakeoff(0) : seaLevelHeight(0), 3));
    text("wpml:gimbalPitchMode", "usePointSetting");
    element("wpml:globalWaypointHeadingParam", [&] {
      text("wpml:waypointHeadingMode", "smoothTransition");
      text("wpml:waypointHeadingAngle", number(signedHeading(plan_.headings_deg.front()), 3));
      text("wpml:waypointPoiPoint", "0.000000,0.000000,0.000000");
      text("wpml:waypointHeadingPathMode", "followBadArc");
    });
    text("wpml:globalWaypointTurnMode", kTurnMode);
  }

  void waylinesFolderHeader() {
    double distance = 0.0, duration = 0.0;
    Eigen::Vector3d previous = plan_.route.home_m;
    for (std::size_t k = 0; k < plan_.route.waypoints.size(); ++k) {
      const double length = (plan_.positions_m[k] - previous).norm();
      distance += length;
      duration +=
          length / (k == 0 ? plan_.cruise_speed_m_s : plan_.speeds_m_s[k - 1]) + plan_.route.waypoints[k].hold_s;
      previous = plan_.positions_m[k];
    }
    text("wpml:templateId", "0");
    text("wpml:executeHeightMode", relative() ? "relativeToStartPoint" : "WGS84");
    text("wpml:waylineId", "0");
    text("wpml:distance", number(distance, 3));
    text("wpml:duration", number(duration, 3));
    text("wpml:autoFlightSpeed", number(plan_.cruise_speed_m_s, 3));
  }

  void placemark(std::size_t k, bool is_template) {
    const mission::RouteWaypoint& w = plan_.route.waypoints[k];
    element("Placemark", [&] {
      element("Point",
              [&] { text("coordinates", number(plan_.geodetic[k].y(), 9) + "," + number(plan_.geodetic[k].x(), 9)); });
      text("wpml:index", std::to_string(k));
      if (is_template) {
        text("wpml:ellipsoidHeight", number(ellipsoidHeight(k), 4));
        text("wpml:height", number(relative() ? heightAboveTakeoff(k) : seaLevelHeight(k), 4));
        text("wpml:useGlobalHeight", "0");
        text("wpml:useGlobalSpeed", "0");
      } else {
        text("wpml:executeHeight", number(relative() ? heightAboveTakeoff(k) : ellipsoidHeight(k), 4));
      }
      text("wpml:waypointSpeed", number(plan_.speeds_m_s[k], 3));
      if (is_template) text("wpml:useGlobalHeadingParam", "0");
      element("wpml:waypointHeadingParam", [&] {
        text("wpml:waypointHeadingMode", "smoothTransition");
        text("wpml:waypointHeadingAngle", number(signedHeading(plan_.headings_deg[k]), 3));
        text("wpml:waypointPoiPoint", "0.000000,0.000000,0.000000");
        text("wpml:waypointHeadingPathMode", "followBadArc");
      });
      if (is_template) text("wpml:useGlobalTurnParam", "0");
      element("wpml:waypointTurnParam", [&] { text("wpml:waypointTurnMode", kTurnMode); });
      if (is_template) text("wpml:gimbalPitchAngle", number(plan_.pitches_deg[k], 3));
      arrivalActions(k, w);
      distanceTrigger(k, w);
    });
  }

  void actionGroupHeader(std::size_t start, std::size_t end) {
    text("wpml:actionGroupId", std::to_string(action_group_id_++));
    text("wpml:actionGroupStartIndex", std::to_string(start));
    text("wpml:actionGroupEndIndex", std::to_string(end));
    text("wpml:actionGroupMode", "sequence");
  }

  void action(int id, const char* function, const std::function<void()>& parameters) {
    element("wpml:action", [&] {
      text("wpml:actionId", std::to_string(id));
      text("wpml:actionActuatorFunc", function);
      element("wpml:actionActuatorFuncParam", parameters);
    });
  }

  void takePhoto(const mission::RouteWaypoint& w, std::size_t k) {
    text("wpml:payloadPositionIndex", std::to_string(plan_.options.payload_position));
    text("wpml:fileSuffix", w.name.empty() ? "wp" + std::to_string(k) : w.name);
    text("wpml:payloadLensIndex", "wide");
    text("wpml:useGlobalPayloadLensIndex", "0");
  }

  // On arrival: turn, pitch the camera, hover, shoot.
  void arrivalActions(std::size_t k, const mission::RouteWaypoint& w) {
    const double previous_heading = k > 0 ? plan_.headings_deg[k - 1] : mission::initialHeading_deg(plan_.route);
    const bool pitch_changes =
        w.gimbal_pitch_deg && (!pitchSetBefore(k) || plan_.pitches_deg[k - 1] != plan_.pitches_deg[k]);
    if (!w.yaw_deg && !pitch_changes && w.hold_s <= 0.0 && !w.take_photo) return;
    element("wpml:actionGroup", [&] {
      actionGroupHeader(k, k);
      element("wpml:actionTrigger", [&] { text("wpml:actionTriggerType", "reachPoint"); });
      int id = 0;
      if (w.yaw_deg) {
        const double turn = std::remainder(plan_.headings_deg[k] - previous_heading, 360.0);
        action(id++, "rotateYaw", [&] {
          text("wpml:aircraftHeading", number(signedHeading(plan_.headings_deg[k]), 3));
          text("wpml:aircraftPathMode", turn >= 0.0 ? "clockwise" : "counterClockwise");
        });
      }
      if (pitch_changes) {
        action(id++, "gimbalRotate", [&] {
          text("wpml:gimbalHeadingYawBase", "north");
          text("wpml:gimbalRotateMode", "absoluteAngle");
          text("wpml:gimbalPitchRotateEnable", "1");
          text("wpml:gimbalPitchRotateAngle", number(*w.gimbal_pitch_deg, 3));
          text("wpml:gimbalRollRotateEnable", "0");
          text("wpml:gimbalRollRotateAngle", "0");
          text("wpml:gimbalYawRotateEnable", "0");
          text("wpml:gimbalYawRotateAngle", "0");
          text("wpml:gimbalRotateTimeEnable", "0");
          text("wpml:gimbalRotateTime", "0");
          text("wpml:payloadPositionIndex", std::to_string(plan_.options.payload_position));
        });
      }
      if (w.hold_s > 0.0) action(id++, "hover", [&] { text("wpml:hoverTime", number(w.hold_s, 3)); });
      if (w.take_photo) action(id++, "takePhoto", [&] { takePhoto(w, k); });
    });
  }

  // Whether an earlier waypoint set the pitch in effect before k (else the gimbal is where the
  // pilot left it, and a pitch given at k must be commanded).
  bool pitchSetBefore(std::size_t k) const {
    for (std::size_t i = 0; i < k; ++i)
      if (plan_.route.waypoints[i].gimbal_pitch_deg) return true;
    return false;
  }

  // A distance trigger starting here: photos every d metres until a waypoint stops it (or the end).
  void distanceTrigger(std::size_t k, const mission::RouteWaypoint& w) {
    if (!w.trigger_distance_m || *w.trigger_distance_m <= 0.0) return;
    std::size_t end = k + 1;
    while (end + 1 < plan_.route.waypoints.size() && !plan_.route.waypoints[end].trigger_distance_m) ++end;
    end = std::min(end, plan_.route.waypoints.size() - 1);
    element("wpml:actionGroup", [&] {
      actionGroupHeader(k, end);
      element("wpml:actionTrigger", [&] {
        text("wpml:actionTriggerType", "multipleDistance");
        text("wpml:actionTriggerParam", number(*w.trigger_distance_m, 3));
      });
      action(0, "takePhoto", [&] { takePhoto(w, k); });
    });
  }

  const Plan& plan_;
  tinyxml2::XMLPrinter* xml_ = nullptr;
  int action_group_id_ = 0;
};

void writeZip(const std::filesystem::path& file, const std::vector<std::pair<std::string, std::string>>& entries) {
  zipFile zip = zipOpen64(file.c_str(), APPEND_STATUS_CREATE);
  if (!zip) throw Error("cannot create " + file.string());
  bool ok = true;
  for (const auto& [name, content] : entries) {
    zip_fileinfo info{};
    info.tmz_date.tm_year = 2020;  // fixed, so the same plan gives the same bytes
    info.tmz_date.tm_mday = 1;
    ok = ok && zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED,
                                     Z_DEFAULT_COMPRESSION, 0) == ZIP_OK;
    ok = ok && zipWriteInFileInZip(zip, content.data(), static_cast<unsigned>(content.size())) == ZIP_OK;
    ok = ok && zipCloseFileInZip(zip) == ZIP_OK;
  }
  ok = zipClose(zip, nullptr) == ZIP_OK && ok;
  if (!ok) throw Error("failed while writing the archive " + file.string());
}

}  // namespace

void DjiWpmlOptions::validate() const {
  const auto oneOf = [](const std::string& value, std::initializer_list<const char*> allowed, const char* field) {
    std::string list;
    for (const char* a : allowed) {
      if (value == a) return;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    throw InputError(std::string("dji: ") + field + " must be one of " + list + ", got '" + value + "'");
  };
  oneOf(finish_action, {"goHome", "autoLand", "noAction", "gotoFirstWaypoint"}, "finish_action");
  oneOf(rc_lost_action, {"goBack", "landing", "hover"}, "rc_lost_action");
  if (!(rth_height_m >= 2.0 && rth_height_m <= 1500.0))
    throw InputError("dji: rth_height_m must lie in DJI's [2, 1500] m, got " + formatNumber(rth_height_m));
  if (drone_enum < 0 || drone_sub_enum < 0 || payload_enum < 0 || payload_position < 0)
    throw InputError("dji: drone, payload and position enum values must be non-negative");
  if (!(gimbal_pitch_range_deg[0] < gimbal_pitch_range_deg[1]) || !std::isfinite(gimbal_pitch_range_deg[0]) ||
      !std::isfinite(gimbal_pitch_range_deg[1]))
    throw InputError("dji: gimbal_pitch_range_deg must be [min, max] with min < max");
  if (height_mode == DjiHeightMode::SeaLevel && (!geoid_separation_m || !std::isfinite(*geoid_separation_m)))
    throw InputError(
        "dji: heights above sea level need geoid_separation_m (ellipsoid above geoid at the site, m) for "
        "waylines.wpml's WGS84 heights");
}

namespace {

// DJI Cloud API product support, "Enumeration values of aircraft, RC and dock" and "Enumeration
// values of camera" (type-subtype-gimbalindex),
// https://developer.dji.com/doc/cloud-api-tutorial/en/overview/product-support.html
struct DjiDrone {
  const char* name;
  int type;
  int sub_type;
  int builtin_camera;  // the drone's own camera's payload type; 0: carries H20/H30 payloads
};
constexpr DjiDrone kDrones[] = {
    {"m300_rtk", 60, 0, 0}, {"m350_rtk", 89, 0, 0}, {"m30", 67, 0, 52},  {"m30t", 67, 1, 53}, {"m3e", 77, 0, 66},
    {"m3t", 77, 1, 67},     {"m3d", 91, 0, 80},     {"m3td", 91, 1, 81}, {"m4e", 99, 0, 88},  {"m4t", 99, 1, 89},
};
struct DjiPayload {
  const char* name;
  int type;
  bool h20_series;  // tilt -120 to +30 degrees underslung (DJI Zenmuse H20 series specifications)
};
constexpr DjiPayload kPayloads[] = {{"h20", 42, true},  {"h20t", 43, true},  {"h20n", 61, true},
                                    {"h30", 82, false}, {"h30t", 83, false}, {"builtin", 0, false}};

template <typename Entry, std::size_t N>
std::vector<std::string> namesOf(const Entry (&entries)[N]) {
  std::vector<std::string> names;
  for (const Entry& e : entries) names.emplace_back(e.name);
  return names;
}

}  // namespace

const std::vector<std::string>& djiDroneNames() {
  static const std::vector<std::string> names = namesOf(kDrones);
  return names;
}

const std::vector<std::string>& djiPayloadNames() {
  static const std::vector<std::string> names = namesOf(kPayloads);
  return names;
}

DjiWpmlOptions djiWpmlOptions(const mission::DjiAircraft& aircraft) {
  const auto drone =
      std::find_if(std::begin(kDrones), std::end(kDrones), [&](const DjiDrone& d) { return aircraft.drone == d.name; });
  const auto payload = std::find_if(std::begin(kPayloads), std::end(kPayloads),
                                    [&](const DjiPayload& p) { return aircraft.payload == p.name; });
  if (drone == std::end(kDrones)) throw InputError("dji: unknown drone '" + aircraft.drone + "'");
  if (payload == std::end(kPayloads)) throw InputError("dji: unknown payload '" + aircraft.payload + "'");
  DjiWpmlOptions options;
  options.drone_enum = drone->type;
  options.drone_sub_enum = drone->sub_type;
  const bool carries_payloads = drone->builtin_camera == 0;
  if (carries_payloads == (payload->type == 0))
    throw InputError("dji: the " + aircraft.drone +
                     (carries_payloads ? " carries a Zenmuse payload (h20, h20t, h20n, h30, h30t), not 'builtin'"
                                       : " flies its own camera: payload: builtin"));
  options.payload_enum = carries_payloads ? payload->type : drone->builtin_camera;
  const std::vector<std::string> mounts{"main", "right", "upper"};
  options.payload_position =
      static_cast<int>(std::find(mounts.begin(), mounts.end(), aircraft.payload_position) - mounts.begin());
  if (options.payload_position == 3) throw InputError("dji: payload_position must be main, right or upper");
  if (options.payload_position > 0 && !carries_payloads)
    throw InputError("dji: the " + aircraft.drone + " has one gimbal: payload_position: main");
  if (aircraft.gimbal_pitch_range_deg) {
    options.gimbal_pitch_range_deg = *aircraft.gimbal_pitch_range_deg;
  } else if (payload->h20_series) {
    // On the upper mount the gimbal hangs the other way up: its range mirrored about the horizon.
    options.gimbal_pitch_range_deg =
        options.payload_position == 2 ? std::array<double, 2>{-30.0, 120.0} : std::array<double, 2>{-120.0, 30.0};
  } else {
    throw InputError("dji: the gimbal pitch range of payload '" + aircraft.payload +
                     "' is not built in: give gimbal_pitch_range_deg: [min, max] from its specifications");
  }
  options.rth_height_m = aircraft.rth_height_m;
  options.finish_action = aircraft.finish_action;
  options.rc_lost_action = aircraft.rc_lost_action;
  options.validate();
  return options;
}

DjiWpml djiWpml(const mission::SortieRoute& route, const mission::GeodeticOrigin& origin,
                const DjiWpmlOptions& options) {
  origin.validate();
  route.validate();
  options.validate();
  for (std::size_t k = 0; k < route.waypoints.size(); ++k) {
    const auto& pitch = route.waypoints[k].gimbal_pitch_deg;
    if (pitch && (*pitch < options.gimbal_pitch_range_deg[0] || *pitch > options.gimbal_pitch_range_deg[1]))
      throw InputError("route waypoint " + std::to_string(k + 1) + ": gimbal pitch " + formatNumber(*pitch) +
                       " deg is outside the payload's range [" + formatNumber(options.gimbal_pitch_range_deg[0]) +
                       ", " + formatNumber(options.gimbal_pitch_range_deg[1]) + "]");
  }
  Plan plan(route, origin, options);
  plan.headings_deg = mission::headingsInEffect_deg(route);
  plan.pitches_deg = mission::gimbalPitchesInEffect_deg(route);
  for (const mission::RouteWaypoint& w : route.waypoints) plan.positions_m.push_back(w.position_m);
  // finishAction lands from the last waypoint: home at the landing height, not on the ground.
  if (route.endsAtHome()) plan.positions_m.back().z() = route.home_m.z() + route.landingHeight_m();
  for (const Eigen::Vector3d& p : plan.positions_m) plan.geodetic.push_back(toGeodetic(origin, p));
  plan.cruise_speed_m_s = plan.within(route.cruise_speed_m_s, kMinSpeed_m_s, kMaxSpeed_m_s, 0, "wpml:autoFlightSpeed");
  for (std::size_t k = 0; k < route.waypoints.size(); ++k)
    plan.speeds_m_s.push_back(
        plan.within(route.speedInto_m_s(k + 1), kMinSpeed_m_s, kMaxSpeed_m_s, k + 1, "wpml:waypointSpeed"));
  plan.takeoff_security_height_m =
      plan.within(route.takeoffHeight_m(), kMinTakeOffSecurityHeight_m, 1500.0, 0, "wpml:takeOffSecurityHeight");
  Writer writer(plan);
  DjiWpml files;
  files.template_kml = writer.document(true);
  files.waylines_wpml = writer.document(false);
  files.clamps = std::move(plan.clamps);
  return files;
}

void writeDjiKmz(const std::filesystem::path& file, const mission::SortieRoute& route,
                 const mission::GeodeticOrigin& origin, const DjiWpmlOptions& options) {
  const DjiWpml files = djiWpml(route, origin, options);
  writeAtomically(file, [&](const std::filesystem::path& temporary) {
    writeZip(temporary, {{"wpmz/template.kml", files.template_kml}, {"wpmz/waylines.wpml", files.waylines_wpml}});
  });
}

}  // namespace ceilplan::io
