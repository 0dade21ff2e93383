// --crs: projected coordinates into the local east-north-up frame, and the geodetic origin a
// mission file needs, checked against known points and GeographicLib's independent transverse
// Mercator (Karney 2011).

#include "run_command.hpp"
#include "scan_files.hpp"

#include "ceilplan/io/projected_frame.hpp"

#include <gtest/gtest.h>
#include <GeographicLib/LocalCartesian.hpp>
#include <GeographicLib/UTMUPS.hpp>
#include <nlohmann/json.hpp>

namespace ceilplan {
namespace {

constexpr double kVoxelAndRounding = 0.1 + 1e-9;

TEST(ProjectedFrame, TheUtmFalseOriginIsOnTheEquatorAtTheCentralMeridian) {
  // UTM zone 32N: easting 500 000 m lies on 9 deg E, northing 0 on the equator, by definition.
  const io::ProjectedFrame frame("EPSG:32632", {500000.0, 0.0, 12.5});
  EXPECT_NEAR(frame.origin().latitude_deg, 0.0, 1e-9);
  EXPECT_NEAR(frame.origin().longitude_deg, 9.0, 1e-9);
  EXPECT_DOUBLE_EQ(frame.origin().altitude_m, 12.5);
  EXPECT_EQ(frame.crsName(), "WGS 84 / UTM zone 32N");
}

TEST(ProjectedFrame, LocalCoordinatesAgreeWithGeographicLib) {
  const Eigen::Vector3d origin(691000.0, 5335000.0, 240.0);  // near Munich
  const io::ProjectedFrame frame("EPSG:32632", origin);
  double lat0, lon0;
  GeographicLib::UTMUPS::Reverse(32, true, origin.x(), origin.y(), lat0, lon0);
  EXPECT_NEAR(frame.origin().latitude_deg, lat0, 1e-9);
  EXPECT_NEAR(frame.origin().longitude_deg, lon0, 1e-9);

  std::vector<Eigen::Vector3d> points = {origin, origin + Eigen::Vector3d(120.0, -80.0, 15.0),
                                         origin + Eigen::Vector3d(-300.0, 450.0, -5.0)};
  const std::vector<Eigen::Vector3d> projected = points;
  frame.toLocal(points);
  const GeographicLib::LocalCartesian enu(lat0, lon0, origin.z());
  for (std::size_t i = 0; i < points.size(); ++i) {
    double lat, lon, x, y, z;
    GeographicLib::UTMUPS::Reverse(32, true, projected[i].x(), projected[i].y(), lat, lon);
    enu.Forward(lat, lon, projected[i].z(), x, y, z);
    EXPECT_NEAR(points[i].x(), x, 1e-3) << i;
    EXPECT_NEAR(points[i].y(), y, 1e-3) << i;
    EXPECT_NEAR(points[i].z(), z, 1e-3) << i;
  }
  EXPECT_LT(points[0].norm(), 1e-6);
  // Grid north is not true north away from the central meridian: the frame turns by the
  // convergence (about 1.5 deg here), so a grid-east step gains a northing.
  EXPECT_GT(std::abs(points[1].y() - (-80.0)), 1.0);
}

TEST(ProjectedFrame, TheOriginNearTheDataIsRounded) {
  EXPECT_TRUE(io::ProjectedFrame::originNear({{100.4, 200.2, 7.9}, {110.2, 230.9, 9.3}})
                  .isApprox(Eigen::Vector3d(105.0, 216.0, 7.0)));
}

TEST(ProjectedFrame, RefusesCodesThatAreNotProjectedCrs) {
  EXPECT_THROW(io::ProjectedFrame::validate("EPSG:4326"), InputError);    // geographic: degrees
  EXPECT_THROW(io::ProjectedFrame::validate("EPSG:999999"), InputError);  // no such code
  EXPECT_THROW(io::ProjectedFrame::validate("32632"), InputError);        // malformed
  EXPECT_NO_THROW(io::ProjectedFrame::validate("EPSG:5555"));             // compound: UTM 32N + DHHN92 height
}

TEST(ImportCrs, MovesAUtmCloudNearTheOriginAndPrintsTheMissionOrigin) {
  const auto dir = testing::scratchDirectory("crs");
  // A deck 10 x 6 m at 253 m over ground at 250.2 m, in UTM 32N coordinates.
  auto points = testing::sampleRectangle({499995.0, 5315997.0, 250.2}, {10, 0, 0}, {0, 6, 0}, 0.05);
  const auto deck = testing::sampleRectangle({499995.0, 5315997.0, 253.0}, {10, 0, 0}, {0, 6, 0}, 0.05);
  points.insert(points.end(), deck.begin(), deck.end());
  testing::writePlyPoints(dir / "utm.ply", points);
  const auto result =
      testing::runCeilplan("import --points " + (dir / "utm.ply").string() +
                           " --crs EPSG:32632 --resolution 0.1 --free-distance 0 --out " + (dir / "utm.bt").string());
  ASSERT_EQ(result.exit_code, 0) << result.err;
  double lat, lon;
  GeographicLib::UTMUPS::Reverse(32, true, 500000.0, 5316000.0, lat, lon);
  char expected[96];
  std::snprintf(expected, sizeof expected, "origin: {lat: %.8f, lon: 9.00000000, alt: 250.000}", lat);
  EXPECT_NE(result.out.find(expected), std::string::npos) << result.out;
  const auto sidecar = nlohmann::json::parse(testing::readWholeFile(dir / "utm.bt.json"));
  EXPECT_NEAR(sidecar["crs"]["origin"]["lat"].get<double>(), lat, 1e-9);
  EXPECT_NEAR(sidecar["crs"]["origin"]["lon"].get<double>(), 9.0, 1e-9);
  EXPECT_EQ(sidecar["crs"]["local_origin_in_crs"], nlohmann::json({500000.0, 5316000.0, 250.0}));
  // The map sits around the local origin, 0.2 m to 3 m up, to a voxel.
  const auto& min = sidecar["extent_m"]["min"];
  const auto& max = sidecar["extent_m"]["max"];
  EXPECT_NEAR(min[0].get<double>(), -5.0, kVoxelAndRounding);
  EXPECT_NEAR(max[0].get<double>(), 5.0, kVoxelAndRounding);
  EXPECT_NEAR(min[1].get<double>(), -3.0, kVoxelAndRounding);
  EXPECT_NEAR(max[1].get<double>(), 3.0, kVoxelAndRounding);
  EXPECT_NEAR(min[2].get<double>(), 0.2, kVoxelAndRounding);
  EXPECT_NEAR(max[2].get<double>(), 3.0, kVoxelAndRounding);
}

}  // namespace
}  // namespace ceilplan
