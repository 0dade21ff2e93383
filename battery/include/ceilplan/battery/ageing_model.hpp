#pragma once
/// @file
/// The common interface of the battery-ageing models (docs/ageing.md): a model
/// is fed a state-of-charge history piece by piece, in time order, and tells the fraction of
/// nominal capacity lost so far.

#include "ceilplan/core/error.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace ceilplan::battery {

/// One point of a battery's history. `current_a` is positive while discharging (the sign of
/// paper eq. 7, SOC falling); the models use it only for the C-rates they report having seen.
/// `state_of_health` is the usable capacity over the nominal one while the pack moved to this
/// sample (paper eq. 7): an SOC swing dSOC moved dSOC * SOH nominal capacities of charge, which
/// is what the throughput-based measures (FEC, Schmalstieg's Q) count. 1 for a new pack.
struct AgeingSample {
  double t_s = 0.0;              ///< time of the sample, s
  double soc = 0.0;              ///< state of charge, 0..1
  double current_a = 0.0;        ///< pack current, A, positive discharging
  double state_of_health = 1.0;  ///< in (0, 1]
};

/// Where a model was fitted, so that a study outside it can say so. Unbounded limits are
/// infinite.
struct ValidityRange {
  std::vector<std::string> chemistries;  ///< fitted on these (e.g. "NMC"); empty: any
  double min_temperature_k;              ///< lowest cell temperature fitted, K
  double max_temperature_k;              ///< highest cell temperature fitted, K
  double max_charge_c_rate;              ///< highest charge C-rate fitted, 1/h
  double max_discharge_c_rate;           ///< highest discharge C-rate fitted, 1/h
  std::string notes;                     ///< what the model ignores, in a sentence
};

/// The conditions of a study, constant over it.
struct OperatingConditions {
  double temperature_k = 298.15;  ///< cell temperature, K
  std::string chemistry;          ///< of the studied pack, e.g. "LiPo"; empty: not checked

  /// Throws ceilplan::InputError for a temperature over 150 C (that reads like kelvin given as
  /// Celsius) or below absolute zero.
  static OperatingConditions fromCelsius(double temperature_c);
  /// Throws ceilplan::InputError unless 0 < temperature_k is finite.
  void validate() const;
};

/// Highest C-rates seen in a history, as multiples of the nominal capacity per hour.
struct ObservedCRates {
  double charge = 0.0;     ///< highest charge C-rate, 1/h
  double discharge = 0.0;  ///< highest discharge C-rate, 1/h
};

/// A battery-ageing model fed an SOC history (docs/ageing.md); makeAgeingModel builds one by name.
class AgeingModel {
 public:
  virtual ~AgeingModel() = default;

  /// A short lower-case identifier: "fec", "xu", "schmalstieg", "woehler".
  virtual std::string name() const = 0;
  virtual ValidityRange validity() const = 0;  ///< Where the model was fitted (chemistries, temperatures, C-rates).

  /// Feeds the next samples, continuing the history (the interval from the previous piece's last
  /// sample counts too). Throws ceilplan::InputError, before using any sample of the piece, on a
  /// non-finite value, an SOC outside [0, 1], a state of health outside (0, 1] or time going
  /// backwards.
  void addSamples(const AgeingSample* samples, std::size_t count);
  /// The same, for a whole vector of samples.
  void addSamples(const std::vector<AgeingSample>& samples);

  /// Fraction of nominal capacity lost so far (0 new, 0.2 at the usual end of life), at most 1
  /// (a law extrapolated past a dead cell). Ranges the rainflow count still holds open count as
  /// half cycles; feeding may go on afterwards.
  double capacityLoss() const;

  /// A copy of the model with its history so far, to be fed on independently.
  virtual std::unique_ptr<AgeingModel> clone() const = 0;

  /// The model's measure of cycle ageing alone, additive over cycles, so cases compare by their
  /// ratio: FEC (against the nominal capacity) for "fec", Miner damage for "woehler", f_c for
  /// "xu", the sqrt(Q) capacity term for "schmalstieg". Open rainflow ranges count as half cycles.
  virtual double cycleWear() const = 0;
  /// What cycleWear() measures, for reports ("FEC", "Miner damage", ...).
  virtual std::string cycleWearName() const = 0;

  /// Samples fed so far.
  std::size_t samplesSeen() const { return samples_seen_; }
  /// Largest charging and discharging currents seen, in amperes (both >= 0).
  double peakChargeCurrentA() const { return peak_charge_current_a_; }
  /// Largest discharging current seen, A (>= 0).
  double peakDischargeCurrentA() const { return peak_discharge_current_a_; }
  /// The peak currents as C-rates of a pack of `nominal_capacity_ah`.
  ObservedCRates observedCRates(double nominal_capacity_ah) const;

 protected:
  AgeingModel() = default;
  AgeingModel(const AgeingModel&) = default;             ///< Copies the history, for clone().
  AgeingModel& operator=(const AgeingModel&) = default;  ///< Copies the history, for clone().

  /// Receives validated samples; `previous` is the sample before samples[0], or nullptr at the
  /// start of the history.
  virtual void consume(const AgeingSample* previous, const AgeingSample* samples, std::size_t count) = 0;
  /// The model's law, unclamped.
  virtual double modelCapacityLoss() const = 0;

 private:
  void validate(const AgeingSample* samples, std::size_t count) const;

  AgeingSample last_{};
  std::size_t samples_seen_ = 0;
  double peak_charge_current_a_ = 0.0;
  double peak_discharge_current_a_ = 0.0;
};

/// Human-readable warnings, one per way the study leaves the model's validity range; empty when
/// it stays inside.
std::vector<std::string> validityWarnings(const std::string& model_name, const ValidityRange& range,
                                          const OperatingConditions& conditions, const ObservedCRates& observed);
/// Same, with the C-rates the model has seen.
std::vector<std::string> validityWarnings(const AgeingModel& model, const OperatingConditions& conditions,
                                          double nominal_capacity_ah);

}  // namespace ceilplan::battery
