#pragma once
// The unknown-space flags of every command that reads a map, registered the same way
// everywhere: `--unknown occupied|free|fill` and `--unknown-fill-max-m M` (docs/environment.md,
// "Unknown space"), and how a command reports what the policy assumed.

#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/unknown_space.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace ceilplan::app {

class UnknownSpaceFlags {
 public:
  // Adds both flags to `command`; this object must outlive the parse (keep it with the
  // command's other options).
  void addTo(CLI::App& command);

  // Whether either flag was given (on the command line or in --config): a mission file's
  // `unknown:` key applies only when not.
  bool given() const;
  // The policy asked for (occupied when no flag was given). Throws ceilplan::InputError for
  // --unknown-fill-max-m without --unknown fill.
  environment::UnknownSpace value() const;

 private:
  std::string policy_ = "occupied";
  double fill_max_m_ = environment::UnknownSpace::kDefaultFillMax_m;
  CLI::Option* policy_option_ = nullptr;
  CLI::Option* fill_option_ = nullptr;
};

// What outputs say about the policy: {"policy", "fill_max_m" (null unless fill),
// "unknown_volume_m3", "assumed_free_volume_m3", "regions", "filled_regions"}.
nlohmann::json unknownSpaceJson(const environment::UnknownSpace& unknown, const environment::UnknownSpaceSummary& summary);
// One line for text outputs, e.g. "fill (pockets up to 1 m): 0.42 of 12.3 m3 unknown assumed free (7 of 19 regions)".
std::string unknownSpaceLine(const environment::UnknownSpace& unknown, const environment::UnknownSpaceSummary& summary);

}  // namespace ceilplan::app
