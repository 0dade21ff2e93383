// `ceilplan tour`: an inspection tour of every target of a mission file (point targets, contact
// grid points and, for a coverage mission, the photos of its surfaces), in ceiling mode, free
// mode or both, split into sorties for the least battery wear and exported to the autopilot.
// docs/tours.md, docs/coverage.md.

#include "cli_checks.hpp"
#include "command_registry.hpp"
#include "map_options.hpp"
#include "output.hpp"

#include "ceilplan/io/mission_file.hpp"
#include "ceilplan/io/output_set.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/io/tour_files.hpp"
#include "ceilplan/io/unknown_space_report.hpp"
#include "ceilplan/mission/route_planning.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/install_paths.hpp"
#include "ceilplan/planner/flight_planner.hpp"
#include "ceilplan/planner/planner_factory.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace ceilplan::app {
namespace {

// Flags that override a setting of the mission's (Mission::planning) when given.
struct TourArguments {
  std::string mission, out, mode, autopilot = "px4";
  std::optional<std::uint32_t> seed;
  std::optional<std::string> ageing_model;
  std::optional<double> standoff_m;
  bool no_export = false;
  UnknownSpaceFlags unknown;
  mission::TourOptions options;
};

void runTour(TourArguments a) {
  mission::Mission mission = io::readMission(a.mission);
  mission::PlanningOptions& settings = mission.planning;
  if (a.seed) settings.seed = *a.seed;
  if (a.ageing_model) settings.ageing_model = *a.ageing_model;
  if (a.standoff_m) settings.standoff_m = *a.standoff_m;
  if (a.unknown.given()) settings.unknown = a.unknown.value();
  // Checked and staged before any work; in place only when complete.
  io::OutputSet out(a.out, commandInputs({{"--mission", a.mission},
                                          {"the mission's map", mission.map_file},
                                          {"the mission's vehicle", mission.vehicle_file}}));
  // Without the mission's origin the geodetic exports are skipped and said so; the rest is written.
  std::optional<io::Autopilot> autopilot;
  if (!a.no_export) autopilot = a.autopilot == "ardupilot" ? io::Autopilot::ArduPilot : io::Autopilot::PX4;
  if (a.mode.empty()) a.mode = mission.mode.empty() ? "ceiling" : mission.mode;
  settings.validate();  // before indexing the map
  a.options.validate();
  // OMPL's generators are seeded once per process from the tour seed; the queries draw from
  // them in scheduling order and stop at a wall-clock limit, so OMPL legs are not bit-reproducible.
  if (!planner::plannerInfo(a.options.planner).deterministic()) planner::seedOmpl(settings.seed);
  const ProgressCallback progress = terminalProgress();
  const mission::PlanningContext context(mission, progress);
  const std::vector<mission::FlightMode> modes = mission::tourFlightModes(a.mode);
  a.options.progress = progress;

  const io::Provenance provenance = io::tourProvenance(commandProvenance(), mission, settings.seed);

  print(io::tourHeadline(mission, a.mode, a.options, settings) +
        "unknown space: " + io::unknownSpaceLine(context.environment()) + "\n");
  // Both modes are planned at once; each is written and summarised as soon as it (and ceiling
  // mode, before it) is planned.
  const std::vector<mission::TourResult> tours =
      mission::planTours(mission, context, modes, a.options, [&](const mission::TourResult& tour) {
        const std::filesystem::path dir =
            modes.size() > 1 ? out.path() / mission::flightModeName(tour.mode) : out.path();
        io::writeTourDirectory(dir, tour, mission, context.environment(), autopilot, provenance);
        print(io::tourSummary(tour));
        if (autopilot) print(io::exportNotes(tour, mission));
      });
  if (tours.size() == 2) {
    print("\n" + io::comparisonTable(tours[0], tours[1]));
    io::writeTourComparison(out.path(), tours[0], tours[1], mission, context.environment(), provenance);
  }
  out.commit();
  print("\n" + io::tourFilesLine(a.out, mission, tours, autopilot));
}

const CommandRegistration registration(50, [](CLI::App& parent) {
  auto a = std::make_shared<TourArguments>();
  CLI::App* command = parent.add_subcommand("tour",
                                            "Inspect every target of a mission file (point targets, contact grids, "
                                            "surfaces to photograph): stops, legs, order, "
                                            "sorties, autopilot files");
  command->add_option("--mission", a->mission, "mission file (" + docPage("missions.md") + ")")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", a->out, "output directory")->required();
  command
      ->add_option("--mode", a->mode,
                   "ceiling, free or both (default: the mission's `mode` if one of these, else ceiling)")
      ->check(CLI::IsMember({"ceiling", "free", "both"}));
  command->add_option("--seed", a->seed, "seed of the order heuristic (default: the mission's)")
      ->check(CLI::Range(1u, 4294967295u));
  command
      ->add_option("--planner", a->options.planner,
                   "leg planner: " + planner::defaultTourPlannerName() +
                       " (one lattice roadmap for all legs, deterministic), or a planner searching each pair of "
                       "places (OMPL's, or the lattice A*; slow on large maps)")
      ->capture_default_str()
      ->check(CLI::IsMember(planner::plannerNames()));
  command->add_option("--time-limit-s", a->options.time_limit_s, "pairwise planners: search time per leg, up to a day")
      ->capture_default_str()
      ->check(positiveFinite() & atMost(planner::PlanRequest::kMaxTimeLimit_s));
  command->add_option("--lattice-spacing-m", a->options.lattice_spacing_m, "roadmap and lattice: node spacing")
      ->capture_default_str()
      ->check(finiteRange(planner::kMinLatticeSpacing_m, planner::kMaxLatticeSpacing_m));
  command
      ->add_option("--workers", a->options.workers,
                   "threads planning legs; from 2, --mode both plans its two modes at once")
      ->capture_default_str()
      ->check(CLI::Range(1, 64));
  command
      ->add_option("--all-pairs-max-places", a->options.all_pairs_max_places,
                   "a leg between every pair of places (home and the stops) up to this many; beyond, legs between "
                   "near neighbours, routed once a plan flies them")
      ->capture_default_str()
      ->check(CLI::Range(2, 100000));
  command
      ->add_option("--neighbours", a->options.neighbours,
                   "large tours: the order search joins each place only to its nearest this many")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  command
      ->add_option("--split-points", a->options.split_points,
                   "large tours: sorties may start at at least this many evenly spaced positions of the order, more "
                   "where the tour needs more sorties, and around the best of them")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  command
      ->add_option("--order-kicks", a->options.order_kicks,
                   "large tours: rounds of iterated local search after the first (from the seed; slower, a little "
                   "cheaper)")
      ->capture_default_str()
      ->check(CLI::Range(0, 100000));
  command->add_option("--ageing-model", a->ageing_model, "the sortie split minimises this model's wear")
      ->default_str(mission::PlanningOptions{}.ageing_model)
      ->check(CLI::IsMember(battery::ageingModelNames()));
  a->unknown.addTo(*command);
  command
      ->add_option("--standoff-m", a->standoff_m,
                   "free mode: the conventional distance from every structure, kept where it fits")
      ->default_str(formatNumber(mission::PlanningOptions{}.standoff_m))
      ->check(nonNegativeFinite());
  command
      ->add_option("--free-standoff-max-m", a->options.free_standoff_max_m,
                   "free mode: a target whose standoff range keeps less than --standoff-m may be seen from up to "
                   "this far (a zoom lens), reported as beyond its range (default: every viewpoint within its "
                   "target's range)")
      ->check(positiveFinite() & atMost(mission::InspectionTarget::kMaxStandoff_m));
  command->add_option("--autopilot", a->autopilot, "mission files for px4 or ardupilot")
      ->capture_default_str()
      ->check(CLI::IsMember({"px4", "ardupilot"}));
  command->add_flag(
      "--search-every-leg", [a](std::int64_t) { a->options.straight_when_clear = false; },
      "never take a clear straight line in place of the searched route (default: take it where it is valid and "
      "cheaper)");
  command->add_flag(
      "--no-export", a->no_export,
      "skip the geodetic exports (mission.plan, mission.waypoints, mission.kmz, routes.kml, routes.geojson), which a "
      "mission without an origin skips anyway");
  command
      ->add_option("--missions-per-day", a->options.missions_per_day,
                   "duty projection: tours a day (default: as many as fit in a day, at most 15)")
      ->check(CLI::Range(1, 1000));
  command->add_option("--days", a->options.days, "duty projection: days")
      ->capture_default_str()
      ->check(CLI::Range(1, 3650));
  command->add_option("--idle-min", a->options.idle_min, "duty projection: idle after each tour, up to a day")
      ->capture_default_str()
      ->check(finiteAtLeast(0.0) & atMost(mission::DutyOptions::kMaxMinutes));
  command
      ->add_option("--charge-max-min", a->options.charge_max_min,
                   "duty projection: longest charge back to the start SOC after each sortie, up to a day")
      ->capture_default_str()
      ->check(positiveFinite() & atMost(mission::DutyOptions::kMaxMinutes));
  command->callback([a] { runTour(*a); });
});

}  // namespace
}  // namespace ceilplan::app
