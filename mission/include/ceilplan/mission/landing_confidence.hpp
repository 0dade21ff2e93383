#pragma once
/// @file
/// How sure a sortie is to land above the reserve, given how well `calibrate` pinned the energy
/// model down and how gusty the wind is (docs/models.md, "Landing confidence"): the landing SOC's
/// variance linearised in the fitted parameters, plus the fit's residual current, mixed over the
/// charge each gust costs as the model flies it (not linearised), and a Monte Carlo check of it.

#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/wind.hpp"
#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/planner/path_evaluation.hpp"

#include <cstdint>
#include <functional>
#include <vector>

namespace ceilplan::mission {

/// The mission's wind as the landing confidence meets it along a sortie's samples.
struct SortieWind {
  energy::Wind wind;  ///< the mean wind (calm: still air) and gust_m_s, the gusts' standard deviation
  /// The share of the wind's speed met at a sample, in [0, 1] (less under shelter); empty: 1 everywhere.
  std::function<double(const planner::PathSample&)> share;

  /// `model`'s wind, sheltered where its speed rule sees a ceiling (FlightCostModel::windShareAt);
  /// it refers to `model`, which must outlive it.
  static SortieWind of(const planner::FlightCostModel& model);
};

/// How many gusts a stretch's charge is flown in: deviations of the wind's speed of
/// gustPointSigma(i) x gust_m_s, i = 0 .. kGustPoints - 1.
inline constexpr int kGustPoints = 17;

/// The i-th gust in standard deviations of the gusts: -4 to 4 in steps of 0.5 (0 is the mean wind).
double gustPointSigma(int i);

/// How a stretch of flight's charge moves with the fitted parameters and the wind's speed.
struct ChargeSensitivity {
  /// dQ / d(theta_j), Ah per unit of parameter j, in energy::FitUncertainty::parameters' order.
  std::vector<double> per_parameter_ah;
  double flight_s = 0.0;  ///< the time it covers: the residual term scales with it
  /// The charge the stretch draws beyond the mean wind's, Ah, when the wind's speed is off its
  /// mean by gustPointSigma(i) x gust_m_s for the whole stretch, flown with the model's own
  /// (nonlinear) response: kGustPoints values, or empty without gusts.
  std::vector<double> gust_charge_ah;

