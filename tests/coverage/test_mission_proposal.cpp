// A coverage mission proposed from the map alone (mission/mission_proposal.hpp,
// io/proposal_files.hpp): on a room whose overhead surfaces are known exactly, the regions, their
// order, what is dropped, the home, and the mission file read back as a mission.

#include "coverage_fixtures.hpp"
#include "input_error.hpp"
#include "run_command.hpp"

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/proposal_files.hpp"
#include "ceilplan/mission/mission_proposal.hpp"
#include "ceilplan/mission/region_surface.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace ceilplan::mission {
namespace {

const environment::Environment& room() { return testing::roomScene().environment; }

// The room (coverage_fixtures.hpp): ceiling underside at 3.0 m over 4 x 4 m, cut by a beam at
// x in [0, 0.3) whose underside is at 2.4 m; a closet of 0.9 x 0.9 m inside in a corner.
TEST(MissionProposal, FindsTheRoomsOverheadSurfacesLargestFirstAndDropsTheSmallOnes) {
  const MissionProposal proposal = proposeMission(room(), ProposalOptions{});
  ASSERT_EQ(proposal.regions.size(), 3u);
  const ProposedRegion& left = proposal.regions[0];
  const ProposedRegion& right = proposal.regions[1];
  const ProposedRegion& beam = proposal.regions[2];
  EXPECT_EQ(left.name, "overhead_1");
  EXPECT_EQ(beam.name, "overhead_3");
  // Areas to within the few elements at the closet's corners whose normals lean (staircase fits).
  EXPECT_NEAR(left.area_m2, 2.0 * 4.0, 1e-3);               // x in [-2, 0)
  EXPECT_NEAR(right.area_m2, 1.7 * 4.0 - 1.0 * 1.0, 1e-3);  // x in [0.3, 2), less the closet's walls and inside
  EXPECT_NEAR(beam.area_m2, 0.3 * 4.0, 1e-6);
  EXPECT_NEAR(left.box_m.min().z(), 2.95, 1e-9);
  EXPECT_NEAR(left.box_m.max().z(), 3.05, 1e-9);
  EXPECT_NEAR(beam.box_m.min().z(), 2.35, 1e-9);
  EXPECT_NEAR(left.box_m.max().x(), 0.0, 1e-9);
  EXPECT_NEAR(right.box_m.min().x(), 0.3, 1e-9);
  EXPECT_EQ(left.elements, 800u);
  // The closet's ceiling (0.9 x 0.9 m) is below the least area of 1 m2.
  EXPECT_EQ(proposal.dropped_regions, 1u);
  EXPECT_NEAR(proposal.dropped_area_m2, 0.81, 1e-6);
  EXPECT_NEAR(proposal.overhead_area_m2, 8.0 + 5.8 + 1.2 + 0.81, 1e-3);
  // Each region, as a mission's box with faces [down], holds its own faces and what lies inside
  // its bounds: the right-hand ceiling's box also holds the closet's, and says so.
  for (const ProposedRegion& region : proposal.regions) {
    FaceSet down;
    down.down = true;
    const RegionSurface surface = extractRegionSurface(
        room().grid(), RegionShape::makeBox(region.box_m.min(), region.box_m.max()), down, region.name);
    EXPECT_NEAR(surface.area_m2, region.box_area_m2, 1e-9) << region.name;
    EXPECT_NEAR(region.box_area_m2 - region.area_m2, &region == &right ? 0.81 : 0.0, 1e-9) << region.name;
  }
  EXPECT_NE(io::proposalText(proposal, "m.yaml", "m.svg")
                .find("overhead_2: 5.8 m2 in the box (0.30, -2.00, 2.95) to (2.00, 2.00, 3.05) (with smaller surfaces "
                      "inside it: 6.61 m2 to cover)"),
            std::string::npos)
      << io::proposalText(proposal, "m.yaml", "m.svg");
}

TEST(MissionProposal, ProposesAHomeInKnownFreeSpaceLowAboveTheFloorNearTheRegions) {
  const MissionProposal proposal = proposeMission(room(), ProposalOptions{});
  EXPECT_FALSE(proposal.home_given);
  EXPECT_TRUE(room().isStateValid(proposal.home_m));
  EXPECT_FALSE(room().assumesFree(proposal.home_m));
  EXPECT_NEAR(proposal.home_m.z() - 0.2, proposal.home_height_m, 1e-9);  // the floor's top is at 0.2 m
  EXPECT_GE(proposal.home_height_m, 0.5);
  EXPECT_LE(proposal.home_height_m, 1.0);
  // The regions' area-weighted centre lies at x = (8 (-1) + 5.8 (1.15) + 1.2 (0.15)) / 15 ~ -0.07.
  EXPECT_LT(std::hypot(proposal.home_m.x() + 0.07, proposal.home_m.y()), 0.75);
}

TEST(MissionProposal, TakesAGivenHomeAndRefusesOneThatCannotBe) {
  ProposalOptions options;
  options.home_m = Eigen::Vector3d(-1.0, -1.0, 1.0);
  const MissionProposal proposal = proposeMission(room(), options);
  EXPECT_TRUE(proposal.home_given);
  EXPECT_EQ(proposal.home_m, *options.home_m);
  EXPECT_NEAR(proposal.home_height_m, 0.8, 1e-9);

  options.home_m = Eigen::Vector3d(-1.0, -1.0, 0.1);
  EXPECT_NE(testing::inputErrorOf([&] {
              proposeMission(room(), options);
            }).find("the given home (-1.00, -1.00, 0.10) is no valid position: "),
            std::string::npos);
  options.home_m = Eigen::Vector3d(50.0, 0.0, 1.0);
  EXPECT_NE(testing::inputErrorOf([&] {
              proposeMission(room(), options);
            }).find("the given home (50.00, 0.00, 1.00) lies outside the map"),
            std::string::npos);
}

TEST(MissionProposal, TheCropTheLeastAreaAndTheMostRegionsSayWhatTheyLeft) {
  ProposalOptions beam_only;
  beam_only.crop_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 2.3), Eigen::Vector3d(2, 2, 2.5));
  const MissionProposal beam = proposeMission(room(), beam_only);
  ASSERT_EQ(beam.regions.size(), 1u);
  EXPECT_NEAR(beam.regions[0].area_m2, 1.2, 1e-6);

  ProposalOptions one;
  one.max_regions = 1;
  const MissionProposal largest = proposeMission(room(), one);
  ASSERT_EQ(largest.regions.size(), 1u);
  EXPECT_NEAR(largest.regions[0].area_m2, 8.0, 1e-6);
  EXPECT_EQ(largest.dropped_regions, 3u);

  ProposalOptions large;
  large.min_region_area_m2 = 10.0;
  EXPECT_EQ(testing::inputErrorOf([&] { proposeMission(room(), large); }),
            "no overhead region of at least 10 m2 in the map (the largest has 8 m2): lower the least region area");

  ProposalOptions floor_only;
  floor_only.crop_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1));
  EXPECT_NE(testing::inputErrorOf([&] { proposeMission(room(), floor_only); })
                .find("no down-facing surface with known free space below it inside the crop (-2.00, -2.00, 0.00) to "
                      "(2.00, 2.00, 1.00)"),
            std::string::npos);
  ProposalOptions empty;
  empty.crop_m = Eigen::AlignedBox3d(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 1));
  EXPECT_EQ(testing::inputErrorOf([&] { proposeMission(room(), empty); }),
            "a crop box's y minimum (0) must be below its maximum (0)");
}

