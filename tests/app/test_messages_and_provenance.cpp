// Text that came from the user, and where every output came from (docs/cli.md). A map path or a
// target name holding bytes that are not UTF-8, or an escape sequence a terminal would obey, is
// shown escaped (\xHH) and written to JSON without failing: the run succeeds as it would with a
// plain name. Every JSON and CSV a command writes records the ceilplan version, the command line
// and each input file with its SHA-256.
#include "run_command.hpp"

#include "ceilplan/io/provenance.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace ceilplan::testing;

const fs::path kSource = CEILPLAN_SOURCE_DIR;

// A name with a byte that is not UTF-8 (0xFF) and a terminal's "turn red" escape.
const std::string kHostileName = "m\xff\x1b[31mark";

// Quoted for the shell: the test's own paths hold no single quote.
std::string shellQuoted(const fs::path& path) { return "'" + path.string() + "'"; }

// A one-target mission on the shipped open scene: quick to tour.
std::string missionText(const fs::path& map, const std::string& target_name) {
  return "map: '" + map.string() + "'\nvehicle: " + (kSource / "maps/vehicles/quad.yaml").string() +
         "\nbattery: {capacity_ah: 5.2, start_soc: 0.95, reserve_soc: 0.25, charge_current_a: 10.4}\n"
         "home: [-4.0, 0.0, 0.5]\norigin: {lat: 52.219, lon: 0.093, alt: 12.0}\nseed: 1\n"
         "targets:\n  - {name: \"" +
         target_name + "\", point: [6.0, 0.0, 0.0], dwell_s: 5, standoff_m: [0.5, 2.0]}\n";
}

// Whether `text` is valid UTF-8 with no control byte but line breaks: what a terminal shows as is.
bool printable(const std::string& text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n' || (c >= 0x20 && c < 0x7f)) {
      ++i;
      continue;
    }
    const int length = c >= 0xF0 && c <= 0xF4 ? 4 : c >= 0xE0 ? 3 : c >= 0xC2 && c <= 0xDF ? 2 : 0;
    if (length == 0 || i + length > text.size()) return false;
    for (int k = 1; k < length; ++k)
      if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) return false;
    if (length == 2 && c == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0) return false;  // C1 controls
    i += length;
  }
  return true;
}

// Every file under `dir` (or `dir` itself) whose name ends in `extension`.
std::vector<fs::path> filesEndingIn(const fs::path& dir, const std::string& extension) {
  std::vector<fs::path> found;
  if (fs::is_regular_file(dir)) {
    if (dir.extension() == extension) found.push_back(dir);
    return found;
  }
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().extension() == extension) found.push_back(entry.path());
  return found;
}

// ---- Hostile names -------------------------------------------------------------------------

struct NameCase {
  std::string name;
  std::string args;                     // after `ceilplan`: {map} the hostile map path, {dir} the case's directory
  bool shows_name;                      // the command's report names the file
  std::string mission_target = "mark";  // the target's name in {dir}/mission.yaml (on {map})
};

void PrintTo(const NameCase& c, std::ostream* os) { *os << c.name; }

class HostileName : public ::testing::TestWithParam<NameCase> {};