  /// Adds another stretch (the sensitivities of consecutive stretches add: a gust lasts the sortie).
  ChargeSensitivity& operator+=(const ChargeSensitivity& other) { return add(other, 1.0); }
  /// Adds another stretch whose charge, and so every term but its time, is `factor` times that
  /// its sensitivity was computed for (the same power at a lower SOC draws more current).
  ChargeSensitivity& add(const ChargeSensitivity& other, double factor);
};

/// The variance (Ah^2) of a stretch's charge at a given wind: s^T C s from the parameters'
/// covariance C, plus (residual_std_a x flight_s / 3600)^2, the fit's residual current taken as a
/// bias that lasts the whole sortie (it does not average out: docs/models.md). The gusts are not
/// in it: the landing SOC is this normal spread mixed over gust_charge_ah (landingProbability).
double chargeVarianceAh2(const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit);

/// The odds of one sortie's landing: without gusts the SOC is normal about the planned landing SOC
/// (standard deviation from chargeVarianceAh2); with them, that normal shifted by each gust's
/// charge and mixed over the gust's normal distribution (landingProbability).
struct LandingOdds {
  double soc_std = 0.0;               ///< standard deviation of the landing SOC, gusts included
  double p_land_above_reserve = 1.0;  ///< P(landing SOC >= reserve)
  double soc_p01 = 0.0;               ///< the landing SOC's 1st percentile
};

/// P(landing SOC >= `reserve_soc`) for a sortie planned to land at `landing_soc` with
/// `sensitivity`; `usable_capacity_ah` turns charge into SOC. With gust_charge_ah, the integral
/// over the gust (a standard normal x, the charge interpolated between the gust points, +-4
/// standard deviations in 320 steps) of the normal odds at landing_soc less that gust's charge.
double landingProbability(double landing_soc, const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit,
                          double usable_capacity_ah, double reserve_soc);

/// The odds of landing at `landing_soc` (the plan's) with `sensitivity`, against `reserve_soc`,
/// as landingProbability.
LandingOdds landingOdds(double landing_soc, const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit,
                        double usable_capacity_ah, double reserve_soc);

/// The SOC a sortie must land at, as planned, to land above `reserve_soc` with probability
/// `confidence`. Without gusts, reserve + z(confidence) x the landing SOC's standard deviation;
/// with them, where landingProbability is `confidence` (by bisection).
double effectiveReserveSoc(double reserve_soc, double confidence, const ChargeSensitivity& sensitivity,
                           const energy::FitUncertainty& fit, double usable_capacity_ah);

/// The split's feasibility test (sortie_plan.hpp): whether a sortie planned to land at
/// `landing_soc` lands above `reserve_soc` with at least `confidence`. The same answer as
/// comparing with effectiveReserveSoc, without its bisection where there are gusts.
bool meetsConfidence(double landing_soc, double confidence, const ChargeSensitivity& sensitivity,
                     const energy::FitUncertainty& fit, double usable_capacity_ah, double reserve_soc);

/// d(current)/d(theta_j) / current at one sample's flight condition (ceiling gap over the whole
/// disc when there is one, ground gap, speed, `climb_m_s`, SOC, the relative `wind` there), by
/// central differences of the parameters' own relative step energy::kCovarianceRelativeStep.
std::vector<double> relativeCurrentSensitivity(const energy::EnergyModel& model, const planner::PathSample& sample,
                                               double climb_m_s, const energy::FitUncertainty& fit,
                                               const energy::RelativeWind& wind = {});

/// The sensitivity of a path's charge: each step's current times its relative sensitivity, and,
/// with gusts, each step flown at every gust point (its own track and shelter; a gust past the
/// model's airspeed limit flies at the limit, as sampleLanding does).
ChargeSensitivity pathChargeSensitivity(const energy::EnergyModel& model,
                                        const std::vector<planner::PathSample>& samples,
                                        const energy::FitUncertainty& fit, const SortieWind& wind = {});

/// The sensitivity of `charge_ah` drawn over `duration_s` at one condition (a hover, or a leg
/// whose samples were dropped, taken at its mean), hovering in `wind` (its whole speed as headwind).
ChargeSensitivity steadyChargeSensitivity(const energy::EnergyModel& model, const planner::PathSample& condition,
                                          double charge_ah, double duration_s, const energy::FitUncertainty& fit,
                                          const SortieWind& wind = {});

/// A Monte Carlo check of landingOdds: `draws` parameter sets from N(fitted, covariance),
/// residual biases from N(0, residual_std_a) and, with gusts, wind-speed deviations from
/// N(0, gust_m_s), seeded with `seed`, each flown over the recorded samples with the model's own
/// (nonlinear) response rather than the linearisation.
struct SampledLanding {
  int draws = 0;                      ///< parameter sets drawn
  std::uint32_t seed = 0;             ///< the draws' seed
  double p_land_above_reserve = 1.0;  ///< share of draws landing at or above the reserve
  double soc_p01 = 0.0;               ///< 1st percentile of the drawn landing SOCs
  /// The binomial standard error of p_land_above_reserve: sqrt(p (1 - p) / draws).
  double standardError() const;
};

/// Flies `samples` (a sortie's record: t_s, current_a, the flight condition) `draws` times.
/// `landing_soc` is the planned landing SOC, which the draws perturb. Without gusts no wind
/// deviation is drawn: a seed draws the same parameters and biases as before gusts counted. A gust that would take a
/// step's airspeed past the model's limit flies that step at the limit (the model answers no further).
SampledLanding sampleLanding(const energy::EnergyModel& model, const std::vector<planner::PathSample>& samples,
                             double landing_soc, double usable_capacity_ah, double reserve_soc,
                             const energy::FitUncertainty& fit, int draws, std::uint32_t seed,
                             const SortieWind& wind = {});

}  // namespace ceilplan::mission
