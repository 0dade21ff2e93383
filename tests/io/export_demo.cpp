// export_demo: writes every flying export and report.html for a `ceilplan tour --out DIR`
// directory, without the tour wiring them in yet: the browser test's input and a worked example
// of the mapping in docs/flying.md.
//
// Usage: export_demo --mission FILE --tour DIR --out OUT [--coverage-mock] [--title TEXT]
// Writes OUT/report.html and, per mode (OUT/<mode>/ after --mode both), trajectory.csv,
// trajectory.json, trajectory_ned.csv, mission.plan, mission.waypoints, mission.kmz, route.kml,
// route.geojson (sortie files named as the tour's mission.plan files).

#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/dji_wpml.hpp"
#include "ceilplan/io/geo_export.hpp"
#include "ceilplan/io/report_html.hpp"
#include "ceilplan/io/trajectory_file.hpp"
#include "flying_fixture.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>
#include <iostream>

using namespace ceilplan;

int main(int argc, char** argv) {
  std::filesystem::path mission_file, tour_dir, out;
  std::string title;
  bool coverage_mock = false;
  for (int k = 1; k < argc; ++k) {
    const std::string flag = argv[k];
    const auto value = [&]() -> std::string {
      if (k + 1 >= argc) throw std::runtime_error(flag + " needs a value");
      return argv[++k];
    };
    if (flag == "--mission")
      mission_file = value();
    else if (flag == "--tour")
      tour_dir = value();
    else if (flag == "--out")
      out = value();
    else if (flag == "--title")
      title = value();
    else if (flag == "--coverage-mock")
      coverage_mock = true;
    else {
      std::cerr << "export_demo: unknown flag " << flag << "\n";
      return 2;
    }
  }
  if (mission_file.empty() || tour_dir.empty() || out.empty()) {
    std::cerr << "usage: export_demo --mission FILE --tour DIR --out OUT [--coverage-mock] [--title TEXT]\n";
    return 2;
  }
  try {
    const testing::MissionFacts facts = testing::readMissionFacts(mission_file);
    const testing::MapCheck map(facts);
    const std::vector<testing::TourOutput> outputs = testing::readTourOutputs(tour_dir, facts);
    // The tour aims the camera straight up at soffit targets: a payload that can look up, as a
    // mission's camera.gimbal_pitch_deg: [-90, 90] would say (docs/flying.md, DJI).
    io::DjiWpmlOptions dji;
    dji.gimbal_pitch_range_deg = {-90.0, 90.0};
    mission::TrajectoryOptions options;
    options.path_is_safe = [&](const std::vector<Eigen::Vector3d>& p) { return map.safe(p); };
    for (const testing::TourOutput& output : outputs) {
      const std::filesystem::path dir = outputs.size() > 1 ? out / output.mode : out;
      const int count = static_cast<int>(output.routes.size());
      for (const mission::SortieRoute& route : output.routes) {
        const auto named = [&](const char* file) { return io::sortieFileName(dir / file, route.sortie, count); };
        const auto start = std::chrono::steady_clock::now();
        const mission::Trajectory t = mission::timeScale(route, testing::trajectoryLimits(facts), options);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const io::Provenance provenance = io::Provenance::of("export_demo");
        io::writeTrajectoryCsv(named("trajectory.csv"), t, io::TrajectoryFrame::Enu, provenance);
        io::writeTrajectoryJson(named("trajectory.json"), t, io::TrajectoryFrame::Enu, facts.origin, provenance);
        io::writeTrajectoryCsv(named("trajectory_ned.csv"), t, io::TrajectoryFrame::Ned, provenance);
        const io::AutopilotMission autopilot = io::autopilotMission(route, facts.origin);
        io::writeQgcPlan(named("mission.plan"), autopilot);
        io::writeQgcWpl(named("mission.waypoints"), autopilot);
        io::writeDjiKmz(named("mission.kmz"), route, facts.origin, dji);
        std::printf(
            "%s sortie %d: trajectory %.1f s, %zu setpoints, %d stops, %d blended corners, %d photos (%.3f s)\n",
            output.mode.c_str(), route.sortie, t.duration_s(), t.setpoints.size(), t.stops, t.blended_corners, t.photos,
            seconds);
      }
      io::writeRoutesKml(dir / "route.kml", output.routes, facts.origin,
                         mission_file.stem().string() + " " + output.mode);
      io::writeRoutesGeoJson(dir / "route.geojson", output.routes, facts.origin);
    }
    const auto start = std::chrono::steady_clock::now();
    io::ReportModel model = testing::reportModel(
        outputs, facts, map, tour_dir, title.empty() ? mission_file.stem().string() + ": inspection tour" : title);
    if (coverage_mock)
      for (io::ReportPlan& plan : model.plans) testing::addCoverageMock(plan, map);
    io::writeReportHtml(out / "report.html", model);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("report.html: %zu structure voxels of %.2f m, %zu plans (%.3f s), in %s\n",
                model.structure.centres_m.size(), model.structure.voxel_m, model.plans.size(), seconds,
                out.string().c_str());
  } catch (const std::exception& e) {
    std::cerr << "export_demo: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
