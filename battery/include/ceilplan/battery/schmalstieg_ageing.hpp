#pragma once
/// @file
/// Schmalstieg et al. 2014, "A holistic aging model for Li(NiMnCo)O2 based 18650 lithium-ion
/// batteries", J. Power Sources 257: capacity C = 1 - a_cap t^0.75 - b_cap sqrt(Q) and
/// resistance R = 1 + a_res t^0.75 + b_res Q (as replicated in NREL BLAST-Lite; resistance
/// constants agree in BLAST-Lite and SimSES; docs/ageing.md).

#include "ceilplan/battery/cycle_ageing_model.hpp"
#include "ceilplan/core/error.hpp"

#include <functional>

namespace ceilplan::battery {

/// Open-circuit voltage of one cell, in volts, at a state of charge in [0, 1]. The caller owns
/// the table (the energy module's); this module embeds none.
using CellVoltageOfSoc = std::function<double(double soc)>;

/// Schmalstieg et al. (2014)'s fitted constants (docs/models.md, "Ageing models").
struct SchmalstiegParameters {
  /// Calendar capacity: a_cap = (a_cap_v V + a_cap_0) 1e6 exp(a_cap_t / T), per day^0.75.
  double a_cap_v = 7.543;
  double a_cap_0 = -23.75;     ///< a_cap's constant term
  double a_cap_t_k = -6976.0;  ///< a_cap's temperature constant a_cap_t, K
  /// Cycle capacity: b_cap = b_cap_v (Vrms - b_cap_v0)^2 + b_cap_0 + b_cap_dod DoD, per sqrt(Ah).
  double b_cap_v = 7.348e-3;
  double b_cap_v0 = 3.667;      ///< b_cap's voltage offset, V
  double b_cap_0 = 7.60e-4;     ///< b_cap's constant term
  double b_cap_dod = 4.081e-3;  ///< b_cap's depth-of-discharge coefficient
  /// Calendar resistance: a_res = (a_res_v V + a_res_0) 1e5 exp(a_res_t / T), per day^0.75.
  double a_res_v = 5.270;
  double a_res_0 = -16.32;     ///< a_res's constant term
  double a_res_t_k = -5986.0;  ///< a_res's temperature constant a_res_t, K
  /// Cycle resistance: b_res = b_res_v (Vrms - b_res_v0)^2 + b_res_0 + b_res_dod DoD, per Ah.
  double b_res_v = 2.153e-4;
  double b_res_v0 = 3.725;      ///< b_res's voltage offset, V
  double b_res_0 = -1.521e-5;   ///< b_res's constant term
  double b_res_dod = 2.798e-4;  ///< b_res's depth-of-discharge coefficient
  /// Q is the charge throughput of the fitted cell (Sanyo UR18650E; 2.15 Ah as in BLAST-Lite),
  /// counted in nominal capacities: a swing of the SOC by dSOC at state of health SOH passes
  /// dSOC * SOH * this many ampere-hours.
  double reference_cell_capacity_ah = 2.15;
};

/// a_cap(V, T), clamped at 0 below the voltage where the fit turns negative (3.149 V).
double schmalstiegCalendarCapacityRate(double cell_voltage_v, double temperature_k,
                                       const SchmalstiegParameters& parameters = {});
/// b_cap(Vrms, DoD).
double schmalstiegCycleCapacityRate(double rms_voltage_v, double depth, const SchmalstiegParameters& parameters = {});
/// a_res(V, T), clamped at 0 (below 3.097 V).
double schmalstiegCalendarResistanceRate(double cell_voltage_v, double temperature_k,
                                         const SchmalstiegParameters& parameters = {});
/// b_res(Vrms, DoD); slightly negative for shallow cycles near 3.725 V, as published.
double schmalstiegCycleResistanceRate(double rms_voltage_v, double depth, const SchmalstiegParameters& parameters = {});

/// Advances a power-law state x = rate * s^exponent by `step` of s at a new rate, from the
/// equivalent s at which the new rate gives the present state (BLAST-Lite's and SimSES's way of
/// chaining varying stress; exact for constant stress).
double advancePowerLawState(double state, double rate, double exponent, double step);

/// Streams the history: calendar terms per sample interval with the trapezoid-averaged rate at
/// the interval's cell voltages; cycle terms per rainflow cycle, Q = 2 n DoD SOH C_ref (the
/// charge moved, in nominal capacities; SOH of the swing reaching the cycle's later turning
/// point), Vrms the RMS cell voltage over the cycle's SOC swing (charge-weighted, Simpson's
/// rule). DoD and Vrms are the faded pack's own: they are the stress the cell sees.
class SchmalstiegAgeingModel : public CycleAgeingModel {
 public:
  /// Throws ceilplan::InputError if `cell_voltage_of_soc` is empty.
  SchmalstiegAgeingModel(const OperatingConditions& conditions, CellVoltageOfSoc cell_voltage_of_soc,
                         const SchmalstiegParameters& parameters = {});
  std::string name() const override { return "schmalstieg"; }
  ValidityRange validity() const override;
  std::unique_ptr<AgeingModel> clone() const override;

  /// Calendar capacity loss so far (fraction of nominal capacity).
  double calendarCapacityLoss() const { return calendar_capacity_loss_; }
  double cycleCapacityLoss() const;  ///< open ranges as half cycles
  double resistanceGrowth() const;   ///< R / R_new - 1, open ranges as half cycles
  /// Q so far, in ampere-hours of the fitted cell, open ranges as half cycles.
  double chargeThroughputAh() const;
  double cycleWear() const override { return cycleCapacityLoss(); }
  std::string cycleWearName() const override { return "cycle capacity loss"; }

  /// The cell voltage the model uses, checked: throws ceilplan::InputError on a value that is
  /// not finite or not between 0 and 5 V (a pack voltage given for a cell's).
  double cellVoltage(double soc) const;
  /// RMS cell voltage over an SOC swing of `depth` around `mean_soc`.
  double rmsCellVoltage(double mean_soc, double depth) const;

 private:
  struct CycleState {
    double capacity_loss = 0.0;
    double resistance_growth = 0.0;
    double throughput_ah = 0.0;
  };

  void addCycle(const RainflowCycle& cycle) override;
  void addInterval(const AgeingSample& from, const AgeingSample& to) override;
  double capacityLossWith(const std::vector<RainflowCycle>& open) const override;
  void advance(CycleState& state, const RainflowCycle& cycle) const;
  CycleState cycleStateWith(const std::vector<RainflowCycle>& open) const;

  OperatingConditions conditions_;
  CellVoltageOfSoc cell_voltage_of_soc_;
  SchmalstiegParameters parameters_;
  CycleState closed_cycles_;
  double calendar_capacity_loss_ = 0.0;
  double calendar_resistance_growth_ = 0.0;
  /// The rates at the last sample's SOC, reused as the next interval's start.
  double last_rates_soc_ = -1.0;
  double last_capacity_rate_ = 0.0;
  double last_resistance_rate_ = 0.0;
};

}  // namespace ceilplan::battery
