#include "flying_fixture.hpp"

#include "ceilplan/core/format.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/vehicle_file.hpp"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>

namespace ceilplan::testing {
namespace {

Eigen::Vector3d vec(const nlohmann::json& a) { return {a[0].get<double>(), a[1].get<double>(), a[2].get<double>()}; }

double distanceToSegment(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double u = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + u * d)).norm();
}

nlohmann::json readJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  return nlohmann::json::parse(in);
}

}  // namespace

MissionFacts readMissionFacts(const std::filesystem::path& mission_file) {
  const YAML::Node root = YAML::LoadFile(mission_file.string());
  const std::filesystem::path dir = mission_file.parent_path();
  MissionFacts facts;
  facts.map = dir / root["map"].as<std::string>();
  facts.vehicle = dir / root["vehicle"].as<std::string>();
  const auto home = root["home"].as<std::vector<double>>();
  facts.home_m = {home[0], home[1], home[2]};
  facts.origin = {root["origin"]["lat"].as<double>(), root["origin"]["lon"].as<double>(),
                  root["origin"]["alt"].as<double>()};
  facts.cruise_m_s = root["speeds"]["cruise_m_s"].as<double>();
  facts.climb_m_s = root["speeds"]["climb_m_s"].as<double>();
  facts.descent_m_s = root["speeds"]["descent_m_s"].as<double>();
  facts.reserve_soc = root["battery"]["reserve_soc"].as<double>();
  return facts;
}

TourOutput readTourOutput(const std::filesystem::path& dir, const MissionFacts& facts) {
  TourOutput out;
  out.tour = readJson(dir / "tour.json");
  out.mode = out.tour["mode"].get<std::string>();
  const io::CsvColumns table =
      io::CsvColumns::read(dir / "path.csv", {"t_s", "x", "y", "z", "current_a", "soc", "sortie", "speed_m_s"});
  const auto &t = table.column("t_s"), &x = table.column("x"), &y = table.column("y"), &z = table.column("z"),
             &current = table.column("current_a"), &soc = table.column("soc"), &sortie = table.column("sortie"),
             &speed = table.column("speed_m_s");
  for (std::size_t k = 0; k < table.rowCount(); ++k)
    out.samples.push_back({t[k], {x[k], y[k], z[k]}, current[k], soc[k], static_cast<int>(sortie[k])});

  std::map<std::string, nlohmann::json> targets;
  for (const auto& target : out.tour["targets"]) targets[target["name"]] = target;
  int number = 0;
  for (const auto& sortie_json : out.tour["sorties"]) {
    mission::SortieRoute route;
    route.sortie = ++number;
    route.cruise_speed_m_s = facts.cruise_m_s;
    route.home_m = facts.home_m;
    for (const auto& leg : sortie_json["legs"]) {
      const auto& waypoints = leg["waypoints"];
      for (std::size_t i = 1; i < waypoints.size(); ++i) route.waypoints.emplace_back(vec(waypoints[i]));
      if (leg["to"] == "home") continue;
      const nlohmann::json& target = targets.at(leg["to"]);
      mission::RouteWaypoint& stop = route.waypoints.back();
      stop.hold_s = target["dwell_s"].get<double>();
      const mission::CameraAim aim = mission::aimAt(stop.position_m, vec(target["point"]));
      stop.yaw_deg = aim.yaw_deg;
      stop.gimbal_pitch_deg = aim.gimbal_pitch_deg;
      stop.take_photo = true;
      stop.name = leg["to"].get<std::string>();
    }
    // Each segment's speed: the slowest sample of this sortie on it.
    Eigen::Vector3d from = route.home_m;
    for (std::size_t k = 0; k < route.waypoints.size(); ++k) {
      double slowest = std::numeric_limits<double>::infinity();
      for (std::size_t s = 0; s < out.samples.size(); ++s)
        if (out.samples[s].sortie == route.sortie && speed[s] > 0.0 &&
            distanceToSegment(out.samples[s].position_m, from, route.waypoints[k].position_m) < 1e-3)
          slowest = std::min(slowest, speed[s]);
      // The speed into waypoint k is set at the waypoint before it.
      if (std::isfinite(slowest) && k > 0) route.waypoints[k - 1].speed_m_s = slowest;
      from = route.waypoints[k].position_m;
    }
    out.routes.push_back(std::move(route));
  }
  return out;
}

std::vector<TourOutput> readTourOutputs(const std::filesystem::path& dir, const MissionFacts& facts) {
  if (std::filesystem::exists(dir / "comparison.json"))
    return {readTourOutput(dir / "ceiling", facts), readTourOutput(dir / "free", facts)};
  return {readTourOutput(dir, facts)};
}

mission::TrajectoryLimits trajectoryLimits(const MissionFacts& facts) {
  mission::TrajectoryLimits limits;
  limits.climb_m_s = facts.climb_m_s;
  limits.descent_m_s = facts.descent_m_s;
  return limits;
}

MapCheck::MapCheck(const MissionFacts& facts, bool unknown_is_free) : map(environment::OccupancyMap::load(facts.map)) {
  environment::MapIndexOptions index_options;
  if (unknown_is_free) index_options.unknown.policy = environment::UnknownPolicy::Free;
  environment = std::make_unique<environment::Environment>(map, io::readVehicle(facts.vehicle).geometry,
                                                           environment::EnvironmentOptions{}, index_options);
  rules = std::make_unique<planner::SafetyRules>(*environment, 0.05);
}