// A yard under a roof, with what a real scan or an open mesh holds besides the roof: 8 x 4 m, the
// ground's top at 0.2 m with a hollow under it at x < -2 (free from -1.8 to 0 m: the ground's
// underside faces free space, as an open mesh's thin ground or a scan's rays under it make it), a table (underside at
// 0.9 m) at x in [-1.5, -0.5), y in [-1, 1), and a roof whose underside is at 3.4 m over x < 2.5; beyond x = 2, a ledge
// up to 2.2 m, 1.2 m below the roof's edge.
environment::OccupancyMap yardWithTableAndLedge() {
  using environment::CellState;
  return testing::analyticMap({-4, -2, -2.0}, {4, 2, 4.0}, 0.1, [](const Eigen::Vector3d& c) {
    if (c.z() < -1.8) return CellState::Occupied;
    if (c.z() < 0.0) return c.x() < -2.0 ? CellState::Free : CellState::Occupied;
    if (c.z() < 0.2) return CellState::Occupied;
    if (c.x() >= 2.0 && c.z() < 2.2) return CellState::Occupied;
    if (c.x() >= -1.5 && c.x() < -0.5 && std::abs(c.y()) < 1.0 && c.z() >= 0.9 && c.z() < 1.0)
      return CellState::Occupied;
    if (c.x() < 2.5 && c.z() >= 3.4) return CellState::Occupied;
    return CellState::Free;
  });
}

