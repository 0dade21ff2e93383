// The hostile-input suite: every command of `ceilplan`, run as a user would, with bad maps,
// numbers, keys, output locations and CSV files. Each row states the exit code (docs/cli.md),
// a fragment of the one-line message, and that the run leaves its directory exactly as it
// found it: no output, no partial set, no temporary or staging file, no created parent.
#include "run_command.hpp"

#include <octomap/ColorOcTree.h>
#include <octomap/OcTree.h>

#include <gtest/gtest.h>

#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <ostream>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

using ceilplan::testing::CommandResult;
using ceilplan::testing::readWholeFile;
using ceilplan::testing::runCeilplan;
using ceilplan::testing::scratchDirectory;
using ceilplan::testing::substituted;

namespace {

namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::string& bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << bytes;
}

// ---- Fixtures, written once and shared by every test process -------------------------------

// A 6 x 6 m room at 0.1 m: floor top at 0.2 m, a ceiling slab from 4.0 to 4.3 m, free between.
// Written as an OcTree (.bt) and as a ColorOcTree (.ot) with the same occupancy.
void writeRoomMaps(const fs::path& bt, const fs::path& color_ot) {
  octomap::OcTree tree(0.1);
  octomap::ColorOcTree color(0.1);
  for (int k = 0; k < 43; ++k)
    for (int j = 0; j < 60; ++j)
      for (int i = 0; i < 60; ++i) {
        const octomap::point3d p(-3.0 + 0.1 * i + 0.05, -3.0 + 0.1 * j + 0.05, 0.1 * k + 0.05);
        const bool occupied = p.z() < 0.2 || p.z() > 4.0;
        const float log_odds = occupied ? tree.getClampingThresMaxLog() : tree.getClampingThresMinLog();
        tree.setNodeValue(p, log_odds, true);
        color.setNodeValue(p, log_odds, true);
        if (occupied) color.setNodeColor(p.x(), p.y(), p.z(), 200, 120, 40);
      }
  tree.updateInnerOccupancy();
  color.updateInnerOccupancy();
  if (!tree.writeBinary(bt.string()) || !color.write(color_ot.string()))
    throw std::runtime_error("cannot write the fixture maps");
}

// A mission on the room: home on the floor, one target on the ceiling's underside.
std::string missionText(const fs::path& fixtures) {
  return "map: " + (fixtures / "room.bt").string() + "\nvehicle: " + (fixtures / "vehicle.yaml").string() +
         "\n"
         "battery: {capacity_ah: 5.2, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 10.4}\n"
         "home: [-2.0, 0.0, 1.0]\n"
         "origin: {lat: 52.2, lon: 0.09, alt: 12.0}\n"
         "speeds: {cruise_m_s: 2.0, inspection_m_s: 0.5, climb_m_s: 1.0, descent_m_s: 0.8}\n"
         "seed: 1\n"
         "targets:\n"
         "  - {name: ceiling_east, point: [1.5, 0.0, 4.0], dwell_s: 10, standoff_m: [0.3, 1.5]}\n";
}

void writeFixtures(const fs::path& dir) {
  writeRoomMaps(dir / "room.bt", dir / "color.ot");
  const std::string room = readWholeFile(dir / "room.bt");
  writeFile(dir / "truncated.bt", room.substr(0, room.size() / 2));
  writeFile(dir / "trailing.bt", room + "\n\n");
  writeFile(dir / "two_trees.bt", room + room);
  writeFile(dir / "empty.bt", "");
  std::mt19937 rng(12);  // fixed: the same junk every run
  std::string junk(4096, '\0');
  for (char& c : junk) c = static_cast<char>(rng() & 0xff);
  writeFile(dir / "random.bt", junk);
  fs::create_directories(dir / "adir");
  fs::copy_file(fs::path(CEILPLAN_SOURCE_DIR) / "maps/vehicles/quad.yaml", dir / "vehicle.yaml");
  writeFile(dir / "battery.yaml", "capacity_ah: 5.2\nstart_soc: 0.95\ncharge_current_a: 10.4\n");
  writeFile(dir / "mission.yaml", missionText(dir));
  writeFile(dir / "path.csv", "x,y,z\n-2,0,1\n0,0,1\n2,0,1\n");
  writeFile(dir / "soc.csv", "t_s,soc\n0,0.9\n10,0.5\n20,0.8\n30,0.3\n");
  writeFile(dir / "points.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 1\n");
}

// Built under a private name and renamed into place: parallel test processes race safely.
const fs::path& fixtures() {
  static const fs::path dir = [] {
    fs::path final_dir = fs::path(CEILPLAN_TEST_TMP) / "hostile_fixtures_v2";
    if (fs::exists(final_dir / "mission.yaml")) return final_dir;
    const fs::path staging = fs::path(CEILPLAN_TEST_TMP) / ("hostile_fixtures_v2.build" + std::to_string(::getpid()));
    fs::remove_all(staging);
    fs::create_directories(staging);
    // The mission names its map by absolute path: write it for the final directory.
    writeFixtures(staging);
    writeFile(staging / "mission.yaml", missionText(final_dir));
    std::error_code ec;
    fs::rename(staging, final_dir, ec);  // fails if another process was first: use its copy
    fs::remove_all(staging, ec);
    return final_dir;
  }();
  return dir;
}

// Named pipes, one per kind of input, that no one ever writes to: a reader that opens one blocks
// for ever. Kept apart from {fx} and {dir}, whose snapshots read every file.
const fs::path& fifos() {
  static const fs::path dir = [] {
    fs::path fifo_dir = fs::path(CEILPLAN_TEST_TMP) / "hostile_fifos_v1";
    fs::create_directories(fifo_dir);
    for (const char* name : {"map.bt", "mission.yaml", "vehicle.yaml", "battery.yaml", "config.yaml", "in.csv",
                             "points.xyz", "points.pcd", "mesh.stl", "origins.csv"})
      if (::mkfifo((fifo_dir / name).c_str(), 0600) != 0 && errno != EEXIST)
        throw std::runtime_error("cannot make the FIFO " + (fifo_dir / name).string());
    return fifo_dir;
  }();
  return dir;
}

// ---- The table --------------------------------------------------------------------------------

// Where {out} points, and what is there before the run.
enum class Out {
  Absent,         // {dir}/NAME, nothing there
  ExistingFile,   // {dir}/NAME is a file ("keep")
  ExistingDir,    // {dir}/NAME is an empty directory
  ReadOnlyDir,    // {dir}/ro/NAME, ro has mode 0555 (read-only even for root: see io::OutputSet)
  MissingParent,  // {dir}/missing/deeper/NAME
  UnderFile,      // {dir}/afile/NAME, afile a file
};

struct Case {
  std::string name;
  std::string args;  // after `ceilplan`: {src} the source tree, {fx} the fixtures, {dir} the case's directory, {out}
  int exit_code;
  std::string says;  // in stderr on failure, in stdout on success
  Out out = Out::Absent;
  std::vector<std::pair<std::string, std::string>> files = {};  // written into {dir} first; may use {fx}
  std::string out_name = "out";
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// `text` with `from` replaced by `to`; `from` must be there (a row never tests the base unchanged).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("row edits '" + from + "', which is not in its base text");
  return text.replace(at, from.size(), to);
}

// The base files of the rows, with {fx} for the fixtures directory.
const std::string kMission =
    "map: {fx}/room.bt\nvehicle: {fx}/vehicle.yaml\n"
    "battery: {capacity_ah: 5.2, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 10.4}\n"
    "home: [-2.0, 0.0, 1.0]\norigin: {lat: 52.2, lon: 0.09, alt: 12.0}\n"
    "speeds: {cruise_m_s: 2.0, inspection_m_s: 0.5, climb_m_s: 1.0, descent_m_s: 0.8}\nseed: 1\ntargets:\n"
    "  - {name: ceiling_east, point: [1.5, 0.0, 4.0], dwell_s: 10, standoff_m: [0.3, 1.5]}\n";

std::string vehicleText() { return readWholeFile(fs::path(CEILPLAN_SOURCE_DIR) / "maps/vehicles/quad.yaml"); }

// Commands as the rows run them, on the fixtures.
const std::string kPlan = "plan --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --planner lattice";
const std::string kCompare = "compare --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --planner lattice";
const std::string kEvaluate = "evaluate --map {fx}/room.bt --path {fx}/path.csv";
const std::string kBench =
    "bench-planners --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --planners RRTstar --runs 1 --time-limit-s 0.2";
const std::string kProbe = "probe --map {fx}/room.bt --at 0,0,1";
const std::string kMapinfo = "mapinfo --map {fx}/room.bt";
const std::string kTour = "tour --mission {dir}/mission.yaml --out {out}";
const std::string kRainflow = "rainflow --csv {fx}/soc.csv --column soc";
const std::string kCalibrate = "calibrate --data {src}/maps/calibration/published-ceiling-hover.csv";

std::vector<Case> mapCases() {
  std::vector<Case> rows;
  struct Bad {
    std::string name, file, says, cli_says;  // cli_says: what CLI11's ExistingFile check says, if it differs
  };
  const std::vector<Bad> bad = {
      {"missing", "{fx}/missing.bt", "no such map file", "File does not exist"},
      {"empty", "{fx}/empty.bt", "not an OctoMap file (it is empty)", ""},
      {"truncated", "{fx}/truncated.bt", "truncated OctoMap file", ""},
      {"random_bytes", "{fx}/random.bt", "not an OctoMap file", ""},
      {"directory", "{fx}/adir", "is a directory, not a map file", "File is actually a directory"},
      {"wrong_kind", "{fx}/vehicle.yaml", "not an OctoMap file", ""},
      {"trailing_bytes", "{fx}/trailing.bt", "2 bytes follow the end of the tree", ""},
      {"two_trees", "{fx}/two_trees.bt", "holds a second OctoMap tree after the first", ""},
      {"device", "/dev/zero", "/dev/zero: is a device, not a map file; give a regular file", ""},
      {"fifo", "{fifo}/map.bt", "map.bt: is a FIFO (named pipe), not a map file; give a regular file", ""},
  };
  for (const Bad& b : bad) {
    const std::string cli = b.cli_says.empty() ? b.says : b.cli_says;
    const auto map = [&](const std::string& command) { return replaced(command, "{fx}/room.bt", b.file); };
    rows.push_back({"map_" + b.name + "_mapinfo", map(kMapinfo) + " --json {out}", 2, b.says});
    rows.push_back({"map_" + b.name + "_probe", map(kProbe) + " --json {out}", 2, b.says});
    rows.push_back({"map_" + b.name + "_plan", map(kPlan) + " --out {out}", 2, cli});
    rows.push_back({"map_" + b.name + "_evaluate", map(kEvaluate) + " --json {out}", 2, cli});
    rows.push_back({"map_" + b.name + "_compare", map(kCompare) + " --out {out}", 2, cli});
    rows.push_back({"map_" + b.name + "_bench_planners", map(kBench) + " --json {out}", 2, cli});
    const std::string tour_says = b.name == "missing"     ? "which does not exist"
                                  : b.name == "directory" ? "which is a directory, not a file"
                                  : b.name == "device"    ? "'map' names /dev/zero: is a device, not a file"
                                  : b.name == "fifo"      ? "map.bt: is a FIFO (named pipe), not a file"
                                                          : b.says;
    rows.push_back({"map_" + b.name + "_tour",
                    kTour,
                    2,
                    tour_says,
                    Out::Absent,
                    {{"mission.yaml", replaced(kMission, "{fx}/room.bt", b.file)}}});
  }
  // A ColorOcTree carries occupancy like an OcTree: it loads.
  rows.push_back({"map_color_octree_mapinfo", "mapinfo --map {fx}/color.ot --json {out}", 0, "resolution_m: 0.1"});
  rows.push_back({"map_color_octree_plan", replaced(kPlan, "room.bt", "color.ot") + " --out {out}", 0, "waypoints"});
  return rows;
}

