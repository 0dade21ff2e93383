#include "ceilplan/mission/landing_confidence.hpp"

#include "ceilplan/core/error.hpp"

#include <Eigen/Dense>
#include <boost/math/distributions/normal.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace ceilplan::mission {
namespace {

constexpr double kSecondsPerHour = 3600.0;

double current(const energy::EnergyModel& model, const planner::PathSample& sample, double climb_m_s) {
  energy::FlightCondition flight;
  flight.ground_gap_m = sample.ground_gap_m;
  flight.speed_m_s = sample.speed_m_s;
  flight.climb_m_s = climb_m_s;
  flight.soc = std::clamp(sample.soc, 0.0, 1.0);
  // The sample keeps the nearest rotor's ceiling gap only: taken over every disc.
  return model.currentA(sample.ceiling_gap_m, std::isfinite(sample.ceiling_gap_m) ? 1.0 : 0.0, flight);
}

// Vertical speed from sample k to the next, 0 where no time passes.
double climbAfter(const std::vector<planner::PathSample>& samples, std::size_t k) {
  if (k + 1 >= samples.size()) return 0.0;
  const double dt_s = samples[k + 1].t_s - samples[k].t_s;
  return dt_s > 0.0 ? (samples[k + 1].position_m.z() - samples[k].position_m.z()) / dt_s : 0.0;
}

double stepS(const std::vector<planner::PathSample>& samples, std::size_t k) {
  return k + 1 < samples.size() ? std::max(0.0, samples[k + 1].t_s - samples[k].t_s) : 0.0;
}

double standardNormalQuantile(double p) { return boost::math::quantile(boost::math::normal(), p); }

}  // namespace

ChargeSensitivity& ChargeSensitivity::operator+=(const ChargeSensitivity& other) {
  if (per_parameter_ah.empty()) per_parameter_ah.assign(other.per_parameter_ah.size(), 0.0);
  for (std::size_t j = 0; j < other.per_parameter_ah.size(); ++j) per_parameter_ah[j] += other.per_parameter_ah[j];
  flight_s += other.flight_s;
  return *this;
}

double chargeVarianceAh2(const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit) {
  double variance_ah2 = 0.0;
  const std::size_t p = std::min(sensitivity.per_parameter_ah.size(), fit.covariance.size());
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = 0; b < p; ++b)
      variance_ah2 += sensitivity.per_parameter_ah[a] * fit.covariance[a][b] * sensitivity.per_parameter_ah[b];
  const double residual_ah = fit.residual_std_a * sensitivity.flight_s / kSecondsPerHour;
  return std::max(0.0, variance_ah2) + residual_ah * residual_ah;
}

LandingOdds landingOdds(double landing_soc, const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit,
                        double usable_capacity_ah, double reserve_soc) {
  LandingOdds odds;
  odds.soc_std = std::sqrt(chargeVarianceAh2(sensitivity, fit)) / usable_capacity_ah;
  if (odds.soc_std <= 0.0) {
    odds.p_land_above_reserve = landing_soc >= reserve_soc ? 1.0 : 0.0;
    odds.soc_p01 = landing_soc;
    return odds;
  }
  const boost::math::normal landing(landing_soc, odds.soc_std);
  odds.p_land_above_reserve = boost::math::cdf(boost::math::complement(landing, reserve_soc));
  odds.soc_p01 = boost::math::quantile(landing, 0.01);
  return odds;
}

double effectiveReserveSoc(double reserve_soc, double confidence, const ChargeSensitivity& sensitivity,
                           const energy::FitUncertainty& fit, double usable_capacity_ah) {
  return reserve_soc +
         standardNormalQuantile(confidence) * std::sqrt(chargeVarianceAh2(sensitivity, fit)) / usable_capacity_ah;
}

std::vector<double> relativeCurrentSensitivity(const energy::EnergyModel& model, const planner::PathSample& sample,
                                               double climb_m_s, const energy::FitUncertainty& fit) {
  const double base_a = current(model, sample, climb_m_s);
  std::vector<double> relative(fit.parameters.size(), 0.0);
  if (base_a <= 0.0) return relative;
  for (std::size_t j = 0; j < fit.parameters.size(); ++j) {
    const double value = energy::parameterValue(model.parameters(), fit.parameters[j]);
    const double step = energy::kCovarianceRelativeStep * std::fabs(value);
    const energy::EnergyModel up(energy::withParameter(model.parameters(), fit.parameters[j], value + step));
    const energy::EnergyModel down(energy::withParameter(model.parameters(), fit.parameters[j], value - step));
    relative[j] = (current(up, sample, climb_m_s) - current(down, sample, climb_m_s)) / (2.0 * step) / base_a;
  }
  return relative;
}

