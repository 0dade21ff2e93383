#pragma once
/// @file
/// Where an output came from: the ceilplan version and git revision, the command line, every
/// input file with its SHA-256, and the seed. JSON outputs carry it as "provenance", CSV
/// outputs as a first comment line.

#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ceilplan::io {

/// One input file of a run, with its SHA-256.
struct InputFile {
  std::string role;            ///< "mission", "map", "vehicle", "battery", "path", ...
  std::filesystem::path path;  ///< as given
  std::string sha256;          ///< hex
};

/// Where an output came from: version, command line, inputs with their SHA-256, seed (docs/cli.md).
struct Provenance {
  std::string version;                ///< "0.1.0 (git abc123)"
  std::string command_line;           ///< as typed (arguments joined and quoted), or who called the library
  std::vector<InputFile> inputs;      ///< every input file read
  std::optional<std::uint64_t> seed;  ///< the seed of every random choice, when there was one

  /// The version of this build, `command_line`, no inputs yet.
  static Provenance of(std::string command_line);
  /// Adds an input file with its SHA-256; an empty path is skipped (a built-in default).
  Provenance& input(const std::string& role, const std::filesystem::path& path);

  /// The provenance as a JSON object.
  nlohmann::json json() const;
  /// The same as named one-line fields, for formats that hold such (OMPL's benchmark log):
  /// "ceilplan", "command", "seed" when there is one, and per input ROLE and ROLE_sha256.
  std::vector<std::pair<std::string, std::string>> fields() const;
  /// One line: "ceilplan 0.1.0 (git ...) | ceilplan tour ... | seed 1 | map bridge.bt sha256 ..."
  std::string line() const;
  /// The same as a comment, "# " + line(): the first line of every CSV output.
  std::string csvComment() const;
};

/// `json`, an object, with `provenance` under "provenance": what every JSON output records.
nlohmann::json withProvenance(nlohmann::json json, const Provenance& provenance);
/// The same for an ordered JSON document.
nlohmann::ordered_json withProvenance(nlohmann::ordered_json json, const Provenance& provenance);

/// The command line as one string, each argument quoted where the shell would need it.
std::string commandLine(int argc, const char* const* argv);

/// SHA-256 of a file's bytes, as lowercase hex. Throws ceilplan::InputError if it cannot be read.
std::string sha256File(const std::filesystem::path& file);

}  // namespace ceilplan::io