std::vector<Case> flagCases() {
  return {
      // help and version
      {"help_lists_the_commands", "help", 0, "bench-planners"},
      {"help_describes_a_command", "help tour", 0, "--mission"},
      {"help_unknown_command", "help fly", 2, "no command 'fly'"},
      {"version", "version", 0, "ceilplan"},
      {"version_flag", "--version", 0, "ceilplan"},
      {"no_command", "", 2, "subcommand"},
      {"unknown_command", "fly --map x", 2, "no command 'fly'"},
      {"misspelt_command", "tuor --mission x", 2, "no command 'tuor'; did you mean 'tour'?"},
      {"unknown_flag", kPlan + " --out {out} --planer lattice", 2, "--planer"},
      // plan: numbers
      {"plan_time_limit_nan", "plan --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --time-limit-s nan --out {out}", 2,
       "--time-limit-s: must be a finite number > 0, got nan"},
      {"plan_time_limit_inf", "plan --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --time-limit-s inf --out {out}", 2,
       "got inf"},
      {"plan_time_limit_negative", "plan --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --time-limit-s -1 --out {out}",
       2, "--time-limit-s"},
      {"plan_time_limit_text", "plan --map {fx}/room.bt --start -2,0,1 --goal 2,0,1 --time-limit-s soon --out {out}", 2,
       "'soon' is not a number"},
      {"plan_band_fraction_nan", kPlan + " --band-fraction nan --out {out}", 2,
       "--band-fraction: must be a finite number in [0, 1], got nan"},
      {"plan_band_fraction_range", kPlan + " --band-fraction 5 --out {out}", 2,
       "must be a finite number in [0, 1], got 5"},
      {"plan_lattice_spacing_nan", kPlan + " --lattice-spacing-m nan --out {out}", 2,
       "--lattice-spacing-m: must be a finite number in [0.01, 2]"},
      {"plan_temperature_huge", kPlan + " --temperature-c 1e300 --out {out}", 2,
       "--temperature-c: must be a finite number in [-40, 80]"},
      {"plan_climb_beyond_a_multirotor", kPlan + " --climb-m-s 100 --out {out}", 2, "climb_m_s 100"},
      {"plan_descent_huge", kPlan + " --descent-m-s 1e300 --out {out}", 2, "descent_m_s 1e+300"},
      {"plan_cruise_beyond_the_vehicle", kPlan + " --cruise-speed-m-s 1e9 --out {out}", 2, "max_speed_m_s (15 m/s)"},
      {"plan_near_ceiling_radii_huge", kPlan + " --near-ceiling-radii 1e300 --out {out}", 2, "near_ceiling_gap_radii"},
      {"plan_min_gap_negative", kPlan + " --min-ceiling-gap-m -1 --out {out}", 2, "--min-ceiling-gap-m"},
      {"plan_seed_zero", kPlan + " --seed 0 --out {out}", 2, "--seed"},
      {"plan_seed_negative", kPlan + " --seed -1 --out {out}", 2, "--seed"},
      {"plan_seed_fraction", kPlan + " --seed 1.5 --out {out}", 2, "--seed"},
      {"plan_start_nan", "plan --map {fx}/room.bt --start nan,0,1 --goal 2,0,1 --out {out}", 2,
       "--start 'nan,0,1': expected three finite numbers"},
      {"plan_start_huge", "plan --map {fx}/room.bt --start 1e300,0,1 --goal 2,0,1 --out {out}", 2,
       "each within +-1e6 m"},
      {"plan_start_two_numbers", "plan --map {fx}/room.bt --start 1,2 --goal 2,0,1 --out {out}", 2,
       "expected three finite numbers"},
      {"plan_start_in_the_floor", "plan --map {fx}/room.bt --start -2,0,0.1 --goal 2,0,1 --planner lattice --out {out}",
       2, "start"},
      {"plan_fill_huge", kPlan + " --unknown fill --unknown-fill-max-m 1e300 --out {out}", 2, "fill size"},
      {"plan_fill_without_policy", kPlan + " --unknown-fill-max-m 1 --out {out}", 2, "applies only to --unknown fill"},
      {"plan_objective_unknown", kPlan + " --objective cheap --out {out}", 2, "--objective"},
      // other commands' numbers
      {"evaluate_temperature_nan", kEvaluate + " --temperature-c nan --json {out}", 2, "--temperature-c"},
      {"compare_flight_min_nan", kCompare + " --flight-min nan --out {out}", 2, "--flight-min"},
      {"compare_flight_min_huge", kCompare + " --flight-min 1e308 --out {out}", 2,
       "--flight-min: must be at most 1440, got 1e308"},
      {"compare_idle_min_huge", kCompare + " --idle-min 1e308 --out {out}", 2, "--idle-min: must be at most 1440"},
      {"compare_charge_min_huge", kCompare + " --charge-max-min 1e308 --out {out}", 2,
       "--charge-max-min: must be at most 1440"},
      {"compare_flight_min_repeats_a_short_route",
       "compare --map {fx}/room.bt --start -2,0,1 --goal -1.5,0,1 "
       "--planner lattice --flight-min 1440 --out {out}",
       2, "times, more than 10000; give a shorter flight time"},
      {"plan_time_limit_huge", kPlan + " --time-limit-s 1e308 --out {out}", 2, "--time-limit-s: must be at most 86400"},
      {"bench_time_limit_huge", replaced(kBench, "--time-limit-s 0.2", "--time-limit-s 1e308") + " --json {out}", 2,
       "--time-limit-s: must be at most 86400, got 1e308"},
      {"tour_time_limit_huge",
       kTour + " --time-limit-s 1e308",
       2,
       "--time-limit-s: must be at most 86400",
       Out::Absent,
       {{"mission.yaml", kMission}}},
      {"plan_cruise_tiny", kPlan + " --cruise-speed-m-s 1e-300 --out {out}", 2,
       "--cruise-speed-m-s: must be a finite number >= 0.01"},
      {"plan_climb_tiny", kPlan + " --climb-m-s 1e-300 --out {out}", 2, "--climb-m-s: must be a finite number >= 0.01"},
      {"compare_days_zero", kCompare + " --days 0 --out {out}", 2, "--days"},
      {"compare_missions_negative", kCompare + " --missions-per-day -1 --out {out}", 2, "--missions-per-day"},
      {"tour_seed_negative", kTour + " --seed -1", 2, "--seed", Out::Absent, {{"mission.yaml", kMission}}},
      {"tour_lattice_spacing_nan",
       kTour + " --lattice-spacing-m nan",
       2,
       "--lattice-spacing-m: must be a finite number",
       Out::Absent,
       {{"mission.yaml", kMission}}},
      {"tour_workers_zero", kTour + " --workers 0", 2, "--workers", Out::Absent, {{"mission.yaml", kMission}}},
      {"tour_idle_nan", kTour + " --idle-min nan", 2, "--idle-min", Out::Absent, {{"mission.yaml", kMission}}},
      {"tour_idle_huge",
       kTour + " --idle-min 1e308",
       2,
       "--idle-min: must be at most 1440",
       Out::Absent,
       {{"mission.yaml", kMission}}},
      {"tour_charge_huge",
       kTour + " --charge-max-min 1e308",
       2,
       "--charge-max-min: must be at most 1440",
       Out::Absent,
       {{"mission.yaml", kMission}}},
      {"tour_free_standoff_huge",
       kTour + " --free-standoff-max-m 1e308",
       2,
       "--free-standoff-max-m: must be at most 50",
       Out::Absent,
       {{"mission.yaml", kMission}}},
      {"tour_standoff_negative",
       kTour + " --standoff-m -1",
       2,
       "--standoff-m",
       Out::Absent,
       {{"mission.yaml", kMission}}},
      {"tour_days_huge", kTour + " --days 1e9", 2, "--days", Out::Absent, {{"mission.yaml", kMission}}},
      {"current_gap_nan", "current --gap-m nan --json {out}", 2, "ceiling gap nan"},
      {"current_gap_negative", "current --gap-m -1 --json {out}", 2, "negative"},
      {"current_gap_text", "current --gap-m close --json {out}", 2, "close"},
      {"current_coverage_range", "current --coverage 2 --json {out}", 2, "coverage 2 is outside [0, 1]"},
      {"current_soc_nan", "current --soc nan --json {out}", 2, "state of charge nan"},
      {"current_speed_huge", "current --speed-m-s 1e9 --json {out}", 2, "beyond the vehicle's max_speed_m_s (15 m/s)"},
      {"current_climb_huge", "current --climb-m-s 1e30 --json {out}", 2,
       "--climb-m-s: must be a finite number in [-10, 10], got 1e30"},
      {"current_descent_huge", "current --climb-m-s -1e9 --json {out}", 2,
       "--climb-m-s: must be a finite number in [-10, 10]"},
      {"mapgen_resolution_nan",
       "mapgen --scene open --resolution nan --out {out}",
       2,
       "resolution",
       Out::Absent,
       {},
       "out.bt"},
      {"mapgen_resolution_tiny",
       "mapgen --scene open --resolution 1e-9 --out {out}",
       2,
       "resolution",
       Out::Absent,
       {},
       "out.bt"},
      {"mapgen_seed_negative",
       "mapgen --scene open --resolution 0.5 --seed -1 --out {out}",
       2,
       "--seed: must be a whole number >= 0, got '-1'",
       Out::Absent,
       {},
       "out.bt"},
      {"mapgen_seed_2_to_the_64",
       "mapgen --scene open --resolution 0.5 --seed 18446744073709551616 --out {out}",
       2,
       "--seed: must be a whole number in [0, 18446744073709551615], got 18446744073709551616",
       Out::Absent,
       {},
       "out.bt"},
      {"mapgen_scene_unknown",
       "mapgen --scene bridg --out {out}",
       2,
       "unknown scene 'bridg'",
       Out::Absent,
       {},
       "out.bt"},
      {"mapgen_bridge_length_inf",
       "mapgen --scene bridge --bridge-length-m inf --out {out}",
       2,
       "bridge length",
       Out::Absent,
       {},
       "out.bt"},
      {"duty_current_nan", "duty --flight-current-a nan --json {out}", 2, "--flight-current-a"},
      {"duty_current_huge", "duty --flight-current-a 1e300 --json {out}", 2, "--flight-current-a"},
      {"duty_step_tiny", "duty --dt-s 1e-9 --json {out}", 2, "--dt-s"},
      {"duty_days_negative", "duty --days -1 --json {out}", 2, "--days"},
      {"duty_soc_range", "duty --soc-start 1.5 --json {out}", 2, "--soc-start"},
      // A capacity so small that SOC figures would be meaningless (-6e297 %) is refused up front.
      {"duty_capacity_tiny", "duty --capacity-ah 1e-300 --json {out}", 2,
       "--capacity-ah: must be a finite number in [0.01, 1000], got 1e-300"},
      {"mapinfo_fill_nan", kMapinfo + " --unknown fill --unknown-fill-max-m nan --json {out}", 2,
       "--unknown-fill-max-m"},
      {"mapinfo_slice_outside", kMapinfo + " --slice-z 100 --slice-csv {out}", 2, "--slice-z 100 lies outside the map"},
      {"probe_at_nan", "probe --map {fx}/room.bt --at nan,0,1 --json {out}", 2, "--at 'nan,0,1'"},
      {"probe_at_huge", "probe --map {fx}/room.bt --at 1e300,0,1 --json {out}", 2, "each within +-1e6 m"},
      {"bench_runs_zero", replaced(kBench, "--runs 1", "--runs 0") + " --json {out}", 2, "--runs"},
      {"bench_planner_unknown", replaced(kBench, "RRTstar", "RRTstr") + " --json {out}", 2, "RRTstr"},
      {"import_resolution_nan",
       "import --points {fx}/points.xyz --resolution nan --out {out}",
       2,
       "--resolution nan",
       Out::Absent,
       {},
       "out.bt"},
      {"import_max_range_negative",
       "import --points {fx}/points.xyz --resolution 0.1 --max-range -1 --out {out}",
       2,
       "--max-range",
       Out::Absent,
       {},
       "out.bt"},
      {"calibrate_fit_unknown", kCalibrate + " --fit k3 --out {out}", 2, "k3"},
  };
}

