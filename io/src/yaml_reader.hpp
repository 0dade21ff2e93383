#pragma once
// Strict reading of ceilplan's YAML inputs (mission, vehicle, battery and --config files, and a
// mission's coverage keys, coverage_keys.hpp): the one YAML reader. Every key is known or an
// error with the nearest valid key, a repeated key is refused, every number has a physical range checked
// before anything is built, a file of the wrong kind says so, and every error is one line
// "FILE: 'dotted.key' ..." as a ceilplan::InputError. Private to io/.

#include <yaml-cpp/yaml.h>

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace ceilplan::io::detail {

// The largest mission, vehicle, battery or --config file read: 64 MiB, far above any real one.
inline constexpr std::uintmax_t kMaxYamlFileBytes = std::uintmax_t{64} << 20;

// A closed, open or half-open interval of physical values, with the unit for messages.
struct Range {
  double min;
  double max;
  std::string unit;       // "m", "Ah", "" for a ratio
  bool min_open = false;  // (min, ...]
  bool max_open = false;  // [..., max)

  static Range closed(double min, double max, std::string unit = "") { return {min, max, std::move(unit)}; }
  // (min, max]: a positive quantity with an upper bound.
  static Range above(double min, double max, std::string unit = "") { return {min, max, std::move(unit), true, false}; }
  // [min, max): e.g. a floor that must stay below 1.
  static Range below(double min, double max, std::string unit = "") { return {min, max, std::move(unit), false, true}; }
  // Any finite number: for a field whose model checks its own range (mission::Camera::validate).
  static Range finite(std::string unit = "");

  bool contains(double value) const;
  bool bounded() const;
  std::string describe() const;  // "(0, 1000] Ah"
};

// The kinds of file, with the top-level keys that identify each (to say "this is a vehicle
// file, not a battery file").
enum class FileKind { Mission, Vehicle, Battery };
std::string kindName(FileKind kind);

// The first YAML document of `text`, and how many documents it holds. yaml-cpp 0.7's LoadAll
// never returns on some malformed text (fuzz-vehicle-yaml, fuzz-mission-yaml and fuzz-flag-file
// found three, tests/io/fuzz_regressions_yaml/), so the first document is read
// with Load and the others are counted by their markers: a '---' line after content, or content
// after a '...' line. Throws YAML::Exception for malformed YAML.
// yaml-cpp's Node assignment is not noexcept; a YamlText is built once and returned, never assigned.
// NOLINTNEXTLINE(bugprone-exception-escape)
struct YamlText {
  YAML::Node first;
  std::size_t documents = 0;
};
YamlText loadYamlText(const std::string& text);

class YamlFile {
 public:
  // Reads `file`, which must exist, be a regular file and hold a YAML map. Throws InputError.
  YamlFile(const std::filesystem::path& file, FileKind kind);

  const std::filesystem::path& path() const { return path_; }
  const YAML::Node& root() const { return root_; }
  FileKind kind() const { return kind_; }

  // Throws InputError "FILE: problem".
  [[noreturn]] void fail(const std::string& problem) const;

 private:
  std::filesystem::path path_;
  FileKind kind_;
  YAML::Node root_;
};

// A map inside a YamlFile, with its dotted path for messages ("" for the root).
class Section {
 public:
  Section(const YamlFile& file, const YAML::Node& node, std::string path);

  const YamlFile& file() const { return *file_; }
  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }  // "battery", "surfaces[0]"; "" for the root
  bool has(const std::string& key) const { return static_cast<bool>(node_[key]); }
  // "battery.capacity_ah" for key "capacity_ah" of section "battery".
  std::string keyPath(const std::string& key) const;

  // Refuses keys not in `known`, naming the nearest known one. At the root, keys typical of
  // another kind of file make the error say which kind the file seems to be.
  void allowOnly(const std::vector<std::string>& known) const;

  // A required or optional sub-map.
  Section section(const std::string& key) const;
  std::optional<Section> optionalSection(const std::string& key) const;
  // A required node of any shape.
  YAML::Node required(const std::string& key) const;

  // Numbers: finite, in `range`; required, or `fallback` when absent.
  double number(const std::string& key, const Range& range) const;
  double number(const std::string& key, const Range& range, double fallback) const;
  // Whole numbers in [min, max].
  long long integer(const std::string& key, long long min, long long max) const;
  long long integer(const std::string& key, long long min, long long max, long long fallback) const;
  std::string text(const std::string& key) const;
  std::string text(const std::string& key, const std::string& fallback) const;
  // One of `choices`, naming them when it is not.
  std::string choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& fallback) const;
  // A required key, or "missing key 'PATH' (HINT)".
  YAML::Node required(const std::string& key, const std::string& hint) const;
  // [x, y, z], each finite and in `range`.
  Eigen::Vector3d vector3(const std::string& key, const Range& range) const;
  // [a, b] (or longer), each finite and in `range`.
  std::vector<double> numbers(const std::string& key, std::size_t count, const Range& range) const;

  // Checks a node read elsewhere (a list entry) the same way.
  double numberAt(const YAML::Node& node, const std::string& path, const Range& range) const;
  std::vector<double> numbersAt(const YAML::Node& node, const std::string& path, std::size_t count,
                                const Range& range) const;
  std::string choiceAt(const YAML::Node& node, const std::string& path, const std::vector<std::string>& choices) const;

  [[noreturn]] void fail(const std::string& problem) const { file_->fail(problem); }

 private:
  const YamlFile* file_;
  YAML::Node node_;
  std::string path_;
};

}  // namespace ceilplan::io::detail