// Only a region with room below most of it for the vehicle (0.3 m inflated, the quad) and the
// standoff (1 m), of faces as high above the ground, is overhead: the roof over the yard, its edge
// over the ledge (1.2 m of room, 2 of its 26 m2) included; not the table's underside (0.7 m above
// the ground), nor the ground seen from the hollow under it (1.8 m of free space, but below the
// ground a home stands on).
TEST(MissionProposal, OnlySurfacesWithRoomBelowToPhotographThemAreOverhead) {
  const testing::CoverageScene yard(yardWithTableAndLedge());
  const MissionProposal proposal = proposeMission(yard.environment, ProposalOptions{});
  EXPECT_NEAR(proposal.min_room_below_m, 1.0 + 0.08 + 0.22, 1e-9);
  ASSERT_EQ(proposal.regions.size(), 1u);
  const ProposedRegion& roof = proposal.regions[0];
  EXPECT_NEAR(roof.box_m.min().z(), 3.35, 1e-9);
  EXPECT_NEAR(roof.box_m.min().x(), -4.0, 1e-9);
  EXPECT_NEAR(roof.box_m.max().x(), 2.5, 1e-9);
  EXPECT_NEAR(roof.area_m2, 6.5 * 4.0, 1e-6);
  EXPECT_NEAR(proposal.ground_m, 0.2, 1e-9);
  // The table and the hollow, less what the staircase normals at their edges lean.
  EXPECT_NEAR(proposal.too_low_area_m2, 1.0 * 2.0 + 2.0 * 4.0, 0.1);
  EXPECT_NEAR(proposal.overhead_area_m2, roof.area_m2 + proposal.too_low_area_m2, 1e-9);
  EXPECT_NE(io::proposalText(proposal, "m.yaml", "m.svg")
                .find("\nleft out 9.942 m2 too low to photograph from below: with less than 1.30 m of free space "
                      "below most of its region, or less than 1.30 m above the ground at 0.20 m (the vehicle with "
                      "its margins and the camera's standoff)\n"),
            std::string::npos)
      << io::proposalText(proposal, "m.yaml", "m.svg");

  // A standoff the yard has no room for anywhere is refused, saying what it asked for.
  ProposalOptions far;
  far.standoff_m = 3.5;
  EXPECT_EQ(testing::inputErrorOf([&] { proposeMission(yard.environment, far); }),
            "no down-facing surface in the map has 3.8 m of free space below it, the vehicle's height with its "
            "margins and a standoff of 3.5 m: the camera cannot photograph any from below");
}

// The regions' centre (x = -1, y = 0) lies over the table. The home stands on the ground beside
// it, not on the table top, and not on the ledge (nor in the hollow under the ground, where no
// home can climb).
TEST(MissionProposal, TheHomeStandsOnTheGroundNotOnATableOrALedge) {
  const testing::CoverageScene yard(yardWithTableAndLedge());
  const MissionProposal proposal = proposeMission(yard.environment, ProposalOptions{});
  EXPECT_NEAR(proposal.home_m.z() - proposal.home_height_m, 0.2, 1e-9);  // on the ground's top
  EXPECT_NEAR(proposal.home_height_m, 0.5, 1e-9);
  EXPECT_TRUE(yard.environment.isStateValid(proposal.home_m));
  EXPECT_FALSE(yard.environment.assumesFree(proposal.home_m));
  EXPECT_LT(proposal.home_m.x(), 2.0 - 0.46);  // off the ledge (collision radius and margin)
  const bool beside_table = proposal.home_m.x() < -1.5 - 0.46 || proposal.home_m.x() > -0.5 + 0.46 ||
                            std::abs(proposal.home_m.y()) > 1.0 + 0.46;
  EXPECT_TRUE(beside_table) << proposal.home_m.transpose();
  EXPECT_LT(std::hypot(proposal.home_m.x() + 1.0, proposal.home_m.y()), 1.6) << proposal.home_m.transpose();

  // Standoffs are the camera's: free mode's 1 m, nearer for a fine GSD, never nearer than focus.
  const Camera camera = testing::upwardCamera();
  EXPECT_NEAR(proposalStandoff_m(camera, 2.0), 1.0, 1e-12);
  EXPECT_NEAR(proposalStandoff_m(camera, 0.2), camera.distanceForGsd_m(0.2), 1e-12);
  EXPECT_LT(camera.distanceForGsd_m(0.2), 1.0);
  EXPECT_NEAR(proposalStandoff_m(camera, 0.01), camera.min_focus_m, 1e-12);
}