std::vector<Case> yamlCases() {
  const auto mission = [](const std::string& from, const std::string& to) {
    return std::vector<std::pair<std::string, std::string>>{{"mission.yaml", replaced(kMission, from, to)}};
  };
  const auto vehicle = [](const std::string& from, const std::string& to) {
    return std::vector<std::pair<std::string, std::string>>{{"v.yaml", replaced(vehicleText(), from, to)}};
  };
  // The mission's battery asking for a landing confidence of `value`.
  const auto confidence = [&](const std::string& value) {
    return mission("capacity_ah: 5.2", "capacity_ah: 5.2, reserve_confidence: " + value);
  };
  const std::string with_vehicle = kPlan + " --vehicle {dir}/v.yaml --out {out}";
  const std::string with_battery = kPlan + " --battery {dir}/b.yaml --out {out}";
  const auto battery = [](const std::string& text) {
    return std::vector<std::pair<std::string, std::string>>{{"b.yaml", text}};
  };
  const auto config = [](const std::string& text) {
    return std::vector<std::pair<std::string, std::string>>{{"c.yaml", text}};
  };
  const std::string base_config = "map: {fx}/room.bt\nstart: -2,0,1\ngoal: 2,0,1\nplanner: lattice\n";
  return {
      // mission files
      {"mission_capacity_nan", kTour, 2, "'battery.capacity_ah' must be a finite number in [0.01, 1000] Ah, got nan",
       Out::Absent, mission("capacity_ah: 5.2", "capacity_ah: .nan")},
      {"mission_capacity_inf", kTour, 2, "got inf", Out::Absent, mission("capacity_ah: 5.2", "capacity_ah: .inf")},
      {"mission_capacity_negative", kTour, 2, "got -5", Out::Absent, mission("capacity_ah: 5.2", "capacity_ah: -5")},
      {"mission_capacity_huge", kTour, 2, "got 1e+300", Out::Absent, mission("capacity_ah: 5.2", "capacity_ah: 1e300")},
      {"mission_capacity_tiny", kTour, 2, "'battery.capacity_ah' must be in [0.01, 1000] Ah, got 1e-300", Out::Absent,
       mission("capacity_ah: 5.2", "capacity_ah: 1e-300")},
      {"mission_capacity_text", kTour, 2, "got 'lots'", Out::Absent, mission("capacity_ah: 5.2", "capacity_ah: lots")},
      {"mission_reserve_confidence_one", kTour, 2, "'battery.reserve_confidence' must be in (0, 1), got 1", Out::Absent,
       confidence("1")},
      {"mission_reserve_confidence_zero", kTour, 2, "'battery.reserve_confidence' must be in (0, 1), got 0",
       Out::Absent, confidence("0")},
      {"mission_reserve_confidence_percent", kTour, 2, "'battery.reserve_confidence' must be in (0, 1), got 99",
       Out::Absent, confidence("99")},
      {"mission_reserve_confidence_text", kTour, 2, "got 'high'", Out::Absent, confidence("high")},
      {"mission_reserve_confidence_uncalibrated", kTour, 2,
       "vehicle.yaml has no 'calibration:' block: fit it with ceilplan calibrate", Out::Absent, confidence("0.99")},
      // Gusts alone do not make a confidence (docs/models.md, "Landing confidence").
      {"mission_reserve_confidence_uncalibrated_in_gusts",
       kTour,
       2,
       "vehicle.yaml has no 'calibration:' block: fit it with ceilplan calibrate",
       Out::Absent,
       {{"mission.yaml", replaced(replaced(kMission, "capacity_ah: 5.2", "capacity_ah: 5.2, reserve_confidence: 0.99"),
                                  "seed: 1", "seed: 1\nwind: {speed_m_s: 5, from_deg: 90, gust_m_s: 3}")}}},
      {"mission_reserve_confidence_misspelt", kTour, 2, "did you mean 'reserve_confidence'?", Out::Absent,
       mission("capacity_ah: 5.2", "capacity_ah: 5.2, reserve_confidense: 0.99")},
      {"mission_capacity_list", kTour, 2, "got a list", Out::Absent,
       mission("capacity_ah: 5.2", "capacity_ah: [1, 2]")},
      {"mission_key_misspelt", kTour, 2, "unknown key 'battery.capacity_a'; did you mean 'capacity_ah'?", Out::Absent,
       mission("capacity_ah: 5.2", "capacity_a: 5.2")},
      {"mission_key_unknown", kTour, 2, "unknown key 'sede'; did you mean 'seed'?", Out::Absent,
       mission("seed: 1", "sede: 1")},
      {"mission_key_twice", kTour, 2, "key 'seed' is given twice", Out::Absent, mission("seed: 1", "seed: 1\nseed: 2")},
      {"mission_battery_cells_not_the_vehicles", kTour, 2, "mission.yaml: 'battery.cell_count' is 6 cells, but ",
       Out::Absent, mission("capacity_ah: 5.2,", "capacity_ah: 5.2, cell_count: 6,")},
      {"mission_map_missing", kTour, 2, "missing key 'map'", Out::Absent, mission("map: {fx}/room.bt\n", "")},
      {"mission_targets_missing", kTour, 2, "missing key 'targets'", Out::Absent,
       mission("targets:\n  - {name: ceiling_east, point: [1.5, 0.0, 4.0], dwell_s: 10, standoff_m: [0.3, 1.5]}\n",
               "")},
      {"mission_dwell_nan", kTour, 2, "'targets[0].dwell_s' must be a finite number", Out::Absent,
       mission("dwell_s: 10", "dwell_s: .nan")},
      {"mission_point_text", kTour, 2, "'targets[0].point[1]' must be a number", Out::Absent,
       mission("point: [1.5, 0.0, 4.0]", "point: [1.5, zero, 4.0]")},
      {"mission_point_two_numbers", kTour, 2, "'targets[0].point' must be [x, y, z]", Out::Absent,
       mission("point: [1.5, 0.0, 4.0]", "point: [1.5, 4.0]")},
      {"mission_seed_negative", kTour, 2, "'seed' must be a whole number", Out::Absent, mission("seed: 1", "seed: -1")},
      {"mission_seed_fraction", kTour, 2, "'seed' must be a whole number", Out::Absent,
       mission("seed: 1", "seed: 1.5")},
      {"mission_cruise_beyond_the_vehicle", kTour, 2, "'speeds.cruise_m_s' must be in [0.01, 15]", Out::Absent,
       mission("cruise_m_s: 2.0", "cruise_m_s: 100")},
      {"mission_climb_beyond_a_multirotor", kTour, 2, "'speeds.climb_m_s' must be in [0.01, 10]", Out::Absent,
       mission("climb_m_s: 1.0", "climb_m_s: 100")},
      {"mission_inspection_speed_tiny", kTour, 2, "'speeds.inspection_m_s' must be in [0.01, 15] m/s", Out::Absent,
       mission("inspection_m_s: 0.5", "inspection_m_s: 1e-300")},
      {"mission_wind_speed_nan", kTour, 2, "'wind.speed_m_s' must be a finite number", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: .nan, from_deg: 90}")},
      {"mission_wind_speed_negative", kTour, 2, "'wind.speed_m_s' must be in [0, 40] m/s, got -3", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: -3, from_deg: 90}")},
      {"mission_wind_from_360", kTour, 2, "'wind.from_deg' must be in [0, 360) deg", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 5, from_deg: 360}")},
      {"mission_wind_from_negative", kTour, 2, "'wind.from_deg' must be in [0, 360) deg", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 5, from_deg: -90}")},
      {"mission_wind_key_misspelt", kTour, 2, "unknown key 'wind.gusts_m_s'; did you mean 'gust_m_s'?", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 5, from_deg: 90, gusts_m_s: 2}")},
      {"mission_wind_direction_missing", kTour, 2, "missing key 'wind.from_deg'", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 5}")},
      {"mission_wind_gust_text", kTour, 2, "'wind.gust_m_s' must be a number", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 5, from_deg: 90, gust_m_s: strong}")},
      {"mission_wind_sheltered_above_one", kTour, 2, "'wind.sheltered_fraction' must be in [0, 1]", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 5, from_deg: 90, sheltered_fraction: 1.5}")},
      {"mission_wind_beyond_the_airspeed_limit", kTour, 2,
       "wind: speed_m_s 14 plus the fastest speed 2 m/s exceeds the vehicle's max_speed_m_s (15 m/s)", Out::Absent,
       mission("seed: 1", "seed: 1\nwind: {speed_m_s: 14, from_deg: 90}")},
      {"mission_second_document", kTour, 2,
       "mission.yaml: holds 2 YAML documents (split by '---'); a mission file is one document", Out::Absent,
       mission("seed: 1\n", "seed: 1\n---\nseed: 2\n")},
      {"mission_key_twice_in_a_section", kTour, 2, "key 'speeds.cruise_m_s' is given twice", Out::Absent,
       mission("cruise_m_s: 2.0", "cruise_m_s: 2.0, cruise_m_s: 3.0")},
      {"mission_map_is_a_fifo", kTour, 2, "'map' names {fifo}/map.bt: is a FIFO (named pipe), not a file", Out::Absent,
       mission("map: {fx}/room.bt", "map: {fifo}/map.bt")},
      {"mission_vehicle_is_a_fifo", kTour, 2, "'vehicle' names {fifo}/vehicle.yaml: is a FIFO", Out::Absent,
       mission("vehicle: {fx}/vehicle.yaml", "vehicle: {fifo}/vehicle.yaml")},
      {"mission_is_a_fifo", "tour --mission {fifo}/mission.yaml --out {out}", 2,
       "mission.yaml: is a FIFO (named pipe), not a mission file; give a regular file"},
      {"mission_is_a_device", "tour --mission /dev/zero --out {out}", 2, "/dev/zero: is a device, not a mission file"},
      {"mission_mode_misspelt", kTour, 2, "did you mean 'ceiling'?", Out::Absent,
       mission("seed: 1", "seed: 1\nmode: ceilling")},
      {"mission_tab", kTour, 2, "malformed YAML at line", Out::Absent, mission("seed: 1", "\tseed: 1")},
      {"mission_vehicle_is_a_map", kTour, 2, "holds binary data, not YAML text; is it a vehicle file?", Out::Absent,
       mission("vehicle: {fx}/vehicle.yaml", "vehicle: {fx}/room.bt")},
      {"mission_vehicle_is_a_directory", kTour, 2, "which is a directory, not a file", Out::Absent,
       mission("vehicle: {fx}/vehicle.yaml", "vehicle: {fx}/adir")},
      {"mission_escape_in_a_key", kTour, 2, "unknown key 'se\\x1B[2Jed'", Out::Absent,
       mission("seed: 1", "se\x1b[2Jed: 1")},
      {"mission_is_a_vehicle_file", "tour --mission {fx}/vehicle.yaml --out {out}", 2,
       "this is a vehicle file, not a mission file"},
      {"mission_empty", "tour --mission {fx}/empty.bt --out {out}", 2, "must be a YAML map of keys"},
      {"mission_is_a_directory", "tour --mission {fx}/adir --out {out}", 2, "File is actually a directory"},
      {"mission_target_in_free_air", kTour, 2,
       "target 'ceiling_east' at (0.00, 0.00, 2.10) lies in free air: no structure within its standoff range of 1.5 m",
       Out::Absent, mission("point: [1.5, 0.0, 4.0]", "point: [0.0, 0.0, 2.1]")},
      {"mission_target_outside_the_map", kTour, 2, "lies outside the map", Out::Absent,
       mission("point: [1.5, 0.0, 4.0]", "point: [100.0, 0.0, 4.0]")},
      {"mission_home_in_the_floor", kTour, 2, "home (-2.00, 0.00, 0.10) is not a valid position", Out::Absent,
       mission("home: [-2.0, 0.0, 1.0]", "home: [-2.0, 0.0, 0.1]")},
      {"mission_battery_runs_out", kTour + " --no-export", 3,
       "no single sortie can reach, inspect and return from 'ceiling_east' above the 25 % reserve (home -> "
       "'ceiling_east' -> home lands at",
       Out::Absent, mission("capacity_ah: 5.2", "capacity_ah: 0.02")},
      // vehicle files
      {"vehicle_collision_radius_huge", with_vehicle, 2, "'airframe.collision_radius_m' must be in (0, 3] m, got 36",
       Out::Absent, vehicle("collision_radius_m: 0.36", "collision_radius_m: 36")},
      {"vehicle_mass_nan", with_vehicle, 2, "'mass_kg' must be a finite number", Out::Absent,
       vehicle("mass_kg: 1.4", "mass_kg: .nan")},
      {"vehicle_rotor_count_text", with_vehicle, 2, "'rotors.count' must be a whole number in [1, 16], got 'four'",
       Out::Absent, vehicle("count: 4", "count: four")},
      {"vehicle_key_misspelt", with_vehicle, 2, "unknown key 'mas_kg'; did you mean 'mass_kg'?", Out::Absent,
       vehicle("mass_kg: 1.4", "mas_kg: 1.4")},
      {"vehicle_mass_missing", with_vehicle, 2, "missing key 'mass_kg'", Out::Absent, vehicle("mass_kg: 1.4\n", "")},
      {"vehicle_hover_current_too_low", with_vehicle, 2, "hover current 0.4 A leaves no propulsion power", Out::Absent,
       vehicle("hover_current_a: 9.5", "hover_current_a: 0.4")},
      {"vehicle_is_a_battery_file", kPlan + " --vehicle {fx}/battery.yaml --out {out}", 2,
       "this is a battery file, not a vehicle file"},
      {"vehicle_is_a_directory", kPlan + " --vehicle {fx}/adir --out {out}", 2, "is a directory, not a vehicle file"},
      {"vehicle_missing", kPlan + " --vehicle {fx}/none.yaml --out {out}", 2, "no such vehicle file"},
      {"vehicle_empty", kPlan + " --vehicle {fx}/empty.bt --out {out}", 2, "must be a YAML map of keys"},
      {"vehicle_key_twice", with_vehicle, 2, "v.yaml: key 'mass_kg' is given twice", Out::Absent,
       vehicle("mass_kg: 1.4", "mass_kg: 1.4\nmass_kg: 2.0")},
      {"vehicle_second_document", with_vehicle, 2,
       "v.yaml: holds 2 YAML documents (split by '---'); a vehicle file is one document", Out::Absent,
       vehicle("mass_kg: 1.4", "mass_kg: 1.4\n---\nmass_kg: 2.0")},
      {"vehicle_calibration_without_covariance_rows", with_vehicle, 2,
       "give 'calibration.parameters' and 'calibration.covariance' together", Out::Absent,
       vehicle("mass_kg: 1.4",
               "mass_kg: 1.4\ncalibration: {samples: 50, residual_rms_a: 0.1, residual_std_a: 0.1, parameters: [k1]}")},
      {"vehicle_calibration_negative_variance", with_vehicle, 2,
       "'calibration.covariance' must be positive semidefinite", Out::Absent,
       vehicle("mass_kg: 1.4",
               "mass_kg: 1.4\ncalibration: {samples: 50, residual_rms_a: 0.1, residual_std_a: 0.1, "
               "parameters: [k1], covariance: [[-1]]}")},
      {"vehicle_calibration_unknown_parameter", with_vehicle, 2, "unknown calibration parameter 'k3'", Out::Absent,
       vehicle("mass_kg: 1.4",
               "mass_kg: 1.4\ncalibration: {samples: 50, residual_rms_a: 0.1, residual_std_a: 0.1, "
               "parameters: [k3], covariance: [[1]]}")},
      {"vehicle_is_a_fifo", kPlan + " --vehicle {fifo}/vehicle.yaml --out {out}", 2,
       "vehicle.yaml: is a FIFO (named pipe), not a vehicle file"},
      // battery files
      {"battery_key_misspelt", with_battery, 2, "unknown key 'capacity_a'; did you mean 'capacity_ah'?", Out::Absent,
       battery("capacity_a: 5.2\n")},
      {"battery_capacity_nan", with_battery, 2, "'capacity_ah' must be a finite number", Out::Absent,
       battery("capacity_ah: .nan\n")},
      {"battery_capacity_tiny", with_battery, 2, "'capacity_ah' must be in [0.01, 1000] Ah, got 1e-300", Out::Absent,
       battery("capacity_ah: 1e-300\n")},
      {"battery_is_a_vehicle_file", kPlan + " --battery {fx}/vehicle.yaml --out {out}", 2,
       "this is a vehicle file, not a battery file"},
      {"battery_list", with_battery, 2, "must be a YAML map of keys", Out::Absent, battery("- 1\n- 2\n")},
      {"battery_key_twice", with_battery, 2, "b.yaml: key 'capacity_ah' is given twice", Out::Absent,
       battery("capacity_ah: 5.2\ncapacity_ah: 6.0\n")},
      {"battery_second_document", with_battery, 2,
       "b.yaml: holds 2 YAML documents (split by '---'); a battery file is one document", Out::Absent,
       battery("capacity_ah: 5.2\n---\ncapacity_ah: 6.0\n")},
      {"battery_is_a_fifo", kPlan + " --battery {fifo}/battery.yaml --out {out}", 2,
       "battery.yaml: is a FIFO (named pipe), not a battery file"},
      {"battery_reserve_above_start", with_battery, 2, "is not below", Out::Absent,
       battery("start_soc: 0.3\nreserve_soc: 0.5\n")},
      {"battery_cells_not_the_vehicles", with_battery, 2,
       "b.yaml: 'cell_count' is 6 cells, but the vehicle 'quad-10in' has a 4-cell pack", Out::Absent,
       battery("cell_count: 6\n")},
      {"battery_cells_not_the_vehicle_files", kPlan + " --vehicle {fx}/vehicle.yaml --battery {dir}/b.yaml --out {out}",
       2, "b.yaml: 'cell_count' is 3 cells, but ", Out::Absent, battery("cell_count: 3\n")},
      // --config files
      {"config_key_misspelt", "plan --config {dir}/c.yaml --out {out}", 2,
       "config file line 5: unknown key 'planer' for 'plan'; did you mean 'planner'?", Out::Absent,
       config(base_config + "planer: roadmap\n")},
      {"config_key_unknown_map", "plan --config {dir}/c.yaml --out {out}", 2, "unknown key 'limits' for 'plan'",
       Out::Absent, config(base_config + "limits: {a: 1}\n")},
      {"config_key_unknown_duty", "duty --config {dir}/c.yaml --json {out}", 2, "unknown key 'rainflw' for 'duty'",
       Out::Absent, config("days: 2\nrainflw: 1\n")},
      {"config_value_nan", "plan --config {dir}/c.yaml --out {out}", 2,
       "--time-limit-s: must be a finite number > 0, got nan", Out::Absent,
       config(base_config + "time_limit_s: nan\n")},
      {"config_list_for_one_value", "plan --config {dir}/c.yaml --out {out}", 2, "--start", Out::Absent,
       config("map: {fx}/room.bt\nstart: [-2, 0, 1]\ngoal: 2,0,1\n")},
      {"config_missing_key", "plan --config {dir}/c.yaml --out {out}", 2, "--goal is required", Out::Absent,
       config("map: {fx}/room.bt\nstart: -2,0,1\n")},
      {"config_malformed", "plan --config {dir}/c.yaml --out {out}", 2, "malformed YAML config at line 2", Out::Absent,
       config("map: {fx}/room.bt\n  start: [\n")},
      {"config_not_a_map", "plan --config {dir}/c.yaml --out {out}", 2, "config file must be a YAML map", Out::Absent,
       config("- map\n")},
      {"config_missing_file", "plan --config {dir}/none.yaml --out {out}", 2, "none.yaml: no such config file"},
      {"config_key_twice", "plan --config {dir}/c.yaml --out {out}", 2,
       "config file line 5: 'planner' gives flag 'planner' again (first on line 4); give each flag once", Out::Absent,
       config(base_config + "planner: roadmap\n")},
      {"config_both_spellings", "plan --config {dir}/c.yaml --out {out}", 2,
       "config file line 6: 'time_limit_s' gives flag 'time-limit-s' again (first on line 5)", Out::Absent,
       config(base_config + "time-limit-s: 1\ntime_limit_s: 2\n")},
      {"config_in_the_section_and_outside", "plan --config {dir}/c.yaml --out {out}", 2,
       "config file line 6: 'planner' gives flag 'planner' again (first on line 4)", Out::Absent,
       config(base_config + "plan:\n  planner: roadmap\n")},
      {"config_second_document", "plan --config {dir}/c.yaml --out {out}", 2,
       "config file holds 2 YAML documents (split by '---')", Out::Absent,
       config(base_config + "---\nplanner: roadmap\n")},
      {"config_is_a_fifo", "plan --config {fifo}/config.yaml --out {out}", 2,
       "config.yaml: is a FIFO (named pipe), not a config file; give a regular file"},
      {"config_is_a_device", "plan --config /dev/zero --out {out}", 2, "/dev/zero: is a device, not a config file"},
      {"config_is_a_directory", "plan --config {fx}/adir --out {out}", 2, "adir: is a directory, not a config file"},
      {"config_section_of_the_command", "plan --config {dir}/c.yaml --out {out}", 0, "waypoints", Out::Absent,
       config("plan:\n  map: {fx}/room.bt\n  start: -2,0,1\n  goal: 2,0,1\n  planner: lattice\n")},
  };
}