io::ReportModel reportModel(const std::vector<TourOutput>& outputs, const MissionFacts& facts, const MapCheck& map,
                            const std::filesystem::path& tour_dir, const std::string& title) {
  io::ReportModel model;
  model.title = title;
  model.home_m = facts.home_m;
  model.reserve_soc = facts.reserve_soc;
  std::vector<Eigen::Vector3d> route;
  for (const TourOutput& output : outputs) {
    io::ReportPlan plan;
    plan.name = output.mode;
    plan.samples = output.samples;
    for (const io::ReportSample& s : output.samples) route.push_back(s.position_m);
    for (const auto& target : output.tour["targets"])
      plan.targets.push_back({target["name"].get<std::string>(), vec(target["point"]), vec(target["viewpoint"])});
    const nlohmann::json& tour = output.tour;
    plan.summary = {{"targets", std::to_string(tour["targets_visited"].get<int>()) + " of " +
                                    std::to_string(tour["targets_total"].get<int>())},
                    {"sorties", std::to_string(tour["sorties"].size())},
                    {"charge", formatFixed(tour["charge_ah"].get<double>(), 4) + " Ah"},
                    {"in the air", formatFixed(tour["duration_s"].get<double>(), 1) + " s"},
                    {"FEC", formatNumber(tour["fec"].get<double>(), 5)},
                    {"lowest SOC", formatFixed(100 * tour["min_soc"].get<double>(), 1) + " %"}};
    model.plans.push_back(std::move(plan));
  }
  model.structure = io::structureNear(map.environment->grid(), route, 3.0);
  if (outputs.size() == 2) {
    const nlohmann::json comparison = readJson(tour_dir / "comparison.json");
    model.comparison_header = {"", "ceiling", "free", "reduction %"};
    const auto row = [&](const std::string& label, const nlohmann::json& c, const nlohmann::json& f, double scale,
                         int decimals, const std::string& reduction) {
      model.comparison_rows.push_back(
          {label, formatFixed(scale * c.get<double>(), decimals), formatFixed(scale * f.get<double>(), decimals),
           reduction.empty() ? "" : formatFixed(comparison["reduction_pct"][reduction].get<double>(), 2)});
    };
    const nlohmann::json &c = comparison["ceiling"], &f = comparison["free"];
    row("charge [Ah]", c["charge_ah"], f["charge_ah"], 1, 4, "charge");
    row("flight time [s]", c["duration_s"], f["duration_s"], 1, 1, "duration");
    row("FEC", c["fec"], f["fec"], 1, 5, "fec");
    row("lowest SOC [%]", c["min_soc"], f["min_soc"], 100, 1, "");
    for (const auto& [model_name, wear] : c["wear"].items())
      row(model_name + " capacity loss [%]", wear["capacity_loss"], f["wear"][model_name]["capacity_loss"], 100, 5,
          "capacity_loss_" + model_name);
  }
  return model;
}

void addCoverageMock(io::ReportPlan& plan, const MapCheck& map) {
  // A 1-inch 20 MP camera (13.2 x 8.8 mm, 5472 x 3648 px, 8.8 mm lens), looking straight up.
  const double sensor_w_mm = 13.2, sensor_h_mm = 8.8, focal_mm = 8.8, pixels_w = 5472;
  const double hfov = 2 * std::atan(sensor_w_mm / (2 * focal_mm)), vfov = 2 * std::atan(sensor_h_mm / (2 * focal_mm));
  const environment::Environment& env = *map.environment;
  struct Footprint {
    Eigen::Vector3d centre;
    double half_w, half_h, gsd_mm;
  };
  std::vector<Footprint> footprints;
  Eigen::Vector3d last(1e9, 1e9, 1e9);
  Eigen::Vector3d low = Eigen::Vector3d::Constant(1e9), high = -low;
  for (const io::ReportSample& s : plan.samples) {
    if ((s.position_m - last).norm() < 1.0 || !env.contains(s.position_m)) continue;
    const double gap = env.ceilingGapAt(s.position_m);
    if (!(gap < 3.0)) continue;
    last = s.position_m;
    const double range = gap + 0.03;  // camera a little below the rotor plane's gap
    plan.photos.push_back({s.position_m, 0.0, 90.0, hfov * 180 / M_PI, vfov * 180 / M_PI, range});
    // Heading north, camera up: image width along x, height along y.
    const double half_w = range * std::tan(hfov / 2), half_h = range * std::tan(vfov / 2);
    footprints.push_back(
        {s.position_m + Eigen::Vector3d(0, 0, gap), half_w, half_h, range * 1000 * sensor_w_mm / focal_mm / pixels_w});
    low = low.cwiseMin(s.position_m);
    high = high.cwiseMax(s.position_m);
  }
  // The soffit within 1.5 m (horizontally) of the photo poses, in 0.5 m patches.
  for (double x = low.x() - 1.5; x <= high.x() + 1.5; x += 0.5)
    for (double y = low.y() - 1.5; y <= high.y() + 1.5; y += 0.5) {
      const Eigen::Vector3d below(x, y, low.z());
      bool near = false;
      for (const io::ReportPhoto& photo : plan.photos) near = near || (photo.position_m - below).head<2>().norm() < 1.5;
      if (!near || !env.contains(below)) continue;
      const double gap = env.ceilingGapAt(below);
      if (!std::isfinite(gap) || gap > 3.0) continue;
      double best = std::nan("");
      for (const Footprint& f : footprints)
        if (std::abs(f.centre.x() - x) <= f.half_w && std::abs(f.centre.y() - y) <= f.half_h &&
            std::abs(f.centre.z() - (below.z() + gap)) < 1.2 && !(f.gsd_mm >= best))
          best = f.gsd_mm;
      plan.coverage.push_back({below + Eigen::Vector3d(0, 0, gap), -Eigen::Vector3d::UnitZ(), 0.48, best});
    }
  plan.coverage_label = "mock GSD [mm/px]";
}

}  // namespace ceilplan::testing
