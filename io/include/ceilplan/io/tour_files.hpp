#pragma once
/// @file
/// What `ceilplan tour` writes for one mode (tour.json, path.csv, the autopilot missions) and,
/// for both modes, the comparison table. docs/tours.md describes every file.

#include "ceilplan/io/autopilot_export.hpp"
#include "ceilplan/io/dji_wpml.hpp"
#include "ceilplan/io/provenance.hpp"
#include "ceilplan/mission/mission.hpp"
#include "ceilplan/mission/tour_planner.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io {

/// A tour's provenance: `provenance` (the command line, and any input it has already) with the
/// mission, map and vehicle files and the seed.
Provenance tourProvenance(Provenance provenance, const mission::Mission& mission, std::uint64_t seed);

/// The geodetic exports (the autopilot missions, the KMZ, KML and GeoJSON) a tour of `mission`
/// skips because the mission has no origin: none when it has one. The local-frame outputs are
/// always written.
std::vector<std::string> geodeticExportsSkipped(const mission::Mission& mission);
/// The one line that names them and says why, e.g. "geodetic exports skipped (mission.plan, ...):
/// scan.yaml has no 'origin:' ...; every local-frame output was written".
std::string geodeticExportsSkippedLine(const mission::Mission& mission);

/// Why the tour's DJI KMZ cannot be written for the mission's aircraft and payload (`dji:`; a
/// gimbal pitch beyond the payload's range, naming the sortie and waypoint), or none.
std::optional<std::string> djiExportProblem(const mission::TourResult& tour, const mission::Mission& mission);
/// Every value the KMZ writes as the nearest one DJI's ranges allow (none when it is not written).
std::vector<DjiClamp> djiClamps(const mission::TourResult& tour, const mission::Mission& mission);
/// What the autopilot files say about the tour, for the terminal: the KMZ not written and why, or
/// the values it clamped to DJI's ranges; empty when there is nothing to say.
std::string exportNotes(const mission::TourResult& tour, const mission::Mission& mission);

/// The places a tour stops at, by kind: point targets, contact readings, photos; all of them and
/// those its sorties fly.
struct StopCounts {
  int targets = 0, targets_visited = 0;
  int contact_readings = 0, contact_readings_taken = 0;
  int photos = 0, photos_taken = 0;
  /** @var targets
   *  Point targets of the mission. */
  /** @var targets_visited
   *  Point targets the sorties fly to. */
  /** @var contact_readings
   *  Contact grid points of the mission. */
  /** @var contact_readings_taken
   *  Contact grid points the sorties read. */
  /** @var photos
   *  Photos of the coverage plan. */
  /** @var photos_taken
   *  Photos the sorties take. */
};
/// The stop counts of `tour`.
StopCounts stopCounts(const mission::TourResult& tour);

/// Everything of the tour (docs/tours.md, "Outputs"), with the mission, map and vehicle named.
nlohmann::json tourJson(const mission::TourResult& tour, const mission::Mission& mission, const Provenance& provenance);

/// Per sortie as tour.json gives it: targets, legs (from, to, charge_ah, duration_s, length_m,
/// waypoints), take-off and landing heights, take-off time, charge, flight and turnaround times,
/// FEC, DoD, lowest SOC, wear and the reason it ends where it does.
nlohmann::json tourSortiesJson(const mission::TourResult& tour);

/// One row of path.csv: a flown sample on the tour's clock (phase "leg" or "dwell"), or the pack's
/// recharge after a sortie (phase "recharge": its end, the mean charge current as a negative
/// current, the start SOC). Gaps are infinite where no surface is within reach.
struct TourPathRow {
  double t_s = 0.0;                                      ///< Time on the tour's clock (s).
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  ///< Body position (m, map frame).
  double speed_m_s = 0.0;                                ///< Ground speed (m/s).
  double ceiling_gap_m = 0.0;                            ///< Gap from the rotors to the ceiling (m).
  double current_a = 0.0;                                ///< Pack current (A); negative while recharging.
  double soc = 0.0;                                      ///< State of charge (fraction).
  int sortie = 1;                                        ///< Sortie number, from 1.
  double ground_gap_m = 0.0;                             ///< Gap from the rotors to the ground (m).
  const char* phase = "leg";                             ///< "leg", "dwell" or "recharge".
  bool assumed_free = false;                             ///< In unknown space the policy assumed free.
};
/// The rows of path.csv for `tour`, in order.
std::vector<TourPathRow> tourPathRows(const mission::TourResult& tour);

/// The flight record: a provenance comment line, then
/// t_s,x,y,z,speed_m_s,ceiling_gap_m,current_a,soc,sortie,ground_gap_m,phase with every sample
/// of every sortie on the tour's clock (phase leg or dwell), and after each sortie a row for the
/// pack's recharge back to the start SOC (phase recharge: its end, on the pack's clock).
void writeTourPathCsv(const std::filesystem::path& file, const mission::TourResult& tour, const Provenance& provenance);