std::vector<Case> outputCases() {
  std::vector<Case> rows;
  struct Command {
    std::string name, args;  // args end with the output flag, {out} after it
    bool directory;          // the output is a directory (an existing file there is refused)
    std::string out_name = "out";
    std::vector<std::pair<std::string, std::string>> files = {};
  };
  const std::vector<Command> commands = {
      {"plan", kPlan + " --out {out}", true},
      {"compare", kCompare + " --out {out}", true},
      {"tour", kTour, true, "out", {{"mission.yaml", kMission}}},
      {"evaluate", kEvaluate + " --json {out}", false},
      {"current", "current --gap-m 0.1 --json {out}", false},
      {"mapinfo", kMapinfo + " --json {out}", false},
      {"mapinfo_slice", kMapinfo + " --slice-z 1 --slice-csv {out}", false},
      {"mapgen", "mapgen --scene open --resolution 0.5 --out {out}", false, "out.bt"},
      {"duty_json", "duty --days 1 --json {out}", false},
      {"duty_csv_dir", "duty --days 1 --csv-dir {out}", true},
      {"rainflow", kRainflow + " --json {out}", false},
      {"calibrate", kCalibrate + " --out {out}", false},
      {"import", "import --points {fx}/points.xyz --resolution 0.1 --out {out}", false, "out.bt"},
      {"probe", kProbe + " --json {out}", false},
      {"bench_planners", kBench + " --json {out}", false},
  };
  for (const Command& c : commands) {
    if (c.directory) {
      rows.push_back({"output_" + c.name + "_is_a_file", c.args, 2, "exists and is not a directory", Out::ExistingFile,
                      c.files, c.out_name});
    } else {
      rows.push_back(
          {"output_" + c.name + "_is_a_directory", c.args, 2, "is a directory", Out::ExistingDir, c.files, c.out_name});
    }
    rows.push_back({"output_" + c.name + "_read_only", c.args, 2, "read-only", Out::ReadOnlyDir, c.files, c.out_name});
    rows.push_back({"output_" + c.name + "_under_a_file", c.args, 2, "is a file, not a directory", Out::UnderFile,
                    c.files, c.out_name});
    rows.push_back({"output_" + c.name + "_missing_parent", c.args, 0, "", Out::MissingParent, c.files, c.out_name});
  }
  // A run that fails leaves no parent directory it created.
  rows.push_back({"output_missing_parent_left_absent_plan", replaced(kPlan, "room.bt", "empty.bt") + " --out {out}", 2,
                  "it is empty", Out::MissingParent});
  rows.push_back({"output_missing_parent_left_absent_rainflow",
                  "rainflow --csv {fx}/empty.bt --column soc --json {out}", 2, "is empty", Out::MissingParent});
  rows.push_back({"output_missing_parent_left_absent_tour",
                  kTour,
                  2,
                  "lies in free air",
                  Out::MissingParent,
                  {{"mission.yaml", replaced(kMission, "point: [1.5, 0.0, 4.0]", "point: [0.0, 0.0, 2.1]")}}});
  return rows;
}

