// A target given on a scanned surface lies inside the occupied voxel that holds the scan's point;
// the tour moves it onto the structure's surface instead of refusing it, and says by how much.
// On the shipped bridge (ceilplan mapgen's scene) the deck's underside is at z = 6.0 m.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace ceilplan::mission {
namespace {

InspectionTarget target(const std::string& name, const Eigen::Vector3d& point_m, double standoff_max_m = 1.5) {
  InspectionTarget t;
  t.name = name;
  t.point_m = point_m;
  t.standoff_max_m = standoff_max_m;
  t.dwell_s = 10.0;
  return t;
}

TEST(TargetSnap, ATargetInsideTheDeckMovesOntoItsUndersideAndTheTourSaysByHowMuch) {
  Mission mission = io::readMission(std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml");
  // 8 cm into the deck, as a scan's point lies in its voxel: no line of sight reaches it there.
  mission.targets = {target("deck_scanned", {10.0, 0.0, 6.08}), target("deck_on_face", {14.0, 0.0, 6.0})};
  const PlanningContext context(mission);
  const environment::Environment& environment = context.environment();
  EXPECT_THROW(chooseViewpoint(mission.targets[0], environment, context.energy()), InputError);

  // The surface point: the nearest face between an occupied and a free voxel, within reach.
  EXPECT_LT((*surfacePoint(mission.targets[0], environment) - Eigen::Vector3d(10.0, 0.0, 6.0)).norm(), 1e-9);
  EXPECT_EQ(*surfacePoint(target("in_free_air", {10.0, 0.0, 5.0}), environment), Eigen::Vector3d(10.0, 0.0, 5.0));
  EXPECT_FALSE(surfacePoint(target("too_deep", {10.0, 0.0, 6.08}, 0.05), environment));

  const TourResult tour = planTour(mission, context, FlightMode::Ceiling);
  ASSERT_EQ(tour.stops.size(), 2u);
  const TourStop& moved = tour.stops[0];
  ASSERT_TRUE(moved.given_point_m);
  EXPECT_EQ(*moved.given_point_m, Eigen::Vector3d(10.0, 0.0, 6.08));
  EXPECT_LT((moved.target.point_m - Eigen::Vector3d(10.0, 0.0, 6.0)).norm(), 1e-9);
  EXPECT_LE(moved.viewpoint.distance_m, 1.5 + 1e-9);
  EXPECT_FALSE(tour.stops[1].given_point_m);  // on the face already: not moved, not reported
  EXPECT_EQ(tour.stops[1].target.point_m, Eigen::Vector3d(14.0, 0.0, 6.0));

  const std::string line =
      "1 target(s) given inside a structure moved onto its surface: 'deck_scanned' by 0.08 m, from (10.00, 0.00, "
      "6.08) to (10.00, 0.00, 6.00) (tour.json: targets[].moved_onto_surface_m)";
  EXPECT_EQ(io::movedOntoSurfaceLine(tour), line);
  EXPECT_NE(io::tourSummary(tour).find("  " + line + "\n"), std::string::npos) << io::tourSummary(tour);
  const nlohmann::json json = io::tourJson(tour, mission, io::Provenance::of("test"));
  EXPECT_NEAR(json["targets"][0]["moved_onto_surface_m"].get<double>(), 0.08, 1e-9);
  EXPECT_EQ(json["targets"][0]["given_point"], nlohmann::json::array({10.0, 0.0, 6.08}));
  EXPECT_NEAR(json["targets"][0]["point"][2].get<double>(), 6.0, 1e-9);
  EXPECT_FALSE(json["targets"][1].contains("moved_onto_surface_m"));
}

}  // namespace
}  // namespace ceilplan::mission
