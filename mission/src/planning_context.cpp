#include "ceilplan/mission/planning_context.hpp"

#include "ceilplan/battery/ageing_factory.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/core/spelling.hpp"
#include "ceilplan/energy/lipo_open_circuit_voltage.hpp"
#include "ceilplan/planner/ageing_rates.hpp"
#include "ceilplan/planner/flight_planner.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>

namespace ceilplan::mission {
namespace {

void requireIn(double value, double min, double max, const std::string& what) {
  if (!(value >= min && value <= max))
    throw InputError(what + " must be in [" + formatNumber(min) + ", " + formatNumber(max) + "], got " +
                     formatNumber(value));
}

}  // namespace

void PlanningOptions::validate() const {
  const auto& objectives = planner::objectiveNames();
  if (std::find(objectives.begin(), objectives.end(), objective) == objectives.end())
    throw InputError("unknown objective '" + objective + "'");
  const auto& models = battery::ageingModelNames();
  if (std::find(models.begin(), models.end(), ageing_model) == models.end())
    throw InputError("unknown ageing model '" + ageing_model + "'");
  requireIn(ageing_dod, 0.0, 1.0, "ageing depth of discharge");
  requireIn(min_ceiling_gap_m, 0.0, 2.0, "minimum ceiling gap (m)");
  requireIn(standoff_m, 0.0, 20.0, "standoff (m)");
  requireIn(temperature_c, -40.0, 80.0, "cell temperature (C)");
  battery::makeAgeingModel(ageing_model, ageingModelOptions(temperature_c));  // the models' own temperature range
  planner::checkSeed(seed);
  unknown.validate();
  wind.validate();
}

battery::AgeingModelOptions ageingModelOptions(double temperature_c) {
  battery::AgeingModelOptions options;
  options.conditions = battery::OperatingConditions::fromCelsius(temperature_c);
  const energy::LipoOpenCircuitVoltage ocv;  // the energy module's cell curve, for Schmalstieg
  options.cell_voltage_of_soc = [ocv](double soc) { return ocv.cellVoltageV(soc); };
  return options;
}

PlanningContext::PlanningContext(environment::OccupancyMap map, Vehicle vehicle, BatterySpec battery,
                                 PlanningOptions options, const ProgressCallback& progress)
    : options_(std::move(options)),
      vehicle_(std::move(vehicle)),
      battery_(std::move(battery)),
      map_(std::move(map)),
      progress_(progress) {
  options_.validate();
  vehicle_.validate();
  battery_.validate();
  energy_ = std::make_unique<energy::EnergyModel>(vehicle_.energy);
  options_.speeds.validate(energy_->maxSpeedM_s());  // before the map is indexed
  planner::checkAirspeedLimit(options_.wind, options_.speeds, energy_->maxSpeedM_s());
  const std::string stage = "indexing " + map_.name();
  environment_ = std::make_unique<environment::Environment>(
      map_, vehicle_.geometry, options_.environment,
      environment::MapIndexOptions{options_.unknown, options_.environment.workers}, [&](double f) {
        if (progress_) progress_(stage, f);
      });
  planner::CostModelOptions full;
  full.speeds = options_.speeds;
  full.planning_soc = battery_.start_soc;
  full.wind = options_.wind;
  full_model_ = std::make_unique<planner::FlightCostModel>(*environment_, *energy_, full);
  base_rules_ = std::make_unique<planner::SafetyRules>(*environment_, options_.min_ceiling_gap_m);
  shared_ = std::make_shared<SharedWork>();
}

// The floods and lattice validities asked for so far; each flood stays where it is, so a
// returned reference stays valid.
struct PlanningContext::SharedWork {
  std::mutex mutex;
  std::vector<std::unique_ptr<planner::ReachableSpace>> spaces;
  std::vector<std::pair<double, std::shared_ptr<const planner::LatticeValidity>>> validities;  ///< by requested spacing
};

PlanningContext::PlanningContext(const Mission& mission, const ProgressCallback& progress)
    : PlanningContext(environment::OccupancyMap::load(mission.map_file), mission.vehicle, mission.battery,
                      mission.planning, progress) {}

PlanningContext::Mode PlanningContext::mode(FlightMode mode) const {
  Mode result;
  planner::CostModelOptions options = full_model_->options();
  if (mode == FlightMode::Free) {
    options.proximity_effects = false;
    options.standoff_m = options_.standoff_m;
  }
  result.model = std::make_unique<planner::FlightCostModel>(*environment_, *energy_, options);
  result.rules = std::make_unique<planner::SafetyRules>(*environment_, options_.min_ceiling_gap_m);
  return result;
}

const planner::ReachableSpace& PlanningContext::reachableFrom(const Eigen::Vector3d& origin_m, double spacing_m,
                                                              int workers) const {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  for (const auto& space : shared_->spaces)
    if (space->origin_m() == origin_m && space->requestedSpacing_m() == spacing_m) return *space;
  shared_->spaces.push_back(std::make_unique<planner::ReachableSpace>(*base_rules_, origin_m, spacing_m, workers));
  return *shared_->spaces.back();
}

std::shared_ptr<const planner::LatticeValidity> PlanningContext::latticeValidity(double spacing_m) const {
  const std::lock_guard<std::mutex> lock(shared_->mutex);
  for (const auto& [requested_m, validity] : shared_->validities)
    if (requested_m == spacing_m) return validity;
  shared_->validities.emplace_back(spacing_m,
                                   std::make_shared<const planner::LatticeValidity>(*base_rules_, spacing_m));
  return shared_->validities.back().second;
}

planner::ObjectiveChoice PlanningContext::objective(const Eigen::Vector3d& start_m, const Eigen::Vector3d& goal_m,
                                                    const std::string& name) const {
  planner::ObjectiveChoice choice;
  choice.name = name.empty() ? options_.objective : name;
  const auto& names = planner::objectiveNames();
  if (std::find(names.begin(), names.end(), choice.name) == names.end())
    throw InputError("unknown objective '" + choice.name + "'" + didYouMean(choice.name, names));
  choice.nominal_capacity_ah = battery_.pack.capacity_ah;
  if (choice.name != "ageing") return choice;
  // The route's expected depth of discharge: the straight line's charge under the full model
  // (a fair estimate for a route a little longer), never below 1 %.
  double dod = options_.ageing_dod;
  if (dod == 0.0) {
    const double straight_ah = full_model_->integrate(start_m, goal_m).charge_ah;
    dod = std::max(0.01, straight_ah / battery_.pack.usableCapacityAh());
  }
  dod = std::min(dod, battery_.start_soc - battery_.pack.soc_min);
  energy::FlightCondition cruise;
  cruise.speed_m_s = options_.speeds.cruise_m_s;
  cruise.soc = battery_.start_soc;
  const double cruise_current_a = energy_->currentA(energy::kNoSurface, 0.0, cruise);
  choice.ageing = planner::measureAgeingRates(options_.ageing_model, ageingModelOptions(options_.temperature_c),
                                              battery_.pack, battery_.start_soc, dod, cruise_current_a);
  return choice;
}

}  // namespace ceilplan::mission