std::vector<Case> csvCases() {
  // The same fault in a CSV for rainflow and evaluate (columns x, y, z, soc, t_s) and in one for
  // calibrate (its own columns only).
  struct Bad {
    std::string name, csv, calibrate_csv;
    int exit_code;
    std::string rainflow_says, evaluate_says, calibrate_says;
  };
  const std::vector<Bad> bad = {
      {"garbage_row", "x,y,z,soc,t_s\n-2,0,1,0.9,0\n2,0,1,0.3,1,7,?\n", "gap_m,current_a\n0.1,8\n0.2,8.5,7,?\n", 2,
       "line 3: 7 fields, but the header names 5 columns", "line 3: 7 fields",
       "line 3: 4 fields, but the header names 2 columns"},
      {"nan_row", "x,y,z,soc,t_s\n-2,0,1,0.9,0\nnan,0,1,NaN,1\n", "gap_m,current_a\n0.1,8\n0.2,NaN\n", 2,
       "'NaN' is not a finite number", "'nan' is not a finite number", "'NaN' is not a finite number"},
      {"one_row", "x,y,z,soc,t_s\n-2,0,1,0.9,0\n", "gap_m,current_a\n0.1,8\n", 2, "has 1 data row",
       "a path needs at least 2 distinct points", "1 samples cannot identify"},
      {"header_only", "x,y,z,soc,t_s\n", "gap_m,current_a\n", 2, "has 0 data rows",
       "a path needs at least 2 distinct points", "holds no samples"},
      {"terminal_escape", "x,y,z,soc,t_s\n-2,0,1,0.9,0\n2,0,\x1b[31m1\x07,\x1b[31m0.3\x07,1\n",
       "gap_m,current_a\n0.1,8\n0.2,\x1b]0;x\x07\n", 2, "'\\x1B[31m0.3\\x07' is not a number",
       "'\\x1B[31m1\\x07' is not a number", "'\\x1B]0;x\\x07' is not a number"},
      {"binary",
       std::string("\x7f"
                   "ELF\x02\x01\x01\x00\x03,\x04\n\x05\x00",
                   14),
       std::string("\x7f"
                   "ELF\x02\x01\x01\x00\x03,\x04\n\x05\x00",
                   14),
       2, "the header holds control characters", "the header holds control characters",
       "the header holds control characters ('\\x7FELF"},
      {"bom_and_crlf", "\xEF\xBB\xBFx,y,z,soc,t_s\r\n-2,0,1,0.9,0\r\n0,0,1,0.3,1\r\n2,0,1,0.8,2\r\n",
       "\xEF\xBB\xBFgap_m,current_a\r\nnone,9.5\r\n0.10,8.0\r\n0.05,8.0\r\n0.01,8.2994\r\n", 0, "cycles in all",
       "valid: true", "rmse_a"},
  };
  std::vector<Case> rows;
  for (const Bad& b : bad) {
    rows.push_back({"csv_" + b.name + "_rainflow",
                    "rainflow --csv {dir}/in.csv --column soc --json {out}",
                    b.exit_code,
                    b.rainflow_says,
                    Out::Absent,
                    {{"in.csv", b.csv}}});
    rows.push_back({"csv_" + b.name + "_evaluate",
                    "evaluate --map {fx}/room.bt --path {dir}/in.csv --json {out}",
                    b.exit_code,
                    b.evaluate_says,
                    Out::Absent,
                    {{"in.csv", b.csv}}});
    rows.push_back({"csv_" + b.name + "_calibrate",
                    "calibrate --data {dir}/in.csv --fit k1 --out {out}",
                    b.exit_code,
                    b.calibrate_says,
                    Out::Absent,
                    {{"in.csv", b.calibrate_csv}}});
  }
  // Inputs that are directories or missing: never a raw stream error.
  for (const std::string flag : {"rainflow --csv", "calibrate --data"}) {
    const std::string name = flag.substr(0, flag.find(' '));
    const std::string tail = name == "rainflow" ? " --column soc --json {out}" : " --out {out}";
    rows.push_back({"csv_directory_" + name, (flag + " {fx}/adir").append(tail), 2, "directory"});
    rows.push_back({"csv_missing_" + name, (flag + " {fx}/none.csv").append(tail), 2, "none.csv"});
  }
  rows.push_back(
      {"csv_directory_evaluate", "evaluate --map {fx}/room.bt --path {fx}/adir --json {out}", 2, "directory"});
  // A FIFO or a device would block the reader or never end.
  for (const std::string& file : {std::string("{fifo}/in.csv"), std::string("/dev/zero")}) {
    const std::string kind = file == "/dev/zero" ? "device" : "fifo";
    const std::string says = file == "/dev/zero"
                                 ? "/dev/zero: is a device, not a CSV file"
                                 : "in.csv: is a FIFO (named pipe), not a CSV file; give a regular file";
    rows.push_back({"csv_" + kind + "_rainflow", "rainflow --csv " + file + " --column soc --json {out}", 2, says});
    rows.push_back({"csv_" + kind + "_calibrate", "calibrate --data " + file + " --out {out}", 2, says});
    rows.push_back(
        {"csv_" + kind + "_evaluate", "evaluate --map {fx}/room.bt --path " + file + " --json {out}", 2, says});
  }
  rows.push_back({"csv_missing_columns_evaluate", "evaluate --map {fx}/room.bt --path {fx}/soc.csv --json {out}", 2,
                  "has neither x, y, z (path.csv) nor x_m, y_m, z_m"});
  // A fit that fails says why in words: NLopt alone says "nlopt failure". A runtime failure: 1.
  rows.push_back({"csv_overflow_calibrate",
                  "calibrate --data {dir}/in.csv --out {out}",
                  1,
                  "the least-squares fit failed: NLopt's L-BFGS gave up",
                  Out::Absent,
                  {{"in.csv", "gap_m,current_a\n0.05,1e200\n0.1,8\n0.2,8.5\nnone,9.5\n"}}});
  return rows;
}

std::vector<Case> importCases() {
  const auto import = [](const std::string& flag, const std::string& file) {
    return "import " + flag + " " + file + " --resolution 0.1 --out {out}";
  };
  const std::string pcd_header = "# .PCD v0.7\nVERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
  const std::string ply_header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n";
  const std::string points = "0 0 0\n1 0 0\n0 1 0\n1 1 1\n";
  const auto in = [](const std::string& name, const std::string& text) {
    return std::vector<std::pair<std::string, std::string>>{{name, text}};
  };
  return {
      {"import_pcd_width_height_not_points", import("--points", "{dir}/in.pcd"), 2,
       "in.pcd: not a readable point cloud (the PCD header's POINTS 4 is not WIDTH x HEIGHT (2 x 1))", Out::Absent,
       in("in.pcd", pcd_header + "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n" + points),
       "out.bt"},
      {"import_pcd_fewer_rows_than_points", import("--points", "{dir}/in.pcd"), 2,
       "in.pcd: not a readable point cloud (the ascii PCD announces 5 points but holds 4 rows)", Out::Absent,
       in("in.pcd", pcd_header + "WIDTH 5\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 5\nDATA ascii\n" + points),
       "out.bt"},
      {"import_ply_more_rows_than_vertices", import("--points", "{dir}/in.ply"), 2,
       "in.ply: not a readable point cloud (data after the last element its header announces", Out::Absent,
       in("in.ply", ply_header + points + "2 2 2\n"), "out.bt"},
      {"import_ply_binary_short", import("--points", "{dir}/in.ply"), 2,
       "in.ply: not a readable point cloud (the PLY's vertex element announces 4 records of 12 bytes, more than the "
       "file's remaining 12 bytes hold)",
       Out::Absent, in("in.ply", replaced(ply_header, "ascii", "binary_little_endian") + std::string(12, '\0')),
       "out.bt"},
      {"import_xyz_bad_line", import("--points", "{dir}/in.xyz"), 2,
       "in.xyz: not a readable point cloud (line 3: '0 one 0' is not 3 numbers; fix or delete the line)", Out::Absent,
       in("in.xyz", "0 0 0\n1 0 0\n0 one 0\n1 1 1\n"), "out.bt"},
      {"import_mesh_of_zero_area_faces", import("--mesh", "{dir}/in.obj"), 2,
       "in.obj: all 2 triangles of the mesh have zero area", Out::Absent,
       in("in.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 4 4 4\n"), "out.bt"},
      {"import_points_fifo",
       import("--points", "{fifo}/points.xyz"),
       2,
       "points.xyz: is a FIFO (named pipe), not a point cloud file",
       Out::Absent,
       {},
       "out.bt"},
      {"import_pcd_fifo",
       import("--points", "{fifo}/points.pcd"),
       2,
       "points.pcd: is a FIFO (named pipe)",
       Out::Absent,
       {},
       "out.bt"},
      {"import_mesh_fifo",
       import("--mesh", "{fifo}/mesh.stl"),
       2,
       "mesh.stl: is a FIFO (named pipe), not a mesh file",
       Out::Absent,
       {},
       "out.bt"},
      {"import_origins_fifo",
       import("--points", "{fx}/points.xyz") + " --origins {fifo}/origins.csv",
       2,
       "origins.csv: is a FIFO (named pipe), not a CSV file",
       Out::Absent,
       {},
       "out.bt"},
      {"import_points_directory", import("--points", "{dir}/scan.xyz"), 2,
       "scan.xyz: is a directory, not a point cloud file", Out::Absent, in("scan.xyz/keep", "0 0 0\n"), "out.bt"},
      {"import_crop_nan",
       import("--points", "{fx}/points.xyz") + " --crop nan,0,0,1,1,1",
       2,
       "--crop 'nan,0,0,1,1,1': expected six finite numbers xmin,ymin,zmin,xmax,ymax,zmax",
       Out::Absent,
       {},
       "out.bt"},
      {"import_crop_five_numbers",
       import("--points", "{fx}/points.xyz") + " --crop 0,0,0,1,1",
       2,
       "--crop '0,0,0,1,1': expected six finite numbers",
       Out::Absent,
       {},
       "out.bt"},
      {"import_crop_min_not_below_max", import("--mesh", "{dir}/in.obj") + " --crop 0,0,2,1,1,1", 2,
       "--crop '0,0,2,1,1,1': a crop box's z minimum (2) must be below its maximum (1)", Out::Absent,
       in("in.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "out.bt"},
      {"import_crop_huge",
       import("--points", "{fx}/points.xyz") + " --crop 0,0,0,1,1,1e300",
       2,
       "each within +-1e6 m",
       Out::Absent,
       {},
       "out.bt"},
      {"import_crop_misses_the_data",
       import("--points", "{fx}/points.xyz") + " --crop 5,5,5,6,6,6",
       2,
       "no point lies in the crop box (5.00, 5.00, 5.00) to (6.00, 6.00, 6.00)",
       Out::Absent,
       {},
       "out.bt"},
      {"import_max_range_nan", import("--points", "{fx}/points.xyz") + " --origins {dir}/origins.csv --max-range nan",
       2, "--max-range nan: a finite number of metres >= 0", Out::Absent, in("origins.csv", "x,y,z\n0.5,0.5,0.5\n"),
       "out.bt"},
      {"import_max_range_negative_with_origins",
       import("--points", "{fx}/points.xyz") + " --origins {dir}/origins.csv --max-range -2", 2,
       "--max-range -2: a finite number of metres >= 0", Out::Absent, in("origins.csv", "x,y,z\n0.5,0.5,0.5\n"),
       "out.bt"},
      {"import_max_range_drops_every_return",
       import("--points", "{fx}/points.xyz") + " --origins {dir}/origins.csv --max-range 0.1", 2,
       "no return lies within 0.1 m of its origin", Out::Absent, in("origins.csv", "x,y,z\n5,5,5\n"), "out.bt"},
  };
}

std::vector<Case> successCases() {
  return {
      {"ok_plan", kPlan + " --out {out}", 0, "planner lattice (lattice spacing 0.2 m)"},
      {"ok_compare", kCompare + " --out {out}", 0, "comparing ceiling and free modes"},
      {"ok_tour", kTour, 0, "seed 1", Out::Absent, {{"mission.yaml", kMission}}},
      {"ok_evaluate", kEvaluate + " --json {out}", 0, "valid: true"},
      {"ok_current", "current --gap-m 0.1 --json {out}", 0, "current_a"},
      {"ok_mapinfo", kMapinfo + " --json {out}", 0, "resolution_m: 0.1"},
      {"ok_mapgen", "mapgen --scene open --resolution 0.5 --out {out}", 0, "scene open", Out::Absent, {}, "out.bt"},
      {"ok_duty", "duty --days 1 --json {out}", 0, "1 day"},
      {"ok_rainflow", kRainflow + " --json {out}", 0, "cycles in all"},
      {"ok_calibrate", kCalibrate + " --out {out}", 0, "rmse_a"},
      {"ok_import",
       "import --points {fx}/points.xyz --resolution 0.1 --out {out}",
       0,
       "import:",
       Out::Absent,
       {},
       "out.bt"},
      {"ok_import_crop",
       "import --points {fx}/points.xyz --resolution 0.1 --crop -1,-1,-1,0.5,2,2 --out {out}",
       0,
       "(cropped to (-1.00, -1.00, -1.00) to (0.50, 2.00, 2.00))",
       Out::Absent,
       {},
       "out.bt"},
      {"ok_probe", kProbe + " --json {out}", 0, "valid"},
      {"ok_bench_planners", kBench + " --json {out}", 0, "RRTstar"},
  };
}

std::vector<Case> allCases() {
  std::vector<Case> rows;
  for (auto part : {mapCases(), flagCases(), yamlCases(), outputCases(), csvCases(), importCases(), successCases()})
    rows.insert(rows.end(), part.begin(), part.end());
  return rows;
}

// ---- Running a row ----------------------------------------------------------------------------

// Every entry under `dir` (relative path), with a file's size and hash (short enough to print
// when two snapshots differ); directories as "<dir>".
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> entries;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = fs::relative(it->path(), dir).string();
    if (it->is_directory()) {
      entries[name] = "<dir>";
    } else {
      const std::string bytes = readWholeFile(it->path());
      entries[name] = std::to_string(bytes.size()) + " bytes, hash " + std::to_string(std::hash<std::string>{}(bytes));
    }
  }
  return entries;
}

