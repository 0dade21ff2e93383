#pragma once
/// @file
/// How sure a sortie is to land above the reserve, given how well `calibrate` pinned the energy
/// model down (docs/models.md, "Landing confidence"): the landing SOC's variance linearised in
/// the fitted parameters plus the fit's residual current, and a Monte Carlo check of it.

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <cstdint>
#include <vector>

namespace ceilplan::mission {

/// How a stretch of flight's charge moves with the fitted parameters.
struct ChargeSensitivity {
  /// dQ / d(theta_j), Ah per unit of parameter j, in energy::FitUncertainty::parameters' order.
  std::vector<double> per_parameter_ah;
  double flight_s = 0.0;  ///< the time it covers: the residual term scales with it

  /// Adds another stretch (the sensitivities of consecutive stretches add).
  ChargeSensitivity& operator+=(const ChargeSensitivity& other);
};

/// The variance (Ah^2) of a stretch's charge: s^T C s from the parameters' covariance C, plus
/// (residual_std_a x flight_s / 3600)^2, the fit's residual current taken as a bias that lasts
/// the whole sortie (it does not average out: docs/models.md). A gust term, a function of the
/// charge's sensitivity to airspeed, adds here.
double chargeVarianceAh2(const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit);

/// The odds of one sortie's landing, the SOC taken as normal about the planned landing SOC.
struct LandingOdds {
  double soc_std = 0.0;               ///< standard deviation of the landing SOC
  double p_land_above_reserve = 1.0;  ///< P(landing SOC >= reserve)
  double soc_p01 = 0.0;               ///< the landing SOC's 1st percentile
};

/// The odds of landing at `landing_soc` (the plan's) with `sensitivity`, against `reserve_soc`;
/// `usable_capacity_ah` turns charge into SOC.
LandingOdds landingOdds(double landing_soc, const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit,
                        double usable_capacity_ah, double reserve_soc);

/// The SOC a sortie must land at, as planned, to land above `reserve_soc` with probability
/// `confidence`: reserve + z(confidence) x the landing SOC's standard deviation. The split's
/// feasibility test (sortie_plan.hpp) compares the planned landing SOC with it.
double effectiveReserveSoc(double reserve_soc, double confidence, const ChargeSensitivity& sensitivity,
                           const energy::FitUncertainty& fit, double usable_capacity_ah);

/// d(current)/d(theta_j) / current at one sample's flight condition (ceiling gap over the whole
/// disc when there is one, ground gap, speed, `climb_m_s`, SOC), by central differences of the
/// parameters' own relative step energy::kCovarianceRelativeStep.
std::vector<double> relativeCurrentSensitivity(const energy::EnergyModel& model, const planner::PathSample& sample,
                                               double climb_m_s, const energy::FitUncertainty& fit);

/// The sensitivity of a path's charge: each step's current times its relative sensitivity.
ChargeSensitivity pathChargeSensitivity(const energy::EnergyModel& model,
                                        const std::vector<planner::PathSample>& samples,
                                        const energy::FitUncertainty& fit);

/// The sensitivity of `charge_ah` drawn over `duration_s` at one condition (a hover, or a leg
/// whose samples were dropped, taken at its mean).
ChargeSensitivity steadyChargeSensitivity(const energy::EnergyModel& model, const planner::PathSample& condition,
                                          double charge_ah, double duration_s, const energy::FitUncertainty& fit);

/// A Monte Carlo check of landingOdds: `draws` parameter sets from N(fitted, covariance) and
/// residual biases from N(0, residual_std_a), seeded with `seed`, each flown over the recorded
/// samples with the model's own (nonlinear) response rather than the linearisation.
struct SampledLanding {
  int draws = 0;                      ///< parameter sets drawn
  std::uint32_t seed = 0;             ///< the draws' seed
  double p_land_above_reserve = 1.0;  ///< share of draws landing at or above the reserve
  double soc_p01 = 0.0;               ///< 1st percentile of the drawn landing SOCs
  /// The binomial standard error of p_land_above_reserve: sqrt(p (1 - p) / draws).
  double standardError() const;
};

/// Flies `samples` (a sortie's record: t_s, current_a, the flight condition) `draws` times.
/// `landing_soc` is the planned landing SOC, which the draws perturb.
SampledLanding sampleLanding(const energy::EnergyModel& model, const std::vector<planner::PathSample>& samples,
                             double landing_soc, double usable_capacity_ah, double reserve_soc,
                             const energy::FitUncertainty& fit, int draws, std::uint32_t seed);

}  // namespace ceilplan::mission
