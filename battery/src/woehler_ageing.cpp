#include "ceilplan/battery/woehler_ageing.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace ceilplan::battery {
namespace {

constexpr double kUnbounded = std::numeric_limits<double>::infinity();

ValidityRange dataSheetValidity(std::string notes) {
  // A data sheet's N100 holds for its own test conditions, which the law cannot know.
  return {{}, 0.0, kUnbounded, kUnbounded, kUnbounded, std::move(notes)};
}

}  // namespace

void WoehlerParameters::validate() const {
  if (!(cycles_at_full_depth > 0.0) || !std::isfinite(cycles_at_full_depth))
    throw ceilplan::InputError("Woehler N100 (cycles to end of life at DoD 1) must be positive, got " +
                               formatNumber(cycles_at_full_depth));
  if (!(exponent >= 0.0) || !std::isfinite(exponent))
    throw ceilplan::InputError("Woehler exponent k must be >= 0, got " + formatNumber(exponent));
  if (!(end_of_life_capacity_loss > 0.0 && end_of_life_capacity_loss <= 1.0))
    throw ceilplan::InputError("end-of-life capacity loss must be in (0, 1], got " +
                               formatNumber(end_of_life_capacity_loss));
}

double woehlerCyclesToEndOfLife(double depth, const WoehlerParameters& parameters) {
  if (!(depth > 0.0)) return kUnbounded;
  return parameters.cycles_at_full_depth * std::pow(std::min(depth, 1.0), -parameters.exponent);
}

WoehlerAgeingModel::WoehlerAgeingModel(const WoehlerParameters& parameters) : parameters_(parameters) {
  parameters_.validate();
}

ValidityRange WoehlerAgeingModel::validity() const {
  return dataSheetValidity(
      "N100 and k come from a data sheet [open]; temperature and C-rate as the data sheet's tests");
}

std::unique_ptr<AgeingModel> WoehlerAgeingModel::clone() const { return std::make_unique<WoehlerAgeingModel>(*this); }

void WoehlerAgeingModel::addCycle(const RainflowCycle& cycle) {
  closed_damage_ += cycle.count / woehlerCyclesToEndOfLife(cycle.range, parameters_);
}

double WoehlerAgeingModel::damageWith(const std::vector<RainflowCycle>& open) const {
  double damage = closed_damage_;
  for (const RainflowCycle& cycle : open) damage += cycle.count / woehlerCyclesToEndOfLife(cycle.range, parameters_);
  return damage;
}

double WoehlerAgeingModel::damage() const { return damageWith(rainflow().residue()); }

double WoehlerAgeingModel::capacityLossWith(const std::vector<RainflowCycle>& open) const {
  return damageWith(open) * parameters_.end_of_life_capacity_loss;
}

FecAgeingModel::FecAgeingModel(const WoehlerParameters& parameters) : parameters_(parameters) {
  parameters_.validate();
}

ValidityRange FecAgeingModel::validity() const {
  return dataSheetValidity("no DoD, SOC, temperature or C-rate dependence; calendar ageing neglected (paper)");
}

double FecAgeingModel::modelCapacityLoss() const {
  return fec_ / parameters_.cycles_at_full_depth * parameters_.end_of_life_capacity_loss;
}

std::unique_ptr<AgeingModel> FecAgeingModel::clone() const { return std::make_unique<FecAgeingModel>(*this); }

void FecAgeingModel::consume(const AgeingSample* previous, const AgeingSample* samples, std::size_t count) {
  // Summed sample by sample, so that any split of the history gives the same total. A swing
  // moved |dSOC| usable capacities, |dSOC| SOH nominal ones.
  double soc_before = previous != nullptr ? previous->soc : samples[0].soc;
  for (std::size_t i = 0; i < count; ++i) {
    fec_ += 0.5 * std::fabs(samples[i].soc - soc_before) * samples[i].state_of_health;
    soc_before = samples[i].soc;
  }
}

}  // namespace ceilplan::battery
