// The tour's one flight record, specified in-process on the shipped bridge mission: path.csv's
// current integrates to tour.json's charge, the SOC is continuous across every leg and dwell
// boundary, wear recomputed from path.csv's SOC equals tour.json's, and tours that need 2, 3 or
// 5 batteries are planned and written in full under every ageing model.

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/io/csv_columns.hpp"
#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>

#include <unistd.h>

namespace ceilplan::mission {
namespace {

const std::filesystem::path kBridge = std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/bridge.yaml";

std::filesystem::path scratch(const std::string& name) {
  // One directory per process: ctest runs this suite's tests in parallel processes.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("ceilplan_tour_record_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

nlohmann::json readJson(const std::filesystem::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

// A tour planned and written once, in-process, as `ceilplan tour` would.
struct WrittenTour {
  TourResult tour;
  std::filesystem::path dir;
  nlohmann::json json;
};

WrittenTour planAndWrite(const Mission& mission, const PlanningContext& context, const TourOptions& options,
                         const std::string& name) {
  WrittenTour written{planTour(mission, context, FlightMode::Ceiling, options), scratch(name), {}};
  std::filesystem::create_directories(written.dir);
  io::Provenance provenance = io::Provenance::of("test_tour_record");
  provenance.seed = context.options().seed;
  io::writeTourDirectory(written.dir, written.tour, mission, context.environment(), io::Autopilot::PX4, provenance);
  written.json = readJson(written.dir / "tour.json");
  return written;
}

class BridgeTour : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    mission_ = std::make_unique<Mission>(io::readMission(kBridge));
    context_ = std::make_unique<PlanningContext>(*mission_);
    written_ = std::make_unique<WrittenTour>(planAndWrite(*mission_, *context_, TourOptions{}, "bridge"));
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(written_->dir);
    written_.reset();
    context_.reset();
    mission_.reset();
  }
  static std::unique_ptr<Mission> mission_;
  static std::unique_ptr<PlanningContext> context_;
  static std::unique_ptr<WrittenTour> written_;
};
std::unique_ptr<Mission> BridgeTour::mission_;
std::unique_ptr<PlanningContext> BridgeTour::context_;
std::unique_ptr<WrittenTour> BridgeTour::written_;

io::CsvColumns readPathCsv(const std::filesystem::path& dir) {
  return io::CsvColumns::read(dir / "path.csv", {"t_s", "current_a", "soc", "sortie", "speed_m_s"});
}

// The flight rows of path.csv (the recharge rows close each sortie at the start SOC).
bool isRechargeRow(const io::CsvColumns& csv, std::size_t row) { return csv.column("current_a")[row] < 0.0; }

TEST_F(BridgeTour, PathCsvCurrentIntegratesToTheTourCharge) {
  const io::CsvColumns csv = readPathCsv(written_->dir);
  const auto& t = csv.column("t_s");
  const auto& current = csv.column("current_a");
  const auto& sortie = csv.column("sortie");
  double charge_ah = 0.0;
  for (std::size_t k = 1; k < csv.rowCount(); ++k)
    if (sortie[k] == sortie[k - 1] && !isRechargeRow(csv, k))
      charge_ah += 0.5 * (current[k - 1] + current[k]) * (t[k] - t[k - 1]) / 3600.0;
  const double expected = written_->json["charge_ah"].get<double>();
  EXPECT_NEAR(charge_ah, expected, 1e-6 * expected);
  // The record itself, and the split that chose the sorties, agree to rounding.
  for (std::size_t k = 0; k < written_->tour.record.sorties.size(); ++k)
    EXPECT_NEAR(written_->tour.record.sorties[k].chargeAh(), written_->tour.plan.sorties[k].charge_ah,
                1e-12 * written_->tour.plan.sorties[k].charge_ah);
}

TEST_F(BridgeTour, SocIsContinuousAcrossEveryLegAndDwellBoundary) {
  const TourResult& tour = written_->tour;
  const double capacity_ah = context_->battery().pack.usableCapacityAh();
  int boundaries = 0;
  for (const SortieRecord& sortie : tour.record.sorties) {
    ASSERT_EQ(sortie.samples.size(), sortie.phases.size());
    EXPECT_DOUBLE_EQ(sortie.samples.front().soc, tour.start_soc);
    for (std::size_t k = 1; k < sortie.samples.size(); ++k) {
      const planner::PathSample& a = sortie.samples[k - 1];
      const planner::PathSample& b = sortie.samples[k];
      ASSERT_GE(b.t_s, a.t_s);
      // Every step, boundaries included, drops the SOC by exactly the charge drawn over it.
      const double drawn_ah = 0.5 * (a.current_a + b.current_a) * (b.t_s - a.t_s) / 3600.0;
      EXPECT_NEAR(a.soc - b.soc, drawn_ah / capacity_ah, 1e-12) << "sample " << k;
      if (sortie.phases[k] != sortie.phases[k - 1] || sortie.steps[k] != sortie.steps[k - 1]) {
        ++boundaries;
        // Across a boundary the position and the SOC carry over: no jump, no restart at 0.95.
        EXPECT_LT(std::fabs(a.soc - b.soc), 1e-3) << "boundary at sample " << k;
      }
    }
  }
  // 13 targets: a leg into each, a dwell at each, and the leg home.
  EXPECT_GE(boundaries, 2 * 13);
}

TEST_F(BridgeTour, DwellsAreFlownAtTheSocWhereTheVehicleHovers) {
  const TourResult& tour = written_->tour;
  const SortieRecord& sortie = tour.record.sorties.front();
  double last_dwell_soc = 1.0;
  int dwells = 0;
  for (std::size_t k = 1; k < sortie.samples.size(); ++k)
    if (sortie.phases[k] == FlightPhase::Dwell && sortie.phases[k - 1] == FlightPhase::Leg) {
      ++dwells;
      // Each dwell starts lower than the one before: the record does not reset it to one SOC.
      EXPECT_LT(sortie.samples[k].soc, last_dwell_soc);
      last_dwell_soc = sortie.samples[k].soc;
    }
  EXPECT_EQ(dwells, 13);
}

TEST_F(BridgeTour, WearFromPathCsvSocEqualsTheTourJson) {
  const io::CsvColumns csv = readPathCsv(written_->dir);
  std::vector<battery::AgeingSample> samples;
  for (std::size_t k = 0; k < csv.rowCount(); ++k)
    samples.push_back({csv.column("t_s")[k], csv.column("soc")[k], csv.column("current_a")[k], 1.0});
  for (const std::string model : {"fec", "xu", "woehler", "schmalstieg"}) {
    const std::unique_ptr<battery::AgeingModel> ageing =
        battery::makeAgeingModel(model, ageingModelOptions(written_->tour.planning.temperature_c));
    ageing->addSamples(samples);
    const double expected = written_->json["wear"][model]["cycle_wear"].get<double>();
    EXPECT_NEAR(ageing->cycleWear(), expected, 1e-6 * expected) << model;
  }
}

TEST_F(BridgeTour, WritesTheFlyingFilesAndItsTrajectoryPassesTheDenseRecheck) {
  for (const char* file : {"trajectory.csv", "trajectory.json", "report.html", "mission.plan", "mission.waypoints",
                           "routes.kml", "routes.geojson"})
    EXPECT_TRUE(std::filesystem::is_regular_file(written_->dir / file)) << file;
  // The KMZ needs a payload that can look where the tour looks; tour.json says which happened.
  const std::string dji = written_->json["dji_kmz"].get<std::string>();
  EXPECT_EQ(std::filesystem::is_regular_file(written_->dir / "mission.kmz"), dji == "written") << dji;
  const TourResult& tour = written_->tour;
  ASSERT_EQ(tour.trajectories.size(), tour.plan.sorties.size());
  for (const Trajectory& trajectory : tour.trajectories) {
    std::vector<Eigen::Vector3d> positions;
    for (const TrajectorySetpoint& s : trajectory.setpoints) positions.push_back(s.position_m);
    EXPECT_FALSE(context_->baseRules().checkPathDensely(positions)) << "sortie " << trajectory.sortie;
  }
  // Every viewpoint is a waypoint with the target's dwell, the camera aimed and a photo.
  int photos = 0;
  for (const SortieRoute& route : tour.routes)
    for (const RouteWaypoint& w : route.waypoints)
      if (w.take_photo) {
        ++photos;
        EXPECT_GT(w.hold_s, 0.0) << w.name;
        EXPECT_TRUE(w.gimbal_pitch_deg.has_value()) << w.name;
      }
  EXPECT_EQ(photos, 13);
}

TEST_F(BridgeTour, TheDutyProjectionIsAReportWithItsSettings) {
  const nlohmann::json& duty = written_->json["duty"];
  EXPECT_TRUE(duty["projected"].get<bool>());
  EXPECT_EQ(duty["days"], 30);
  EXPECT_GT(duty["fec_total"].get<double>(), 0.0);
}

// Smaller packs on the shipped bridge: tours of `sorties` sorties, planned and written in full
// under every ageing model (the duty projection may not fit the day: it says so and the plan
// is still written). Under "fec" wear follows charge, so the split flies the fewest sorties;
// the convex models may buy more, shallower ones.
void expectSorties(double capacity_ah, std::size_t sorties) {
  Mission mission = io::readMission(kBridge);
  mission.battery.pack.capacity_ah = capacity_ah;
  for (const std::string& model : battery::ageingModelNames()) {
    SCOPED_TRACE(model + ", " + std::to_string(capacity_ah) + " Ah");
    mission.planning.ageing_model = model;
    const PlanningContext context(mission);
    const WrittenTour written = planAndWrite(mission, context, {}, "pack_" + model);
    const std::size_t flown = written.tour.plan.sorties.size();
    if (model == "fec") {
      EXPECT_EQ(flown, sorties);
    } else {
      EXPECT_GE(flown, sorties);
    }
    EXPECT_EQ(written.json["sorties"].size(), flown);
    EXPECT_EQ(written.json["targets_visited"], 13);
    EXPECT_GE(written.json["min_soc"].get<double>(), mission.battery.reserve_soc);
    for (const char* file : {"tour.json", "path.csv", "map_top.csv", "map_side.csv"})
      EXPECT_TRUE(std::filesystem::is_regular_file(written.dir / file)) << file;
    for (std::size_t k = 1; k <= flown; ++k)
      for (const char* extension : {".plan", ".waypoints"})
        EXPECT_TRUE(std::filesystem::is_regular_file(written.dir / ("mission_sortie" + std::to_string(k) + extension)))
            << "sortie " << k << extension;
    // The turnarounds are part of the duration.
    double turnaround_s = 0.0;
    for (std::size_t k = 0; k + 1 < written.tour.plan.sorties.size(); ++k)
      turnaround_s += written.tour.plan.sorties[k].turnaround_s;
    EXPECT_NEAR(written.tour.plan.duration_s, written.tour.plan.flight_s + turnaround_s, 1e-6);
    const nlohmann::json& duty = written.json["duty"];
    if (!duty["projected"].get<bool>()) {
      EXPECT_FALSE(duty["note"].get<std::string>().empty());
    }
    std::filesystem::remove_all(written.dir);
  }
}

TEST(SmallPackBridgeTour, TwoSorties) { expectSorties(0.75, 2); }
TEST(SmallPackBridgeTour, ThreeSorties) { expectSorties(0.6, 3); }
TEST(SmallPackBridgeTour, FiveSorties) { expectSorties(0.37, 5); }

// A large tour (sparse legs, here from the third place on) that needs more sorties than it has
// split points: a stretch between two that no sortie can fly is divided until one can, so the
// tour flies (it was refused as if no sortie could reach its targets) and splits as it does with
// a split point at every position.
TEST(SmallPackBridgeTour, MoreSortiesThanSplitPointsFlyAsWithEveryPosition) {
  Mission mission = io::readMission(kBridge);
  mission.battery.pack.capacity_ah = 0.37;
  const PlanningContext context(mission);
  TourOptions options;
  options.all_pairs_max_places = 2;
  options.split_points = 2;
  const TourResult few = planTour(mission, context, FlightMode::Ceiling, options);
  options.split_points = 13;
  const TourResult every = planTour(mission, context, FlightMode::Ceiling, options);

  ASSERT_EQ(few.order.method, "neighbour-list 2-opt+or-opt");
  EXPECT_GE(few.plan.sorties.size(), 5u);
  std::multiset<int> flown;
  for (const Sortie& sortie : few.plan.sorties) {
    flown.insert(sortie.targets.begin(), sortie.targets.end());
    EXPECT_GE(sortie.lowest_soc, mission.battery.reserve_soc - 1e-12);
  }
  EXPECT_EQ(flown.size(), 13u);
  EXPECT_EQ(std::set<int>(flown.begin(), flown.end()).size(), 13u);
  ASSERT_EQ(few.plan.sorties.size(), every.plan.sorties.size());
  for (std::size_t s = 0; s < few.plan.sorties.size(); ++s)
    EXPECT_EQ(few.plan.sorties[s].targets, every.plan.sorties[s].targets) << "sortie " << s + 1;
  EXPECT_DOUBLE_EQ(few.plan.charge_ah, every.plan.charge_ah);
}

}  // namespace
}  // namespace ceilplan::mission