std::vector<std::string> temporariesUnder(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (name.find(".tmp") != std::string::npos) found.push_back(entry.path().string());
  }
  return found;
}

// One line, "ceilplan: ...", with nothing a terminal would obey and nothing from the library's
// insides: no raw bytes, no C++ exception names, no errno's "Success", no std::to_string double.
void expectOneCleanLine(const std::string& err) {
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_EQ(err.rfind("ceilplan: ", 0), 0u) << err;
  EXPECT_TRUE(std::none_of(err.begin(), err.end(),
                           [](char c) { return (c >= 0 && c < 0x20 && c != '\n') || c == 0x7f || c == '\x9b'; }))
      << "raw control bytes echoed: " << err;
  for (const char* inside : {"basic_", "std::", "bad_alloc", "Success", "terminate called", "what()", "Aborted"})
    EXPECT_EQ(err.find(inside), std::string::npos) << err;
  EXPECT_FALSE(std::regex_search(err, std::regex("[0-9]\\.[0-9]{6}([^0-9]|$)"))) << "a std::to_string double: " << err;
}

class HostileInput : public ::testing::TestWithParam<Case> {};

TEST_P(HostileInput, GivesTheDocumentedExitAndLeavesNothingBehind) {
  const Case& c = GetParam();
  const fs::path dir = scratchDirectory("hostile_" + c.name);
  const fs::path& fx = fixtures();
  const std::map<std::string, std::string> paths = {
      {"{fx}", fx.string()}, {"{src}", CEILPLAN_SOURCE_DIR}, {"{dir}", dir.string()}, {"{fifo}", fifos().string()}};
  for (const auto& [name, text] : c.files) writeFile(dir / name, substituted(text, paths));

  fs::path out = dir / c.out_name;
  switch (c.out) {
    case Out::Absent:
      break;
    case Out::ExistingFile:
      writeFile(out, "keep");
      break;
    case Out::ExistingDir:
      fs::create_directories(out);
      break;
    case Out::ReadOnlyDir:
      fs::create_directories(dir / "ro");
      fs::permissions(dir / "ro", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                      fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
      out = dir / "ro" / c.out_name;
      break;
    case Out::MissingParent:
      out = dir / "missing" / "deeper" / c.out_name;
      break;
    case Out::UnderFile:
      writeFile(dir / "afile", "keep");
      out = dir / "afile" / c.out_name;
      break;
  }
  // mapgen and import name their output with its extension, as the row's out_name does.
  std::map<std::string, std::string> all = paths;
  all["{out}"] = out.string();
  const auto before = snapshot(dir);
  const auto fixtures_before = snapshot(fx);

  // A reader that opens a FIFO blocks, one that reads a device never ends: the timeout (exit 124)
  // makes either a failure, not a hang.
  const auto mentions = [&](const std::string& what) {
    return c.args.find(what) != std::string::npos || std::any_of(c.files.begin(), c.files.end(), [&](const auto& file) {
             return file.second.find(what) != std::string::npos;
           });
  };
  const bool may_block = mentions("{fifo}") || mentions("/dev/");
  const CommandResult r = runCeilplan(substituted(c.args, all), may_block ? "timeout 60" : "");
  std::error_code ignored;
  fs::permissions(dir / "ro", fs::perms::owner_all, fs::perm_options::add, ignored);  // for the next run's cleanup

  EXPECT_EQ(r.exit_code, c.exit_code) << "stderr: " << r.err << "\nstdout: " << r.out;
  const std::string says = substituted(c.says, paths);
  EXPECT_NE((c.exit_code == 0 ? r.out : r.err).find(says), std::string::npos) << "expected '" << says << "' in:\n"
                                                                              << (c.exit_code == 0 ? r.out : r.err);
  EXPECT_TRUE(temporariesUnder(dir).empty()) << temporariesUnder(dir).front();
  EXPECT_EQ(snapshot(fx), fixtures_before) << "a run wrote into the fixtures";
  if (c.exit_code != 0) {
    expectOneCleanLine(r.err);
    EXPECT_EQ(snapshot(dir), before) << "a failed run changed its directory (an output, a partial set or a parent)";
  } else {
    if (c.args.find("{out}") != std::string::npos) {
      EXPECT_TRUE(fs::exists(out)) << out << " not written";
    }
    const auto after = snapshot(dir);
    for (const auto& [name, file] : before) {
      ASSERT_EQ(after.count(name), 1u) << name << " removed";
      EXPECT_EQ(after.at(name), file) << name << " changed";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Table, HostileInput, ::testing::ValuesIn(allCases()),
                         [](const auto& info) { return info.param.name; });

// ---- Outside the table -----------------------------------------------------------------------

// A ColorOcTree is read as the occupancy it carries: the same figures as the OcTree.
TEST(HostileInputMaps, AColorOcTreeHoldsTheSameOccupancyAsTheOcTree) {
  const CommandResult plain = runCeilplan("mapinfo --map " + (fixtures() / "room.bt").string());
  const CommandResult color = runCeilplan("mapinfo --map " + (fixtures() / "color.ot").string());
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  ASSERT_EQ(color.exit_code, 0) << color.err;
  // The volumes, the unknown space and the ceiling share (the leaf counts depend on pruning).
  const auto figures = [](const std::string& out) { return out.substr(out.find("volume_m3")); };
  EXPECT_EQ(figures(color.out), figures(plain.out));
  EXPECT_NE(color.out.find("volume_m3: 18.0 occupied, 136.8 free"), std::string::npos) << color.out;
}

// A write that fails (here: past a file-size limit, EFBIG) names the file and the system's
// reason, never "Success", exits 1 and leaves nothing.
TEST(HostileInputMessages, AFailedWriteSaysWhyAndLeavesNothing) {
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"duty", "duty --days 1 --json {out}"},
      {"current", "current --sweep --json {out}"},
      {"plan", kPlan + " --out {out}"},
      {"csv_dir", "duty --days 1 --csv-dir {out}"},
  };
  for (const auto& [name, args] : runs) {
    const fs::path dir = scratchDirectory("write_failure_" + name);
    const auto before = snapshot(dir);
    const CommandResult r =
        runCeilplan(substituted(args, {{"{fx}", fixtures().string()}, {"{out}", (dir / "out").string()}}),
                    "trap '' XFSZ; ulimit -f 1;");  // 512 bytes; the signal ignored, write() fails with EFBIG
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find("cannot write " + (dir / "out").string()), std::string::npos) << name << ": " << r.err;
    EXPECT_NE(r.err.find("File too large"), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << name << ": the staging path is named: " << r.err;
    expectOneCleanLine(r.err);
    EXPECT_EQ(snapshot(dir), before) << name;
  }
}

// A seed is printed as given (1, not 0), and only for a planner that draws random numbers: the
// lattice planners have neither a seed nor a time limit.
TEST(HostileInputMessages, SeedsAndTimeLimitsAreShownOnlyWhereTheyApply) {
  const fs::path dir = scratchDirectory("planner_lines");  // no "seed" in the paths it prints
  const std::string query = "plan --map " + (fixtures() / "room.bt").string() + " --start -2,0,1 --goal 2,0,1";
  const CommandResult lattice = runCeilplan(query + " --planner lattice --out " + (dir / "lattice").string());
  ASSERT_EQ(lattice.exit_code, 0) << lattice.err;
  EXPECT_EQ(lattice.out.find("seed"), std::string::npos) << lattice.out;
  EXPECT_NE(lattice.out.find("planner lattice (lattice spacing 0.2 m)\n"), std::string::npos) << lattice.out;
  // 2 s, not less: under a sanitizer on a loaded machine RRT* needed more than 0.25 s to join the room's ends.
  const CommandResult sampled =
      runCeilplan(query + " --planner RRTstar --seed 1 --time-limit-s 2 --out " + (dir / "sampled").string());
  ASSERT_EQ(sampled.exit_code, 0) << sampled.err;
  EXPECT_NE(sampled.out.find("planner RRTstar, seed 1, 2 s\n"), std::string::npos) << sampled.out;
  EXPECT_NE(readWholeFile(dir / "sampled" / "plan.json").find("\"seed\": 1"), std::string::npos);
}

bool builtWithAddressSanitizer() {
#if defined(__SANITIZE_ADDRESS__)
  return true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return true;
#endif
#endif
  return false;
}

// Memory running out is said in words (exit 1), never as std::bad_alloc.
TEST(HostileInputMessages, RunningOutOfMemoryIsSaidInWords) {
  if (builtWithAddressSanitizer()) GTEST_SKIP() << "ASan reserves more address space than the limit allows";
  const fs::path dir = scratchDirectory("out_of_memory");
  // Two occupied voxels 14 m apart at 0.02 m: a 700^3 box (343 million voxels, under the index's
  // limit) in a file of a few hundred bytes.
  octomap::OcTree tree(0.02);
  tree.updateNode(octomap::point3d(0.01f, 0.01f, 0.01f), true);
  tree.updateNode(octomap::point3d(13.99f, 13.99f, 13.99f), true);
  ASSERT_TRUE(tree.writeBinary((dir / "sparse.bt").string()));
  const CommandResult r =
      runCeilplan("mapinfo --map " + (dir / "sparse.bt").string() + " --json " + (dir / "out.json").string(),
                  "ulimit -v 1500000;");  // 1.5 GB of address space
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("out of memory"), std::string::npos) << r.err;
  expectOneCleanLine(r.err);
  EXPECT_FALSE(fs::exists(dir / "out.json"));
}

// Output as a terminal shows it: '\r' returns to the line's start, ESC[K erases to its end.
std::vector<std::string> visibleLines(const std::string& raw) {
  std::vector<std::string> lines(1);
  std::size_t column = 0;
  for (std::size_t i = 0; i < raw.size(); ++i) {
    std::string& line = lines.back();
    if (raw[i] == '\n') {
      lines.emplace_back();
      column = 0;
    } else if (raw[i] == '\r') {
      column = 0;
    } else if (raw.compare(i, 3, "\x1b[K") == 0) {
      line.resize(column);
      i += 2;
    } else {
      if (column < line.size()) {
        line[column] = raw[i];
      } else {
        line.push_back(raw[i]);
      }
      ++column;
    }
  }
  return lines;
}

// Runs ceilplan with stdout and stderr on a pseudo-terminal, so it draws its progress lines.
std::string runOnTerminal(const std::vector<std::string>& arguments, int& exit_code) {
  int master = -1;
  const pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(CEILPLAN_EXE)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(CEILPLAN_EXE, argv.data());
    ::_exit(127);
  }
  std::string output;
  char buffer[4096];
  for (ssize_t n; (n = ::read(master, buffer, sizeof buffer)) > 0;) output.append(buffer, static_cast<std::size_t>(n));
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(master);
  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return output;
}

