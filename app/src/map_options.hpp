#pragma once
// The unknown-space flags of every command that reads a map, registered the same way
// everywhere: `--unknown occupied|free|fill` and `--unknown-fill-max-m M` (docs/environment.md,
// "Unknown space"); io/unknown_space_report.hpp says what the policy assumed.

#include "ceilplan/environment/map_index.hpp"
#include "ceilplan/environment/unknown_space.hpp"

#include <CLI/CLI.hpp>

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

}  // namespace ceilplan::app