ChargeSensitivity pathChargeSensitivity(const energy::EnergyModel& model,
                                        const std::vector<planner::PathSample>& samples,
                                        const energy::FitUncertainty& fit) {
  ChargeSensitivity sensitivity;
  sensitivity.per_parameter_ah.assign(fit.parameters.size(), 0.0);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double dt_s = stepS(samples, k);
    if (dt_s <= 0.0) continue;
    const std::vector<double> relative = relativeCurrentSensitivity(model, samples[k], climbAfter(samples, k), fit);
    for (std::size_t j = 0; j < relative.size(); ++j)
      sensitivity.per_parameter_ah[j] += samples[k].current_a * relative[j] * dt_s / kSecondsPerHour;
    sensitivity.flight_s += dt_s;
  }
  return sensitivity;
}

ChargeSensitivity steadyChargeSensitivity(const energy::EnergyModel& model, const planner::PathSample& condition,
                                          double charge_ah, double duration_s, const energy::FitUncertainty& fit) {
  ChargeSensitivity sensitivity;
  sensitivity.per_parameter_ah = relativeCurrentSensitivity(model, condition, 0.0, fit);
  for (double& s : sensitivity.per_parameter_ah) s *= charge_ah;
  sensitivity.flight_s = duration_s;
  return sensitivity;
}

double SampledLanding::standardError() const {
  return draws > 0 ? std::sqrt(p_land_above_reserve * (1.0 - p_land_above_reserve) / draws) : 0.0;
}

SampledLanding sampleLanding(const energy::EnergyModel& model, const std::vector<planner::PathSample>& samples,
                             double landing_soc, double usable_capacity_ah, double reserve_soc,
                             const energy::FitUncertainty& fit, int draws, std::uint32_t seed) {
  if (draws < 1) throw InputError("a sampled landing check needs at least one draw");
  SampledLanding result;
  result.draws = draws;
  result.seed = seed;
  const std::size_t p = fit.parameters.size();
  // Draws theta = fitted + L z with L L^T = C; C may be semidefinite, so L from its eigenvectors.
  Eigen::MatrixXd root = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
  if (p > 0) {
    Eigen::MatrixXd c(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
    for (std::size_t a = 0; a < p; ++a)
      for (std::size_t b = 0; b < p; ++b)
        c(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = fit.covariance[a][b];
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(c);
    root = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  }
  std::vector<double> base_a(samples.size()), climb_m_s(samples.size()), step_s(samples.size());
  double flight_s = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    climb_m_s[k] = climbAfter(samples, k);
    step_s[k] = stepS(samples, k);
    base_a[k] = step_s[k] > 0.0 ? current(model, samples[k], climb_m_s[k]) : 0.0;
    flight_s += step_s[k];
  }
  std::mt19937 random(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> landings;
  landings.reserve(static_cast<std::size_t>(draws));
  int above = 0;
  int rejected = 0;
  while (static_cast<int>(landings.size()) < draws) {
    Eigen::VectorXd z(static_cast<Eigen::Index>(p));
    for (Eigen::Index j = 0; j < z.size(); ++j) z[j] = normal(random);
    const double bias_a = fit.residual_std_a * normal(random);
    const Eigen::VectorXd delta = root * z;
    energy::EnergyParameters drawn = model.parameters();
    for (std::size_t j = 0; j < p; ++j)
      drawn =
          energy::withParameter(drawn, fit.parameters[j],
                                energy::parameterValue(drawn, fit.parameters[j]) + delta[static_cast<Eigen::Index>(j)]);
    double extra_ah = bias_a * flight_s / kSecondsPerHour;
    try {
      const energy::EnergyModel perturbed(drawn);
      for (std::size_t k = 0; k < samples.size(); ++k)
        if (step_s[k] > 0.0 && base_a[k] > 0.0)
          extra_ah += samples[k].current_a * (current(perturbed, samples[k], climb_m_s[k]) / base_a[k] - 1.0) *
                      step_s[k] / kSecondsPerHour;
    } catch (const InputError&) {
      // A draw outside the model's valid range (e.g. efficiency above 1) is drawn again.
      if (++rejected > 10 * draws)
        throw Error(
            "the calibration's covariance puts most parameter draws outside the model's valid range; "
            "calibrate on more data");
      continue;
    }
    const double soc = landing_soc - extra_ah / usable_capacity_ah;
    landings.push_back(soc);
    if (soc >= reserve_soc) ++above;
  }
  result.p_land_above_reserve = static_cast<double>(above) / draws;
  std::sort(landings.begin(), landings.end());
  result.soc_p01 = landings[static_cast<std::size_t>(std::floor(0.01 * (draws - 1)))];
  return result;
}

}  // namespace ceilplan::mission