/// One autopilot mission per sortie from the tour's routes (mission/tour_routes.hpp): the camera
/// aimed and a photo at each viewpoint. Throws ceilplan::InputError without a geodetic origin.
std::vector<AutopilotMission> autopilotMissions(const mission::TourResult& tour, const mission::Mission& mission,
                                                Autopilot autopilot);

/// DIR/tour.json, DIR/path.csv, DIR/map_top.csv, DIR/map_side.csv, DIR/trajectory.csv and
/// DIR/trajectory.json (per sortie when several: trajectory_sortie2.csv, ...), DIR/report.html
/// and, with `autopilot` and the mission's origin, DIR/mission.plan, DIR/mission.waypoints and
/// DIR/mission.kmz (DJI WPML) per sortie, DIR/routes.kml and DIR/routes.geojson (docs/tours.md,
/// docs/flying.md); without an origin those are skipped (geodeticExportsSkipped, tour.json
/// geodetic_exports_skipped).
void writeTourDirectory(const std::filesystem::path& dir, const mission::TourResult& tour,
                        const mission::Mission& mission, const environment::Environment& environment,
                        std::optional<Autopilot> autopilot, const Provenance& provenance);

/// The side-by-side table of two modes (ceiling first), as printed and as DIR/comparison.txt.
std::string comparisonTable(const mission::TourResult& ceiling, const mission::TourResult& free);
/// comparison.json: both modes' figures, with the provenance (which names the mission, map and vehicle).
nlohmann::json comparisonJson(const mission::TourResult& ceiling, const mission::TourResult& free,
                              const Provenance& provenance);
/// DIR/comparison.txt, DIR/comparison.json, DIR/report.html (both modes) and map views covering both routes.
void writeTourComparison(const std::filesystem::path& dir, const mission::TourResult& ceiling,
                         const mission::TourResult& free, const mission::Mission& mission,
                         const environment::Environment& environment, const Provenance& provenance);

/// `ceilplan tour`'s first line: what the mission inspects, the mode ("ceiling", "free" or
/// "both"), the leg planner, the seed and the model whose wear the sortie split minimises.
std::string tourHeadline(const mission::Mission& mission, const std::string& mode, const mission::TourOptions& options,
                         const mission::PlanningOptions& settings);
/// Its last lines: each directory written (DIR, or DIR/ceiling and DIR/free for both modes) with
/// the files in it (the DJI KMZ only where it was written), the geodetic exports skipped for want
/// of an origin (geodeticExportsSkippedLine), then the command that draws the figures.
std::string tourFilesLine(const std::filesystem::path& dir, const mission::Mission& mission,
                          const std::vector<mission::TourResult>& tours, std::optional<Autopilot> autopilot);

/// One paragraph for the terminal: targets, sorties with their reasons, totals, in free mode
/// standoffLine, where the time went and, for a coverage tour, what its photos cover (re-check).
std::string tourSummary(const mission::TourResult& tour);
/// Free mode (tour.standoff set): where the tour kept less than the conventional standoff, e.g.
/// "standoff 1 m: kept over 20.3 of 55.1 m flown, narrowed over 34.8 m on 9 legs; 9 of 9
/// viewpoints keep less; closest: the airframe's bounding sphere 0.12 m from the nearest
/// structure at (8.50, 0.24, 1.52) (tour.json: standoff)"; a negative closest approach is said as
/// the overlap it is (standoffText).
std::string standoffLine(const mission::TourResult& tour);
/// The point targets given inside a structure and moved onto its surface (TourStop::given_point_m),
/// each with how far and from where to where, e.g. "1 target(s) given inside a structure moved
/// onto its surface: 'deck' by 0.08 m, from (10.00, 0.00, 6.08) to (10.00, 0.00, 6.00) (tour.json:
/// targets[].moved_onto_surface_m)"; none when no target was moved.
std::optional<std::string> movedOntoSurfaceLine(const mission::TourResult& tour);
/// Free mode: the point targets whose standoff range holds no viewpoint keeping the conventional
/// standoff and where each was seen from, e.g. "1 target(s) keep less than the 1 m standoff, as no
/// viewpoint in their standoff range keeps it: 'deck_bay_14_north' seen from 1.50 m, within its
/// range 0.3-1.5 m, with the airframe's bounding sphere 0.97 m from the nearest structure
/// (tour.json: standoff.limited_targets)"; none when every target's range keeps it.
std::optional<std::string> standoffLimitedLine(const mission::TourResult& tour);

}  // namespace ceilplan::io
