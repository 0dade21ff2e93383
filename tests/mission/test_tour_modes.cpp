// planTours: both modes of a tour planned at once over one shared context are the modes planned
// one after the other, to the byte of every file written, and the front end hears of them (the
// tours, the progress) from its own thread only, in order. On the shipped tunnel crown's coverage
// mission (photos, sparse legs, the roadmap), in-process and from the command line.

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/mission/planning_context.hpp"
#include "ceilplan/mission/tour_planner.hpp"
#include "run_command.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <stdexcept>
#include <thread>

namespace ceilplan::mission {
namespace {

using testing::readWholeFile;
using testing::runCeilplan;
using testing::scratchDirectory;

const std::filesystem::path kTunnelCrown =
    std::filesystem::path(CEILPLAN_SOURCE_DIR) / "maps/coverage/tunnel_crown.yaml";

// What a tour writes that its plan decides (the trajectories and figures follow from them).
const char* const kPlanFiles[] = {"tour.json", "path.csv", "photos.csv", "coverage.json", "coverage_elements.csv"};

void writeTour(const std::filesystem::path& dir, const TourResult& tour, const Mission& mission,
               const PlanningContext& context) {
  std::filesystem::create_directories(dir);
  io::Provenance provenance = io::Provenance::of("test_tour_modes");
  provenance.seed = context.options().seed;
  io::writeTourDirectory(dir, tour, mission, context.environment(), std::nullopt, provenance);
}

TEST(TourModes, BothModesPlannedAtOnceWriteWhatEachModePlannedAloneWrites) {
  const Mission mission = io::readMission(kTunnelCrown);
  const PlanningContext context(mission);
  const std::filesystem::path dir = scratchDirectory("tour_modes_library");
  const std::thread::id caller = std::this_thread::get_id();
  std::set<std::thread::id> progress_threads;
  std::set<std::string> stages;
  std::vector<FlightMode> handed;
  TourOptions options;
  options.workers = 2;  // the modes at once
  options.progress = [&](const std::string& stage, double) {
    progress_threads.insert(std::this_thread::get_id());
    stages.insert(stage.substr(0, stage.find(": ")));
  };
  const std::vector<TourResult> tours =
      planTours(mission, context, {FlightMode::Ceiling, FlightMode::Free}, options, [&](const TourResult& tour) {
        EXPECT_EQ(std::this_thread::get_id(), caller);
        handed.push_back(tour.mode);
        writeTour(dir / "both" / flightModeName(tour.mode), tour, mission, context);
      });
  ASSERT_EQ(tours.size(), 2u);
  EXPECT_EQ(handed, (std::vector<FlightMode>{FlightMode::Ceiling, FlightMode::Free}));
  EXPECT_EQ(progress_threads, std::set<std::thread::id>{caller});
  EXPECT_EQ(stages.count("ceiling mode"), 1u);
  EXPECT_EQ(stages.count("free mode"), 1u);
  ASSERT_TRUE(tours[1].coverage);
  EXPECT_GT(tours[1].stops.size(), static_cast<std::size_t>(options.all_pairs_max_places));  // sparse legs

  for (const FlightMode mode : {FlightMode::Ceiling, FlightMode::Free}) {
    const TourResult alone = planTour(mission, context, mode, TourOptions{});
    writeTour(dir / "alone" / flightModeName(mode), alone, mission, context);
    for (const char* file : kPlanFiles)
      EXPECT_EQ(readWholeFile(dir / "both" / flightModeName(mode) / file),
                readWholeFile(dir / "alone" / flightModeName(mode) / file))
          << flightModeName(mode) << " mode: " << file;
  }
}

// A front end that fails on the first tour (its outputs cannot be written, say) gets its own
// error back, and the other mode is stopped rather than waited for to the end.
TEST(TourModes, AnErrorFromTheFrontEndStopsTheOtherMode) {
  const Mission mission = io::readMission(kTunnelCrown);
  const PlanningContext context(mission);
  TourOptions options;
  options.progress = [](const std::string&, double) {};
  int handed = 0;
  EXPECT_THROW(planTours(mission, context, {FlightMode::Ceiling, FlightMode::Free}, options,
                         [&](const TourResult&) {
                           ++handed;
                           throw std::runtime_error("disk full");
                         }),
               std::runtime_error);
  EXPECT_EQ(handed, 1);
}

// `ceilplan tour --mode both` plans the modes at once from 2 workers, one after the other with 1:
// the same files but for the command line in their provenance.
TEST(TourModes, TheCommandWritesTheSameToursWithTheModesAtOnceOrOneAfterTheOther) {
  const std::filesystem::path dir = scratchDirectory("tour_modes_command");
  for (const char* workers : {"1", "2"}) {
    const testing::CommandResult result =
        runCeilplan("tour --mission " + kTunnelCrown.string() + " --mode both --no-export --workers " + workers +
                    " --out " + (dir / workers).string());
    ASSERT_EQ(result.exit_code, 0) << result.err;
  }
  const auto withoutProvenance = [](const std::filesystem::path& file) {
    if (file.extension() == ".json") {
      nlohmann::json json = nlohmann::json::parse(readWholeFile(file));
      json["provenance"].erase("command");
      return json.dump();
    }
    const std::string text = readWholeFile(file);
    return text.substr(text.find('\n') + 1);  // the first line: the provenance comment
  };
  for (const char* mode : {"ceiling", "free"})
    for (const char* file : kPlanFiles)
      EXPECT_EQ(withoutProvenance(dir / "1" / mode / file), withoutProvenance(dir / "2" / mode / file))
          << mode << "/" << file;
  EXPECT_EQ(withoutProvenance(dir / "1" / "comparison.json"), withoutProvenance(dir / "2" / "comparison.json"));
}

}  // namespace
}  // namespace ceilplan::mission