// The mission file, read back by the mission reader, is the proposal with the settings: its
// map and vehicle found from where it lies, no origin, the camera on an upward mount.
TEST(MissionProposal, TheMissionFileReadsBackAsTheProposal) {
  const auto dir = testing::scratchDirectory("mission_proposal_yaml");
  const std::filesystem::path mission_file = dir / "sub dir" / "proposed.yaml";
  std::filesystem::create_directories(mission_file.parent_path());
  const MissionProposal proposal = proposeMission(room(), ProposalOptions{});
  io::ProposalSettings settings;
  settings.map_file = testing::shippedFile("warehouse.bt");  // any map file: read, not indexed here
  settings.vehicle_file = testing::shippedFile("vehicles/quad.yaml");
  settings.gsd_mm_px = 1.5;
  settings.overlap_side_pct = 50.0;
  settings.unknown.policy = environment::UnknownPolicy::Fill;
  settings.unknown.fill_max_m = 1.5;
  std::ofstream(mission_file) << io::proposedMissionYaml(proposal, settings, mission_file, io::Provenance::of("test"));
  const Mission mission = io::readMission(mission_file);
  EXPECT_EQ(std::filesystem::weakly_canonical(mission.map_file), std::filesystem::weakly_canonical(settings.map_file));
  EXPECT_LT((mission.home_m - proposal.home_m).norm(), 1e-3);
  EXPECT_FALSE(mission.origin.has_value());
  EXPECT_EQ(mission.planning.unknown, settings.unknown);
  ASSERT_TRUE(mission.camera.has_value());
  EXPECT_EQ(mission.camera->name, "zenmuse_h20_wide");
  EXPECT_EQ(mission.camera->gimbal_pitch_max_deg, 90.0);
  ASSERT_EQ(mission.surfaces.size(), proposal.regions.size());
  for (std::size_t r = 0; r < proposal.regions.size(); ++r) {
    EXPECT_EQ(mission.surfaces[r].name, proposal.regions[r].name);
    EXPECT_LT((mission.surfaces[r].shape.box.min() - proposal.regions[r].box_m.min()).norm(), 1e-3);
    EXPECT_LT((mission.surfaces[r].shape.box.max() - proposal.regions[r].box_m.max()).norm(), 1e-3);
    EXPECT_TRUE(mission.surfaces[r].faces.down);
    EXPECT_FALSE(mission.surfaces[r].faces.side);
    EXPECT_EQ(mission.surfaces[r].gsd_mm_px, 1.5);
    EXPECT_EQ(mission.surfaces[r].overlap_side_pct, 50.0);
    checkCameraReaches(*mission.camera, mission.surfaces[r]);  // throws if the camera cannot look up at it
  }

  settings.camera_preset = "phantom5";
  EXPECT_NE(testing::inputErrorOf([&] { settings.validate(); }).find("phantom5"), std::string::npos);
}

TEST(MissionProposal, ThePictureIsWellFormedAndShowsEveryRegionAndTheHome) {
  const MissionProposal proposal = proposeMission(room(), ProposalOptions{});
  const std::string svg = io::proposalPictureSvg(room().grid(), proposal, "room <&> map");
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  for (const ProposedRegion& region : proposal.regions)
    EXPECT_NE(svg.find(">" + region.name + "</text>"), std::string::npos);
  EXPECT_NE(svg.find(">home</text>"), std::string::npos);
  EXPECT_NE(svg.find("room &lt;&amp;&gt; map"), std::string::npos);
  EXPECT_EQ(svg.find("<&>"), std::string::npos);
}

}  // namespace
}  // namespace ceilplan::mission