TEST_P(HostileName, IsShownEscapedAndWrittenToJsonWithoutFailing) {
  const NameCase& c = GetParam();
  const fs::path dir = scratchDirectory("hostile_name_" + c.name);
  const fs::path map = dir / (kHostileName + ".bt");
  fs::copy_file(kSource / "maps/open.bt", map);
  writeWholeFile(dir / "mission.yaml", missionText(map, c.mission_target));
  writeWholeFile(dir / (kHostileName + ".csv"), "t_s,soc\n0,0.9\n10,0.5\n20,0.8\n30,0.3\n");
  const CommandResult r = runCeilplan(substituted(c.args, {{"{map}", shellQuoted(map)}, {"{dir}", shellQuoted(dir)}}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(printable(r.out)) << "raw bytes on the terminal: " << r.out;
  EXPECT_TRUE(printable(r.err)) << "raw bytes on the terminal: " << r.err;
  if (c.shows_name) {
    EXPECT_NE(r.out.find("m\\xFF\\x1B[31mark"), std::string::npos) << "not shown escaped:\n" << r.out;
  }
  const std::vector<fs::path> json = filesEndingIn(dir / "out", ".json");
  EXPECT_FALSE(json.empty());
  for (const fs::path& file : json) EXPECT_TRUE(nlohmann::json::accept(readWholeFile(file))) << file;
}

INSTANTIATE_TEST_SUITE_P(
    Table, HostileName,
    ::testing::Values(NameCase{"map_path_mapinfo", "mapinfo --map {map} --json {dir}/out/info.json", true},
                      NameCase{"map_path_probe", "probe --map {map} --at 0,0,1 --json {dir}/out/probe.json", false},
                      NameCase{"map_path_plan",
                               "plan --map {map} --start -4,0,1 --goal 4,0,1 --planner lattice --out {dir}/out", false},
                      NameCase{"map_path_tour", "tour --mission {dir}/mission.yaml --no-export --out {dir}/out", false},
                      NameCase{"target_name_tour", "tour --mission {dir}/mission.yaml --no-export --out {dir}/out",
                               false, kHostileName},
                      NameCase{"csv_path_rainflow",
                               "rainflow --csv {dir}/" + shellQuoted(kHostileName + ".csv") +
                                   " --column soc --json {dir}/out/cycles.json",
                               true}),
    [](const auto& info) { return info.param.name; });

// A message quoting a hostile name (a missing file, an unknown flag CLI11 reports) is one line,
// escaped.
TEST(HostileNameMessages, AreOneEscapedLine) {
  const fs::path dir = scratchDirectory("hostile_name_messages");
  writeWholeFile(dir / "soc.csv", "t_s,soc\n0,0.9\n10,0.5\n");
  for (const std::string& args :
       {"mapinfo --map " + shellQuoted(dir / (kHostileName + ".bt")),
        "mapinfo --map " + shellQuoted(kSource / "maps/open.bt") + " " + shellQuoted("--" + kHostileName),
        "rainflow --csv " + shellQuoted(dir / "soc.csv") + " --column " + shellQuoted(kHostileName)}) {
    const CommandResult r = runCeilplan(args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(printable(r.err)) << "raw bytes on the terminal: " << r.err;
    EXPECT_NE(r.err.find("m\\xFF\\x1B[31mark"), std::string::npos) << r.err;
  }
}

// ---- Provenance in every output -----------------------------------------------------------

struct OutputCase {
  std::string name;
  std::string args;  // after `ceilplan`: {src} the source tree, {dir} the case's inputs, {out} the output
  std::vector<std::string> inputs;  // files whose SHA-256 every output records ({src} and {dir} as in args)
};

void PrintTo(const OutputCase& c, std::ostream* os) { *os << c.name; }

class EveryOutput : public ::testing::TestWithParam<OutputCase> {};

TEST_P(EveryOutput, RecordsTheVersionTheCommandLineAndTheInputsWithTheirSha256) {
  const OutputCase& c = GetParam();
  const fs::path dir = scratchDirectory("provenance_" + c.name);
  writeWholeFile(dir / "path.csv", "x,y,z\n-4,0,1\n0,0,1\n4,0,1\n");
  writeWholeFile(dir / "soc.csv", "t_s,soc\n0,0.9\n10,0.5\n20,0.8\n30,0.3\n");
  writeWholeFile(dir / "points.xyz", "0 0 0\n1 0 0\n0 1 0\n1 1 1\n");
  writeWholeFile(dir / "mission.yaml", missionText(kSource / "maps/open.bt", "mark"));
  const std::map<std::string, std::string> values = {
      {"{src}", kSource.string()}, {"{dir}", dir.string()}, {"{out}", (dir / "out").string()}};
  const std::string args = substituted(c.args, values);
  const CommandResult r = runCeilplan(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string command = args.substr(0, args.find(' '));

  std::vector<fs::path> outputs;
  for (const fs::path& root : {dir / "out", dir / "out.json", dir / "out.bt.json"}) {
    if (!fs::exists(root)) continue;
    for (const char* extension : {".json", ".csv"})
      for (const fs::path& file : filesEndingIn(root, extension)) outputs.push_back(file);
  }
  ASSERT_FALSE(outputs.empty()) << "no JSON or CSV written";
  for (const fs::path& file : outputs) {
    const std::string text = readWholeFile(file);
    std::string version, command_line;
    std::map<std::string, std::string> sha256;  // path -> hex
    if (file.extension() == ".json") {
      const nlohmann::json json = nlohmann::json::parse(text);
      ASSERT_TRUE(json.contains("provenance")) << file;
      const nlohmann::json& provenance = json["provenance"];
      version = provenance["ceilplan"].get<std::string>();
      command_line = provenance["command"].get<std::string>();
      for (const nlohmann::json& input : provenance["inputs"])
        sha256[input["path"].get<std::string>()] = input["sha256"].get<std::string>();
    } else {
      const std::string first = text.substr(0, text.find('\n'));
      ASSERT_EQ(first.rfind("# ceilplan ", 0), 0u) << file << ": " << first;
      version = first;
      command_line = first;
      for (auto at = first.find(" sha256 "); at != std::string::npos; at = first.find(" sha256 ", at + 1)) {
        const std::size_t path_start = first.rfind(' ', at - 1) + 1;
        sha256[first.substr(path_start, at - path_start)] = first.substr(at + 8, 64);
      }
    }
    EXPECT_NE(version.find("git "), std::string::npos) << file << ": " << version;
    EXPECT_NE(command_line.find("ceilplan " + command + " "), std::string::npos) << file << ": " << command_line;
    for (const std::string& input : c.inputs) {
      const std::string path = substituted(input, values);
      ASSERT_EQ(sha256.count(path), 1u) << file << " does not record " << path;
      EXPECT_EQ(sha256[path], ceilplan::io::sha256File(path)) << file;
    }
  }
}

const std::string kOpen = "{src}/maps/open.bt";

INSTANTIATE_TEST_SUITE_P(
    Table, EveryOutput,
    ::testing::Values(
        OutputCase{
            "plan", "plan --map " + kOpen + " --start -4,0,1 --goal 4,0,1 --planner lattice --out {out}", {kOpen}},
        OutputCase{"compare",
                   "compare --map " + kOpen + " --start -4,0,1 --goal 4,0,1 --planner lattice --out {out}",
                   {kOpen}},
        OutputCase{"evaluate",
                   "evaluate --map " + kOpen + " --path {dir}/path.csv --json {out}/check.json",
                   {kOpen, "{dir}/path.csv"}},
        OutputCase{"tour",
                   "tour --mission {dir}/mission.yaml --out {out}",
                   {"{dir}/mission.yaml", kOpen, "{src}/maps/vehicles/quad.yaml"}},
        OutputCase{"current",
                   "current --gap-m 0.1 --vehicle {src}/maps/vehicles/quad.yaml --json {out}/current.json",
                   {"{src}/maps/vehicles/quad.yaml"}},
        OutputCase{"mapinfo",
                   "mapinfo --map " + kOpen + " --json {out}/info.json --slice-z 1 --slice-csv {out}/slice.csv",
                   {kOpen}},
        OutputCase{"probe", "probe --map " + kOpen + " --at 0,0,1 --json {out}/probe.json", {kOpen}},
        OutputCase{"duty", "duty --days 1 --json {out}/duty.json --csv-dir {out}/series", {}},
        OutputCase{"rainflow", "rainflow --csv {dir}/soc.csv --column soc --json {out}/cycles.json", {"{dir}/soc.csv"}},
        OutputCase{"calibrate",
                   "calibrate --data {src}/maps/calibration/published-ceiling-hover.csv --out {out}/quad.yaml "
                   "--json {out}/fit.json",
                   {"{src}/maps/calibration/published-ceiling-hover.csv"}},
        OutputCase{"import", "import --points {dir}/points.xyz --resolution 0.1 --out {out}.bt", {"{dir}/points.xyz"}},
        OutputCase{
            "bench_planners",
            "bench-planners --map " + kOpen +
                " --start -4,0,1 --goal 4,0,1 --planners RRTstar --runs 1 --time-limit-s 0.2 --json {out}/bench.json",
            {kOpen}}),
    [](const auto& info) { return info.param.name; });

// The calibrated vehicle file and OMPL's benchmark log have their own forms: a YAML comment and
// the log's experiment properties.
TEST(EveryOutput, TheCalibratedVehicleAndTheBenchmarkLogRecordTheirProvenance) {
  const fs::path dir = scratchDirectory("provenance_yaml_and_log");
  const std::string data = (kSource / "maps/calibration/published-ceiling-hover.csv").string();
  ASSERT_EQ(runCeilplan("calibrate --data " + data + " --out " + (dir / "quad.yaml").string()).exit_code, 0);
  const std::string yaml = readWholeFile(dir / "quad.yaml");
  EXPECT_NE(yaml.find("\n# ceilplan "), std::string::npos) << yaml.substr(0, 400);
  EXPECT_NE(yaml.find(data + " sha256 " + ceilplan::io::sha256File(data)), std::string::npos) << yaml.substr(0, 400);

  const std::string map = (kSource / "maps/open.bt").string();
  const CommandResult bench = runCeilplan("bench-planners --map " + map +
                                          " --start -4,0,1 --goal 4,0,1 --planners RRTstar "
                                          "--runs 1 --time-limit-s 0.2 --log " +
                                          (dir / "bench.log").string());
  ASSERT_EQ(bench.exit_code, 0) << bench.err;
  const std::string log = readWholeFile(dir / "bench.log");
  EXPECT_NE(log.find("provenance_command VARCHAR = "), std::string::npos) << log.substr(0, 600);
  EXPECT_NE(log.find("provenance_map_sha256 VARCHAR = " + ceilplan::io::sha256File(map)), std::string::npos)
      << log.substr(0, 600);
}

}  // namespace
