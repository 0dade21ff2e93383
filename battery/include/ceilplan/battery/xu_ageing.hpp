#pragma once
/// @file
/// Xu et al. 2018, "Modeling of Lithium-Ion Battery Degradation for Cell Life Assessment",
/// IEEE Trans. Smart Grid 9(2): cycle stress from rainflow depth, mean SOC and temperature, a
/// calendar term, and the capacity-loss law with its SEI phase (docs/ageing.md).

#include "ceilplan/battery/cycle_ageing_model.hpp"

namespace ceilplan::battery {

/// Constants as published (Xu et al. 2018), agreed by five open implementations of the model.
struct XuParameters {
  double k_d1 = 1.40e5;                ///< depth stress
  double k_d2 = -0.501;                ///< depth stress exponent
  double k_d3 = -1.23e5;               ///< depth stress offset
  double k_s = 1.04;                   ///< SOC stress
  double soc_ref = 0.5;                ///< reference SOC of the SOC stress
  double k_t_per_k = 0.0693;           ///< temperature stress, 1/K
  double t_ref_k = 298.15;             ///< reference temperature, K
  double k_calendar_per_s = 4.14e-10;  ///< calendar rate k_t, 1/s
  double a_sei = 0.0575;               ///< share of capacity lost in the fast SEI phase
  double b_sei = 121.0;                ///< rate of the fast SEI phase, per unit damage
};

/// S_d(d) = 1 / (k_d1 d^k_d2 + k_d3), depth clamped to [0, 1] (S_d is positive only below
/// d = 1.295); 0 at depth 0.
double xuDepthStress(double depth, const XuParameters& parameters = {});
/// S_s(s) = exp(k_s (s - s_ref)).
double xuSocStress(double soc, const XuParameters& parameters = {});
/// S_T(T) = exp(k_T (T - T_ref) T_ref / T), T in kelvin.
double xuTemperatureStress(double temperature_k, const XuParameters& parameters = {});
/// L = 1 - a_sei exp(-b_sei f_d) - (1 - a_sei) exp(-f_d): capacity lost at total damage f_d.
double xuCapacityLoss(double damage, const XuParameters& parameters = {});

/// f_c = sum n_i S_d(d_i) S_s(s_i) S_T(T) over rainflow cycles; f_t = k_t t S_s(s_avg) S_T(T) with
/// s_avg the time-averaged SOC over the history (trapezoid rule between samples).
class XuAgeingModel : public CycleAgeingModel {
 public:
  /// A Xu model at the study's `conditions` (temperature) with `parameters`.
  explicit XuAgeingModel(const OperatingConditions& conditions = {}, const XuParameters& parameters = {});
  std::string name() const override { return "xu"; }
  ValidityRange validity() const override;
  std::unique_ptr<AgeingModel> clone() const override;

  double cycleDamage() const;     ///< f_c, open ranges as half cycles
  double calendarDamage() const;  ///< f_t
  double cycleWear() const override { return cycleDamage(); }
  std::string cycleWearName() const override { return "cycle damage f_c"; }

 private:
  void addCycle(const RainflowCycle& cycle) override;
  void addInterval(const AgeingSample& from, const AgeingSample& to) override;
  double capacityLossWith(const std::vector<RainflowCycle>& open) const override;
  double cycleDamageWith(const std::vector<RainflowCycle>& open) const;
  double cycleStress(const RainflowCycle& cycle) const;

  XuParameters parameters_;
  double temperature_stress_;
  double closed_cycle_damage_ = 0.0;
  double elapsed_s_ = 0.0;
  double soc_time_integral_s_ = 0.0;  ///< integral of SOC over time
};

}  // namespace ceilplan::battery
