#include "ceilplan/planner/lattice_planner_base.hpp"
#include "ceilplan/core/format.hpp"

#include "ceilplan/core/error.hpp"

#include <cmath>
#include <limits>

namespace ceilplan::planner {

void LatticeSettings::validate() const {
  if (!(spacing_m >= kMinLatticeSpacing_m && spacing_m <= kMaxLatticeSpacing_m))
    throw ceilplan::InputError("lattice spacing must be a finite number in [" + formatNumber(kMinLatticeSpacing_m) +
                               ", " + formatNumber(kMaxLatticeSpacing_m) + "] m, got " + formatNumber(spacing_m));
  if (workers < 1) throw ceilplan::InputError("the lattice planners need at least one worker thread");
}

LatticePlannerBase::LatticePlannerBase(const ompl::base::SpaceInformationPtr& si, const std::string& name,
                                       LatticeSettings settings)
    : ompl::base::Planner(si, name),
      settings_(std::move(settings)),
      best_cost_(std::numeric_limits<double>::infinity()) {
  settings_.validate();
  specs_.optimizingPaths = true;
  specs_.directed = true;
  declareParam<double>("spacing_m", this, &LatticePlannerBase::setSpacing, &LatticePlannerBase::getSpacing,
                       "0.01:0.01:2.0");
  addPlannerProgressProperty("best cost REAL", [this] { return formatNumber(best_cost_.load(), 17); });
}

void LatticePlannerBase::setSpacing(double spacing_m) {
  LatticeSettings settings = settings_;
  settings.spacing_m = spacing_m;
  settings.validate();
  settings_ = settings;
  settingsChanged();
}

void LatticePlannerBase::forgetResult() {
  best_cost_ = std::numeric_limits<double>::infinity();
  blockage_.reset();
}

}  // namespace ceilplan::planner