// When a stage ends, its progress line is gone: what follows starts on a clean line, on
// success and on an error found after the map was indexed.
TEST(HostileInputMessages, ProgressLinesAreClearedWhenWorkEnds) {
  const fs::path dir = scratchDirectory("progress");
  writeFile(dir / "free_air.yaml", substituted(replaced(kMission, "point: [1.5, 0.0, 4.0]", "point: [0.0, 0.0, 2.1]"),
                                               {{"{fx}", fixtures().string()}}));
  const std::string bridge = std::string(CEILPLAN_SOURCE_DIR) + "/maps/bridge.bt";
  const std::vector<std::pair<int, std::vector<std::string>>> runs = {
      {0,
       {"plan", "--map", bridge, "--start", "-4,0,0.5", "--goal", "-4,2,0.5", "--planner", "lattice", "--out",
        (dir / "plan").string()}},
      {0, {"mapinfo", "--map", bridge}},
      {2, {"tour", "--mission", (dir / "free_air.yaml").string(), "--out", (dir / "tour").string()}},
  };
  bool saw_progress = false;
  for (const auto& [expected_exit, arguments] : runs) {
    int exit_code = -1;
    const std::string raw = runOnTerminal(arguments, exit_code);
    EXPECT_EQ(exit_code, expected_exit) << raw;
    // The progress labels drawn: the text between a '\r' and " NN %".
    std::set<std::string> labels;
    const std::regex progress("\r([^\r\n]+?) [0-9]+ %");
    for (auto it = std::sregex_iterator(raw.begin(), raw.end(), progress); it != std::sregex_iterator(); ++it)
      labels.insert((*it)[1]);
    saw_progress |= !labels.empty();
    for (const std::string& line : visibleLines(raw))
      for (const std::string& label : labels)
        EXPECT_EQ(line.rfind(label, 0), std::string::npos) << "stale progress line: '" << line << "'";
  }
  EXPECT_TRUE(saw_progress) << "no progress drawn on a terminal: the check above checked nothing";
}

// ---- Interrupted runs --------------------------------------------------------------------------

struct Interruption {
  std::string name;
  std::vector<std::string> arguments;  // {dir} the case's directory
  std::string started;                 // interrupt once stdout holds this ...
  std::string staged;                  // ... and, if not empty, the staging directory holds this entry
  std::string exists = "";             // ... and, if not empty, this path under {dir} exists
  int signal = SIGINT;
};

void PrintTo(const Interruption& c, std::ostream* os) { *os << c.name; }

class InterruptedRun : public ::testing::TestWithParam<Interruption> {};

// Part-way through the work, SIGINT (SIGHUP, SIGTERM): the process ends by the signal (as a shell expects) and
// the output location holds nothing: no partial set, no temporary, no parent it created.
TEST_P(InterruptedRun, LeavesNothingBehind) {
  const Interruption& c = GetParam();
  const fs::path dir = scratchDirectory("interrupted_" + c.name);
  if (c.name == "rainflow") {
    std::ofstream csv(dir / "big.csv");
    csv << "t_s,soc\n";
    std::mt19937 rng(7);  // fixed: the same series every run
    std::uniform_real_distribution<double> soc(0.0, 1.0);
    for (int i = 0; i < 400000; ++i) csv << i << ',' << soc(rng) << '\n';
  }
  const auto before = snapshot(dir);
  const fs::path stdout_path = dir.parent_path() / ("interrupted_" + c.name + ".stdout");
  fs::remove(stdout_path);  // a previous run's must not look like this one's progress
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int out = ::open(stdout_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    std::freopen("/dev/null", "w", stderr);
    std::vector<std::string> arguments;
    for (const std::string& a : c.arguments) arguments.push_back(substituted(a, {{"{dir}", dir.string()}}));
    std::vector<char*> argv{const_cast<char*>(CEILPLAN_EXE)};
    for (std::string& a : arguments) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(CEILPLAN_EXE, argv.data());
    ::_exit(127);
  }
  const auto staged = [&] {
    if (!c.exists.empty() && !fs::exists(dir / c.exists)) return false;
    if (c.staged.empty()) return true;
    std::error_code ec;
    // A staging directory holds the output under its final name: {dir}/out.tmp-ceilplan-XXXXXX/out/...
    for (const auto& entry : fs::directory_iterator(dir, ec))
      if (entry.path().filename().string().find(".tmp") != std::string::npos)
        for (const auto& staged_output : fs::directory_iterator(entry.path(), ec))
          if (fs::exists(staged_output.path() / c.staged)) return true;
    return false;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
  int status = 0;
  bool ready = false;
  while (!ready && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(pid, &status, WNOHANG) == pid)
      FAIL() << "finished before it was interrupted: " << readWholeFile(stdout_path);
    ready = readWholeFile(stdout_path).find(c.started) != std::string::npos && staged();
    if (!ready) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_TRUE(ready) << "never reached the point to interrupt";
  ::kill(pid, c.signal);
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == c.signal) << "status " << status;
  EXPECT_EQ(snapshot(dir), before) << "an interrupted run left something";
}

const std::string kBridge = std::string(CEILPLAN_SOURCE_DIR) + "/maps/bridge.bt";

INSTANTIATE_TEST_SUITE_P(
    Signal, InterruptedRun,
    ::testing::Values(
        // tour --mode both: interrupted once ceiling mode's files are staged and free mode plans
        Interruption{"tour",
                     {"tour", "--mission", std::string(CEILPLAN_SOURCE_DIR) + "/maps/bridge.yaml", "--mode", "both",
                      "--no-export", "--out", "{dir}/out"},
                     "unknown space",
                     "ceiling/tour.json"},
        // the terminal closes during a tour: the same
        Interruption{"tour_sighup",
                     {"tour", "--mission", std::string(CEILPLAN_SOURCE_DIR) + "/maps/bridge.yaml", "--mode", "both",
                      "--no-export", "--out", "{dir}/out"},
                     "unknown space",
                     "ceiling/tour.json",
                     "",
                     SIGHUP},
        // duty's JSON and CSV directory are one set: SIGTERM while it is staged leaves neither
        Interruption{"duty_sigterm",
                     {"duty", "--days", "2000", "--json", "{dir}/d.json", "--csv-dir", "{dir}/csv"},
                     "",
                     ".ceilplan-output",
                     "",
                     SIGTERM},
        Interruption{"compare",
                     {"compare", "--map", kBridge, "--start", "-4,0,0.5", "--goal", "46,0,5.5", "--time-limit-s", "30",
                      "--out", "{dir}/out"},
                     "unknown space",
                     ""},
        Interruption{"plan",
                     {"plan", "--map", kBridge, "--start", "-4,0,0.5", "--goal", "46,0,5.5", "--time-limit-s", "30",
                      "--out", "{dir}/out"},
                     "unknown space",
                     ""},
        // rainflow prints its table, then writes the JSON under a parent it creates
        Interruption{"rainflow",
                     {"rainflow", "--csv", "{dir}/big.csv", "--column", "soc", "--json", "{dir}/out/c.json"},
                     "Rainflow cycles",
                     "",
                     "out"}),
    [](const auto& info) { return info.param.name; });

// ---- Outputs that would destroy, merge or half-write -----------------------------------------

// What a directory holds, seen without following links and without reading a FIFO or a device:
// a regular file's size and hash, a link's target, a special file's kind.
std::map<std::string, std::string> lstatSnapshot(const fs::path& dir) {
  std::map<std::string, std::string> entries;
  for (auto it = fs::recursive_directory_iterator(dir); it != fs::recursive_directory_iterator(); ++it) {
    const std::string name = it->path().lexically_relative(dir).string();  // fs::relative would follow links
    const fs::file_status status = it->symlink_status();
    if (fs::is_symlink(status)) {
      entries[name] = "link to " + fs::read_symlink(it->path()).string();
    } else if (fs::is_regular_file(status)) {
      const std::string bytes = readWholeFile(it->path());
      entries[name] = std::to_string(bytes.size()) + " bytes, hash " + std::to_string(std::hash<std::string>{}(bytes));
    } else {
      entries[name] = fs::is_directory(status) ? "<dir>" : fs::is_fifo(status) ? "<fifo>" : "<special>";
    }
  }
  return entries;
}

struct OutputRule {
  std::string name;
  std::string args;  // {fx} the fixtures, {src} the source tree, {dir} the row's directory
  std::string says;  // in stderr; every row is refused with exit 2
  std::function<void(const fs::path& dir)> prepare = [](const fs::path&) {};
};

void PrintTo(const OutputRule& c, std::ostream* os) { *os << c.name; }

// A directory a previous run of ceilplan wrote (it carries the marker).
void ceilplanOutputDirectory(const fs::path& dir) { writeFile(dir / ".ceilplan-output", "Written by ceilplan\n"); }

std::vector<OutputRule> outputRules() {
  const auto copy = [](const std::string& from, const std::string& name) {
    return [from, name](const fs::path& dir) {
      fs::copy_file(substituted(from, {{"{fx}", fixtures().string()}}), dir / name);
    };
  };
  const std::string calibration = std::string(CEILPLAN_SOURCE_DIR) + "/maps/calibration/published-ceiling-hover.csv";
  return {
      // An output that is one of the command's inputs: by name, through a symbolic or a hard link.
      {"input_mapinfo_map", "mapinfo --map {dir}/m.bt --json {dir}/m.bt", "--json {dir}/m.bt is the input --map",
       copy("{fx}/room.bt", "m.bt")},
      {"input_evaluate_path", "evaluate --map {fx}/room.bt --path {dir}/p.csv --json {dir}/p.csv",
       "--json {dir}/p.csv is the input --path", copy("{fx}/path.csv", "p.csv")},
      {"input_calibrate_data", "calibrate --data {dir}/c.csv --out {dir}/c.csv",
       "--out {dir}/c.csv is the input --data", copy(calibration, "c.csv")},
      {"input_rainflow_csv", "rainflow --csv {dir}/s.csv --column soc --json {dir}/s.csv",
       "--json {dir}/s.csv is the input --csv", copy("{fx}/soc.csv", "s.csv")},
      {"input_through_a_symlink", "mapinfo --map {dir}/m.bt --json {dir}/link.json",
       "--json {dir}/link.json is the input --map",
       [](const fs::path& dir) {
         fs::copy_file(fixtures() / "room.bt", dir / "m.bt");
         fs::create_symlink(dir / "m.bt", dir / "link.json");
       }},
      {"input_through_a_hard_link", "probe --map {dir}/m.bt --at 0,0,1 --json {dir}/hard.json",
       "--json {dir}/hard.json is the input --map",
       [](const fs::path& dir) {
         fs::copy_file(fixtures() / "room.bt", dir / "m.bt");
         fs::create_hard_link(dir / "m.bt", dir / "hard.json");
       }},
      {"input_config_file", "duty --config {dir}/c.yaml --json {dir}/c.yaml",
       "--json {dir}/c.yaml is the input --config",
       [](const fs::path& dir) { writeFile(dir / "c.yaml", "days: 1\n"); }},
      {"input_the_missions_map", "tour --mission {dir}/mission.yaml --out {dir}/m.bt --no-export",
       "--out {dir}/m.bt is the input the mission's map",
       [](const fs::path& dir) {
         fs::copy_file(fixtures() / "room.bt", dir / "m.bt");
         writeFile(dir / "mission.yaml", substituted(replaced(kMission, "{fx}/room.bt", (dir / "m.bt").string()),
                                                     {{"{fx}", fixtures().string()}}));
       }},
      {"input_inside_the_out_directory", "tour --mission {dir}/out/mission.yaml --out {dir}/out --no-export",
       "--out {dir}/out holds the input --mission {dir}/out/mission.yaml",
       [](const fs::path& dir) {
         ceilplanOutputDirectory(dir / "out");
         writeFile(dir / "out" / "mission.yaml", substituted(kMission, {{"{fx}", fixtures().string()}}));
       }},
      // Two outputs on one path, or one inside another that is written whole.
      {"shared_calibrate", "calibrate --data " + calibration + " --out {dir}/v.yaml --json {dir}/v.yaml",
       "--out and --json are the same path"},
      {"shared_bench_planners", kBench + " --json {dir}/b --log {dir}/b", "--json and --log are the same path"},
      {"shared_duty", "duty --days 1 --json {dir}/o --csv-dir {dir}/o", "--json and --csv-dir are the same path"},
      {"shared_duty_inside", "duty --days 1 --json {dir}/o/d.json --csv-dir {dir}/o",
       "--json {dir}/o/d.json lies inside --csv-dir {dir}/o"},
      {"shared_mapinfo", kMapinfo + " --json {dir}/s --slice-z 1 --slice-csv {dir}/s",
       "--json and --slice-csv are the same path"},
      // Special files: replaced by a regular file they would be gone.
      {"special_fifo_json", kMapinfo + " --json {dir}/fifo",
       "--json {dir}/fifo is a FIFO (named pipe), not a regular file",
       [](const fs::path& dir) { ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0); }},
      {"special_fifo_out", kPlan + " --out {dir}/fifo",
       "--out {dir}/fifo is a FIFO (named pipe), not a regular directory",
       [](const fs::path& dir) { ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0644), 0); }},
      {"special_link_to_stdout", "duty --days 1 --json {dir}/stdout", "--json {dir}/stdout is a symbolic link",
       [](const fs::path& dir) { fs::create_symlink("/dev/stdout", dir / "stdout"); }},
      {"special_link_to_a_directory", kPlan + " --out {dir}/elsewhere", "--out {dir}/elsewhere is a symbolic link",
       [](const fs::path& dir) {
         ceilplanOutputDirectory(dir / "real");
         fs::create_symlink(dir / "real", dir / "elsewhere");
       }},
      // A file output named as a directory.
      {"file_named_as_a_directory", "duty --days 1 --json {dir}/d/", "--json {dir}/d/ names a directory"},
      // A directory ceilplan did not write (or wrote before the marker): refused, untouched.
      {"foreign_directory_plan", kPlan + " --out {dir}/mine", "--out {dir}/mine is a directory ceilplan did not write",
       [](const fs::path& dir) { writeFile(dir / "mine" / "notes.txt", "keep"); }},
      {"foreign_directory_duty", "duty --days 1 --csv-dir {dir}/mine", "remove it or choose another --csv-dir",
       [](const fs::path& dir) { writeFile(dir / "mine" / "sub" / "notes.txt", "keep"); }},
      {"foreign_directory_tour", "tour --mission {fx}/mission.yaml --no-export --out {dir}/mine",
       "remove it or choose another --out", [](const fs::path& dir) { writeFile(dir / "mine" / "tour.json", "{}"); }},
  };
}

