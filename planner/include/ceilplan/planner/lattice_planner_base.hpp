#pragma once
/// @file
/// What the lattice planners (LatticePlanner, LatticeRoadmap) share as OMPL planners: their
/// settings, the spacing as an OMPL parameter, the best cost as a progress property (for
/// ompl::tools::Benchmark), and the blockage of a search that found no path.

#include "ceilplan/planner/blockage.hpp"
#include "ceilplan/planner/lattice_settings.hpp"

#include <ompl/base/Planner.h>

#include <atomic>
#include <optional>
#include <string>

namespace ceilplan::planner {

/// What the lattice planners share: their settings and the blockage they report when no path exists.
class LatticePlannerBase : public ompl::base::Planner, public BlockageReporter {
 public:
  /// The lattice settings.
  const LatticeSettings& settings() const { return settings_; }
  /// Throws ceilplan::InputError for a spacing that is not a positive number.
  void setSpacing(double spacing_m);
  /// The node spacing asked for, m.
  double getSpacing() const { return settings_.spacing_m; }

  /// After a search that found no path: where the way is blocked.
  std::optional<Blockage> lastBlockage() const override { return blockage_; }

 protected:
  /// Throws ceilplan::InputError for bad settings.
  LatticePlannerBase(const ompl::base::SpaceInformationPtr& si, const std::string& name, LatticeSettings settings);
  /// Called when the settings change (the roadmap drops what it built for the old ones).
  virtual void settingsChanged() {}
  /// Forgets the last search's cost and blockage.
  void forgetResult();

  LatticeSettings settings_;          ///< the lattice settings
  std::atomic<double> best_cost_;     ///< the last search's best cost
  std::optional<Blockage> blockage_;  ///< the last search's blockage, if it found no path
};

}  // namespace ceilplan::planner
