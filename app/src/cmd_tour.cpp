// `ceilplan tour`: an inspection tour of every target of a mission file, in ceiling mode, free
// mode or both, split into sorties for the least battery wear and exported to the autopilot.
// docs/tours.md.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "map_views.hpp"
#include "mission_file.hpp"
#include "output.hpp"
#include "planning_setup.hpp"
#include "tour_output.hpp"
#include "tour_run.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/planner_factory.hpp"
#include "ceilplan/core/error.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iomanip>
#include <optional>
#include <string>

namespace ceilplan::app {
namespace {

struct TourArguments {
  std::string mission, out, mode, autopilot = "px4";
  std::optional<std::uint32_t> seed;
  bool no_export = false;
  double standoff_m = 1.0;
  TourOptions options;
};

std::vector<PlanningMode> modesToRun(const std::string& mode) {
  if (mode == "both") return {PlanningMode::Ceiling, PlanningMode::Free};
  return {modeFromName(mode)};
}

void runTour(TourArguments a) {
  const MissionFile mission = readMissionFile(a.mission);
  std::optional<io::Autopilot> autopilot;
  if (!a.no_export) {
    try {
      mission.requireOrigin();  // fail before planning, not after
    } catch (const ceilplan::InputError& e) {
      throw ceilplan::InputError(std::string(e.what()) + "; or pass --no-export");
    }
    autopilot = a.autopilot == "ardupilot" ? io::Autopilot::ArduPilot : io::Autopilot::PX4;
  }
  if (a.mode.empty())
    a.mode = (mission.mode == "ceiling" || mission.mode == "free" || mission.mode == "both") ? mission.mode : "ceiling";
  a.options.seed = a.seed ? *a.seed : mission.seed;
  if (!planner::plannerInfo(a.options.planner).deterministic()) {
    // OMPL's generators are seeded once per process from the tour seed; the queries draw from
    // them in scheduling order and stop at a wall-clock limit, so legs are not bit-reproducible.
    if (a.options.seed == 0 || a.options.seed > 0xffffffffULL)
      throw ceilplan::InputError("--seed must lie in [1, 4294967295] for an OMPL planner");
    planner::seedOmpl(static_cast<std::uint32_t>(a.options.seed));
  }
  PlanningArguments planning = planningArguments(mission);
  planning.standoff_m = a.standoff_m;
  const PlanningSetup setup(planning);
  const std::vector<PlanningMode> modes = modesToRun(a.mode);

  std::printf("tour of %s: %zu targets, mode %s, planner %s, seed %llu, split for least %s wear\n",
              mission.file.c_str(), mission.targets.size(), a.mode.c_str(), a.options.planner.c_str(),
              static_cast<unsigned long long>(a.options.seed), a.options.ageing_model.c_str());
  std::fflush(stdout);
  const std::filesystem::path out(a.out);
  std::vector<TourResult> tours;
  for (PlanningMode mode : modes) {
    tours.push_back(planTour(mission, setup, mode, a.options));
    const std::filesystem::path dir = modes.size() > 1 ? out / tours.back().mode : out;
    writeTourDirectory(dir, tours.back(), mission, setup.environment(), autopilot);
    std::printf("%s", tourSummary(tours.back()).c_str());
    std::fflush(stdout);
  }
  if (tours.size() == 2) {
    const std::string table = comparisonTable(tours[0], tours[1]);
    std::printf("\n%s", table.c_str());
    std::vector<Eigen::Vector3d> routes;
    for (const TourResult& tour : tours)
      for (const auto& samples : tour.sortie_samples)
        for (const planner::PathSample& sample : samples) routes.push_back(sample.position_m);
    writeMapViews(out, setup.environment(), routes);
    writeTextAtomically(out / "comparison.txt", [&](std::ostream& stream) { stream << table; });
    writeTextAtomically(out / "comparison.json",
                        [&](std::ostream& stream) { stream << std::setw(2) << comparisonJson(tours[0], tours[1]) << '\n'; });
  }
  std::printf("\nwrote %s (tour.json, path.csv%s); figures: scripts/plot-tour %s\n", out.c_str(),
              autopilot ? ", mission.plan, mission.waypoints" : "", out.c_str());
}

const CommandRegistration registration(50, [](CLI::App& parent) {
  auto a = std::make_shared<TourArguments>();
  CLI::App* command = parent.add_subcommand(
      "tour", "Inspect every target of a mission file: viewpoints, legs, order, sorties, autopilot files");
  command->add_option("--mission", a->mission, "mission file (docs/missions.md)")->required()->check(CLI::ExistingFile);
  command->add_option("--out", a->out, "output directory")->required();
  command->add_option("--mode", a->mode, "ceiling, free or both (default: the mission's `mode` if one of these, else ceiling)")
      ->check(CLI::IsMember({"ceiling", "free", "both"}));
  command->add_option("--seed", a->seed, "seed of the order heuristic (default: the mission's)")
      ->check(CLI::Range(1u, 4294967295u));
  command->add_option("--planner", a->options.planner,
                      "leg planner: " + planner::defaultTourPlannerName() +
                          " (one lattice roadmap for all legs, deterministic), or a planner searching each pair of "
                          "places (OMPL's, or the lattice A*; slow on large maps)")
      ->capture_default_str()
      ->check(CLI::IsMember(planner::plannerNames()));
  command->add_option("--time-limit-s", a->options.time_limit_s,
                      "pairwise planners: search time per leg (refinement may take as long again)")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--lattice-spacing-m", a->options.lattice_spacing_m, "roadmap and lattice: node spacing")
      ->capture_default_str()->check(CLI::Range(0.01, 2.0));
  command->add_option("--lattice-stride", a->options.lattice_stride,
                      "roadmap and lattice: node spacing in voxels of the map instead (to be retired)")
      ->check(CLI::Range(1, 16));
  command->add_option("--workers", a->options.workers, "threads planning legs")->capture_default_str()->check(CLI::Range(1, 64));
  command->add_option("--ageing-model", a->options.ageing_model, "the sortie split minimises this model's wear")
      ->capture_default_str()
      ->check(CLI::IsMember(battery::ageingModelNames()));
  command->add_option("--standoff-m", a->standoff_m,
                      "free mode: the conventional distance from every structure, kept where it fits")
      ->capture_default_str()->check(nonNegativeFinite());
  command->add_option("--free-standoff-max-m", a->options.free_standoff_max_m,
                      "free mode: farthest viewpoint from a target (a conventional planner inspects from where its "
                      "standoff lets it, with a zoom lens)")
      ->capture_default_str()->check(positiveFinite());
  command->add_option("--autopilot", a->autopilot, "mission files for px4 or ardupilot")
      ->capture_default_str()->check(CLI::IsMember({"px4", "ardupilot"}));
  command->add_flag("--search-every-leg", [a](std::int64_t) { a->options.straight_when_clear = false; },
                    "never take a clear straight line in place of the searched route (default: take it where it is valid and "
                    "cheaper)");
  command->add_flag("--no-export", a->no_export, "skip mission.plan / mission.waypoints (no geodetic origin needed)");
  command->callback([a] { runTour(*a); });
});

}  // namespace
}  // namespace ceilplan::app