class OutputRules : public ::testing::TestWithParam<OutputRule> {};

// Refused before any work with exit 2 and one line naming the flag, the path and the problem;
// the directory, inputs and special files included, exactly as it was.
TEST_P(OutputRules, AreRefusedBeforeAnyWorkAndLeaveEverythingAsItWas) {
  const OutputRule& c = GetParam();
  const fs::path dir = scratchDirectory("output_rule_" + c.name);
  c.prepare(dir);
  const auto before = lstatSnapshot(dir);
  const std::map<std::string, std::string> paths = {
      {"{fx}", fixtures().string()}, {"{src}", CEILPLAN_SOURCE_DIR}, {"{dir}", dir.string()}};
  const CommandResult r = runCeilplan(substituted(c.args, paths));
  EXPECT_EQ(r.exit_code, 2) << "stderr: " << r.err << "\nstdout: " << r.out;
  const std::string says = substituted(c.says, paths);
  EXPECT_NE(r.err.find(says), std::string::npos) << "expected '" << says << "' in:\n" << r.err;
  expectOneCleanLine(r.err);
  EXPECT_EQ(lstatSnapshot(dir), before);
}

INSTANTIATE_TEST_SUITE_P(Table, OutputRules, ::testing::ValuesIn(outputRules()),
                         [](const auto& info) { return info.param.name; });

// A character device (a copy of /dev/null, made with mknod where allowed) is never replaced.
TEST(OutputRulesDevices, ACharacterDeviceIsRefused) {
  const fs::path dir = scratchDirectory("output_rule_device");
  if (::mknod((dir / "null").c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0)
    GTEST_SKIP() << "mknod needs root (CAP_MKNOD)";
  for (const std::string& args : {"current --gap-m 0.1 --json " + (dir / "null").string(),
                                  "duty --days 1 --csv-dir " + (dir / "null").string()}) {
    const CommandResult r = runCeilplan(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_NE(r.err.find((dir / "null").string() + " is a device"), std::string::npos) << r.err;
    struct stat status {};
    ASSERT_EQ(::lstat((dir / "null").c_str(), &status), 0);
    EXPECT_TRUE(S_ISCHR(status.st_mode)) << "the device was replaced";
  }
}

std::set<std::string> namesIn(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

// A second run into the same --out replaces the first's set: nothing of the first is merged in.
TEST(OutputRulesReruns, ATourWithoutExportLeavesNoAutopilotFileOfTheLastOne) {
  const fs::path dir = scratchDirectory("output_rerun_tour");
  const std::string tour =
      "tour --mission " + (fixtures() / "mission.yaml").string() + " --out " + (dir / "out").string();
  const CommandResult exported = runCeilplan(tour);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  const std::set<std::string> first = namesIn(dir / "out");
  for (const char* name : {"mission.plan", "mission.waypoints", "routes.kml", "routes.geojson", ".ceilplan-output"})
    ASSERT_EQ(first.count(name), 1u) << name << " not written by the first run: the check below checks nothing";
  const CommandResult again = runCeilplan(tour + " --no-export");
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const std::set<std::string> second = namesIn(dir / "out");
  EXPECT_EQ(second.count("tour.json"), 1u);
  EXPECT_EQ(second.count(".ceilplan-output"), 1u);
  for (const std::string& name : second)
    EXPECT_TRUE(name.find("mission.") != 0 && name.find("routes.") != 0) << name << " left from the first run";
  EXPECT_EQ(namesIn(dir), std::set<std::string>{"out"}) << "a staging directory or the old set left beside --out";
}

TEST(OutputRulesReruns, DutyWithFewerCasesLeavesNoCsvOfTheLastOnes) {
  const fs::path dir = scratchDirectory("output_rerun_duty");
  const std::string csv_dir = " --csv-dir " + (dir / "csv").string();
  const CommandResult three =
      runCeilplan("duty --days 1 --flight-current-a 9.5 --flight-current-a 8 --flight-current-a 7" + csv_dir);
  ASSERT_EQ(three.exit_code, 0) << three.err;
  const auto case3 = [&] {
    const std::set<std::string> names = namesIn(dir / "csv");
    return std::count_if(names.begin(), names.end(), [](const std::string& n) { return n.rfind("case3", 0) == 0; });
  };
  ASSERT_GT(case3(), 0) << "the first run wrote no case3 file: the check below checks nothing";
  const CommandResult one = runCeilplan("duty --days 1 --flight-current-a 9.5" + csv_dir);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(case3(), 0) << "case3's files were kept from the first run";
  EXPECT_EQ(namesIn(dir), std::set<std::string>{"csv"});
}

// An empty directory is fine; one ceilplan wrote, with a subdirectory of its own, is replaced
// whole (the merge used to stop half-way at a directory entry).
TEST(OutputRulesReruns, AnEmptyDirectoryOrOneCeilplanWroteIsReplacedWhole) {
  const fs::path dir = scratchDirectory("output_rerun_replace");
  fs::create_directories(dir / "empty");
  const std::string plan =
      "plan --map " + (fixtures() / "room.bt").string() + " --start -2,0,1 --goal 2,0,1 --planner lattice";
  const CommandResult into_empty = runCeilplan(plan + " --out " + (dir / "empty").string());
  ASSERT_EQ(into_empty.exit_code, 0) << into_empty.err;
  EXPECT_TRUE(fs::exists(dir / "empty" / "plan.json"));
  ceilplanOutputDirectory(dir / "old");
  writeFile(dir / "old" / "plan.json" / "stale.txt", "a directory where the new set has a file");
  writeFile(dir / "old" / "stale.csv", "from an older run");
  const CommandResult replaced_run = runCeilplan(plan + " --out " + (dir / "old").string());
  ASSERT_EQ(replaced_run.exit_code, 0) << replaced_run.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "old" / "plan.json"));
  EXPECT_FALSE(fs::exists(dir / "old" / "stale.csv"));
  EXPECT_EQ(namesIn(dir), (std::set<std::string>{"empty", "old"}));
  // "old/" is "old": staged beside it, not inside.
  const CommandResult slash = runCeilplan(plan + " --out " + (dir / "old").string() + "/");
  ASSERT_EQ(slash.exit_code, 0) << slash.err;
  EXPECT_TRUE(fs::is_regular_file(dir / "old" / "plan.json"));
  EXPECT_EQ(namesIn(dir), (std::set<std::string>{"empty", "old"}));
  EXPECT_EQ(namesIn(dir / "old").count(".ceilplan-output"), 1u);
}

// A staging directory left by a killed run (here: by a process that no longer exists, and by
// an earlier PID 1 of another container, with a start time that is not the present one's) is
// never merged into the next run's output, and is removed by it; a live run's is left alone.
TEST(OutputRulesReruns, StagingLeftByAKilledRunIsNeverMergedAndIsRemoved) {
  const fs::path dir = scratchDirectory("output_stale_staging");
  const std::string boot = [] {
    std::ifstream in("/proc/sys/kernel/random/boot_id");
    std::string id;
    std::getline(in, id);
    return id;
  }();
  const auto stale = [&](const std::string& suffix, const std::string& owner) {
    fs::path staging = dir / ("out.tmp-ceilplan-" + suffix);
    writeFile(staging / "out" / "stale.csv", "from a killed run");
    writeFile(staging / "out.owner", owner + "\n");
    return staging;
  };
  const fs::path dead = stale("Dead01", "2147483646 12345 " + boot);
  const fs::path pid1 = stale("Pid1ab", "1 1 " + boot);
  // This test process is alive: its start time, as /proc gives it.
  const std::string stat = readWholeFile("/proc/self/stat");
  std::istringstream fields(stat.substr(stat.rfind(')') + 1));
  std::string start;
  for (int i = 3; i <= 22; ++i) fields >> start;
  const fs::path live = stale("Live01", std::to_string(::getpid()) + " " + start + " " + boot);

  const CommandResult r = runCeilplan("duty --days 1 --csv-dir " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "stale.csv")) << "a killed run's staging was merged";
  EXPECT_FALSE(fs::exists(dead)) << "the staging of a process that is gone was kept";
  EXPECT_FALSE(fs::exists(pid1)) << "the staging of another container's PID 1 was kept";
  EXPECT_TRUE(fs::exists(live / "out" / "stale.csv")) << "a live run's staging was removed";
}

// A full disk (a small tmpfs, mounted where the test may) part-way through a set: none of its
// outputs appears, and the message names the output and the reason.
TEST(OutputRulesDiskFull, NoOutputOfTheSetAppears) {
  const fs::path dir = scratchDirectory("output_disk_full");
  const fs::path small = dir / "small";
  fs::create_directories(small);
  if (std::system(("mount -t tmpfs -o size=64k tmpfs " + small.string() + " 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "mounting a tmpfs needs root (CAP_SYS_ADMIN)";
  struct Unmount {
    fs::path at;
    ~Unmount() { std::system(("umount " + at.string()).c_str()); }
  } unmount{small};
  const std::vector<std::pair<std::string, std::string>> runs = {
      // the JSON fits, the series of 30 days do not
      {"duty", "duty --days 30 --json {small}/d.json --csv-dir {small}/csv"},
      // the JSON and the log do not both fit beside the filler
      {"bench_planners", replaced(kBench, "--runs 1", "--runs 10") + " --json {small}/b.json --log {small}/b.log"},
  };
  for (const auto& [name, args] : runs) {
    if (name == "bench_planners") writeFile(small / "filler", std::string(std::size_t{48} * 1024, 'x'));
    const auto before = lstatSnapshot(small);
    const CommandResult r =
        runCeilplan(substituted(args, {{"{fx}", fixtures().string()}, {"{small}", small.string()}}));
    EXPECT_EQ(r.exit_code, 1) << name << ": " << r.err;
    EXPECT_NE(r.err.find("No space left on device"), std::string::npos) << name << ": " << r.err;
    EXPECT_EQ(r.err.find(".tmp"), std::string::npos) << name << ": the staging path is named: " << r.err;
    expectOneCleanLine(r.err);
    EXPECT_EQ(lstatSnapshot(small), before) << name << ": part of the set was left";
  }
}

}  // namespace
