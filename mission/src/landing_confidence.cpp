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

energy::FlightCondition flightCondition(const planner::PathSample& sample, double climb_m_s,
                                        const energy::RelativeWind& wind) {
  energy::FlightCondition flight;
  flight.ground_gap_m = sample.ground_gap_m;
  flight.speed_m_s = sample.speed_m_s;
  flight.climb_m_s = climb_m_s;
  flight.soc = std::clamp(sample.soc, 0.0, 1.0);
  flight.headwind_m_s = wind.headwind_m_s;
  flight.crosswind_m_s = wind.crosswind_m_s;
  return flight;
}

double current(const energy::EnergyModel& model, const planner::PathSample& sample,
               const energy::FlightCondition& flight) {
  // The sample keeps the nearest rotor's ceiling gap only: taken over every disc.
  return model.currentA(sample.ceiling_gap_m, std::isfinite(sample.ceiling_gap_m) ? 1.0 : 0.0, flight);
}

double current(const energy::EnergyModel& model, const planner::PathSample& sample, double climb_m_s,
               const energy::RelativeWind& wind) {
  return current(model, sample, flightCondition(sample, climb_m_s, wind));
}

// The air's velocity at a sample per m/s of the wind's speed: its direction, less any shelter.
Eigen::Vector2d airPerWindSpeed(const SortieWind& wind, const planner::PathSample& sample) {
  energy::Wind unit = wind.wind;
  unit.speed_m_s = 1.0;
  return (wind.share ? wind.share(sample) : 1.0) * unit.airVelocityM_s();
}

// The horizontal unit track from sample k to the next; zero when hovering or moving vertically.
Eigen::Vector2d trackAfter(const std::vector<planner::PathSample>& samples, std::size_t k) {
  if (k + 1 >= samples.size()) return Eigen::Vector2d::Zero();
  const Eigen::Vector2d step_m = (samples[k + 1].position_m - samples[k].position_m).head<2>();
  return step_m.norm() > 1e-9 ? Eigen::Vector2d(step_m.normalized()) : Eigen::Vector2d::Zero();
}

// Where a step flies and the wind it meets there, for the mean wind or a deviation of its speed.
struct StepWind {
  Eigen::Vector2d air_per_m_s = Eigen::Vector2d::Zero();
  Eigen::Vector2d track = Eigen::Vector2d::Zero();

  energy::RelativeWind at(double speed_m_s) const { return energy::relativeWind(speed_m_s * air_per_m_s, track); }
};

// Vertical speed from sample k to the next, 0 where no time passes.
double climbAfter(const std::vector<planner::PathSample>& samples, std::size_t k) {
  if (k + 1 >= samples.size()) return 0.0;
  const double dt_s = samples[k + 1].t_s - samples[k].t_s;
  return dt_s > 0.0 ? (samples[k + 1].position_m.z() - samples[k].position_m.z()) / dt_s : 0.0;
}

// `flight` with its airspeed brought down to the model's limit if a gust took it past (the
// model answers no further); its direction against the track kept.
energy::FlightCondition withinAirspeed(const energy::EnergyModel& model, energy::FlightCondition flight) {
  const double airspeed_m_s = flight.airspeedM_s();
  // A hair under the limit, so that rounding in airspeedM_s() does not take it past again.
  const double limit_m_s = model.maxSpeedM_s() * (1.0 - 1e-9);
  if (airspeed_m_s <= limit_m_s) return flight;
  const double scale = limit_m_s / airspeed_m_s;
  flight.headwind_m_s = (flight.speed_m_s + flight.headwind_m_s) * scale - flight.speed_m_s;
  flight.crosswind_m_s *= scale;
  return flight;
}

double stepS(const std::vector<planner::PathSample>& samples, std::size_t k) {
  return k + 1 < samples.size() ? std::max(0.0, samples[k + 1].t_s - samples[k].t_s) : 0.0;
}

double standardNormalQuantile(double p) { return boost::math::quantile(boost::math::normal(), p); }

// The current at a step with the wind's speed at `speed_m_s`, kept within the model's airspeed.
double currentInWind(const energy::EnergyModel& model, const planner::PathSample& sample, double climb_m_s,
                     const StepWind& step, double speed_m_s) {
  return current(model, sample, withinAirspeed(model, flightCondition(sample, climb_m_s, step.at(speed_m_s))));
}

// Adds to `gust_charge_ah` what `charge_ah`, drawn at `base_a` in the mean wind, draws beyond it in
// each gust: the model's relative change of current, so that it scales a recorded current too.
void addGustCharges(const energy::EnergyModel& model, const planner::PathSample& sample, double climb_m_s,
                    const StepWind& step, const energy::Wind& wind, double base_a, double charge_ah,
                    std::vector<double>& gust_charge_ah) {
  if (step.air_per_m_s.isZero() || base_a <= 0.0) return;
  for (int i = 0; i < kGustPoints; ++i)
    if (gustPointSigma(i) != 0.0)
      gust_charge_ah[static_cast<std::size_t>(i)] +=
          charge_ah *
          (currentInWind(model, sample, climb_m_s, step, wind.speed_m_s + gustPointSigma(i) * wind.gust_m_s) / base_a -
           1.0);
}

// The gust's standard normal x over +-4 in 320 steps, with trapezoid weights of its density
// that sum to 1: where landingProbability integrates.
struct GustGrid {
  static constexpr int kSteps = 320;
  std::vector<double> x, weight;

  GustGrid() {
    const double span = -gustPointSigma(0);
    double sum = 0.0;
    for (int k = 0; k <= kSteps; ++k) {
      x.push_back(-span + 2.0 * span * k / kSteps);
      weight.push_back(std::exp(-0.5 * x.back() * x.back()) * (k == 0 || k == kSteps ? 0.5 : 1.0));
      sum += weight.back();
    }
    for (double& w : weight) w /= sum;
  }

  static const GustGrid& instance() {
    static const GustGrid grid;
    return grid;
  }
};

// The gust's charge at standard normal x, linear between the gust points.
double gustChargeAh(const std::vector<double>& gust_charge_ah, double x) {
  const double step = gustPointSigma(1) - gustPointSigma(0);
  const double at = std::clamp((x - gustPointSigma(0)) / step, 0.0, static_cast<double>(kGustPoints - 1));
  const auto i = std::min(static_cast<std::size_t>(at), static_cast<std::size_t>(kGustPoints - 2));
  const double f = at - static_cast<double>(i);
  return (1.0 - f) * gust_charge_ah[i] + f * gust_charge_ah[i + 1];
}

// The landing SOC's shift below the planned one at each point of the gust grid.
std::vector<double> gustSocShifts(const ChargeSensitivity& sensitivity, double usable_capacity_ah) {
  const GustGrid& grid = GustGrid::instance();
  std::vector<double> shift(grid.x.size());
  for (std::size_t k = 0; k < shift.size(); ++k)
    shift[k] = gustChargeAh(sensitivity.gust_charge_ah, grid.x[k]) / usable_capacity_ah;
  return shift;
}

// P(landing SOC >= reserve): normal with `soc_std` about landing_soc less each shift, mixed.
double mixedProbability(double landing_soc, double soc_std, const std::vector<double>& shifts, double reserve_soc) {
  const GustGrid& grid = GustGrid::instance();
  double p = 0.0;
  for (std::size_t k = 0; k < shifts.size(); ++k) {
    const double margin = landing_soc - shifts[k] - reserve_soc;
    p += grid.weight[k] *
         (soc_std > 0.0 ? 0.5 * std::erfc(-margin / (soc_std * std::sqrt(2.0))) : (margin >= 0.0 ? 1.0 : 0.0));
  }
  return std::min(p, 1.0);
}

// The x where a decreasing `f` crosses `target` within [low, high], by bisection.
template <typename F>
double bisect(F f, double target, double low, double high) {
  for (int k = 0; k < 100 && high - low > 1e-12; ++k) {
    const double mid = 0.5 * (low + high);
    (f(mid) >= target ? low : high) = mid;
  }
  return 0.5 * (low + high);
}

// The gust's SOC shifts widened by 10 standard deviations either way: with a landing SOC x, the
// landings the mixture can give lie within x minus this span; the planned SOC whose odds reach a
// given level over a reserve r lies within r plus it.
std::pair<double, double> shiftSpan(double soc_std, const std::vector<double>& shifts) {
  const auto [least, most] = std::minmax_element(shifts.begin(), shifts.end());
  return {*least - 10.0 * soc_std - 1e-9, *most + 10.0 * soc_std + 1e-9};
}

// The model with each fitted parameter stepped up and down by its central difference's step:
// built once for a whole path, not again at every sample.
class ParameterSteps {
 public:
  ParameterSteps(const energy::EnergyModel& model, const energy::FitUncertainty& fit) {
    for (const energy::FreeParameter parameter : fit.parameters) {
      const double value = energy::parameterValue(model.parameters(), parameter);
      const double step = energy::kCovarianceRelativeStep * std::fabs(value);
      steps_.push_back(step);
      up_.emplace_back(energy::withParameter(model.parameters(), parameter, value + step));
      down_.emplace_back(energy::withParameter(model.parameters(), parameter, value - step));
    }
  }

  // d(current)/d(theta_j) / current at one sample, for each fitted parameter j, given the fitted
  // model's current there (`base_a`), which the caller needs too.
  std::vector<double> relativeSensitivity(const planner::PathSample& sample, double climb_m_s,
                                          const energy::RelativeWind& wind, double base_a) const {
    std::vector<double> relative(steps_.size(), 0.0);
    if (base_a <= 0.0) return relative;
    for (std::size_t j = 0; j < steps_.size(); ++j)
      relative[j] = (current(up_[j], sample, climb_m_s, wind) - current(down_[j], sample, climb_m_s, wind)) /
                    (2.0 * steps_[j]) / base_a;
    return relative;
  }

 private:
  std::vector<double> steps_;
  std::vector<energy::EnergyModel> up_, down_;
};

}  // namespace

ChargeSensitivity& ChargeSensitivity::add(const ChargeSensitivity& other, double factor) {
  if (per_parameter_ah.empty()) per_parameter_ah.assign(other.per_parameter_ah.size(), 0.0);
  for (std::size_t j = 0; j < other.per_parameter_ah.size(); ++j)
    per_parameter_ah[j] += factor * other.per_parameter_ah[j];
  flight_s += other.flight_s;
  if (!other.gust_charge_ah.empty()) {
    if (gust_charge_ah.empty()) gust_charge_ah.assign(other.gust_charge_ah.size(), 0.0);
    for (std::size_t i = 0; i < other.gust_charge_ah.size(); ++i) gust_charge_ah[i] += factor * other.gust_charge_ah[i];
  }
  return *this;
}

// The mean wind's gust point, in the middle.
constexpr int kMeanGustPoint = (kGustPoints - 1) / 2;

double gustPointSigma(int i) { return 0.5 * (i - kMeanGustPoint); }

double chargeVarianceAh2(const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit) {
  double variance_ah2 = 0.0;
  const std::size_t p = std::min(sensitivity.per_parameter_ah.size(), fit.covariance.size());
  for (std::size_t a = 0; a < p; ++a)
    for (std::size_t b = 0; b < p; ++b)
      variance_ah2 += sensitivity.per_parameter_ah[a] * fit.covariance[a][b] * sensitivity.per_parameter_ah[b];
  const double residual_ah = fit.residual_std_a * sensitivity.flight_s / kSecondsPerHour;
  return std::max(0.0, variance_ah2) + residual_ah * residual_ah;
}

double landingProbability(double landing_soc, const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit,
                          double usable_capacity_ah, double reserve_soc) {
  const double soc_std = std::sqrt(chargeVarianceAh2(sensitivity, fit)) / usable_capacity_ah;
  if (!sensitivity.gust_charge_ah.empty())
    return mixedProbability(landing_soc, soc_std, gustSocShifts(sensitivity, usable_capacity_ah), reserve_soc);
  if (soc_std <= 0.0) return landing_soc >= reserve_soc ? 1.0 : 0.0;
  return boost::math::cdf(boost::math::complement(boost::math::normal(landing_soc, soc_std), reserve_soc));
}

LandingOdds landingOdds(double landing_soc, const ChargeSensitivity& sensitivity, const energy::FitUncertainty& fit,
                        double usable_capacity_ah, double reserve_soc) {
  LandingOdds odds;
  odds.soc_std = std::sqrt(chargeVarianceAh2(sensitivity, fit)) / usable_capacity_ah;
  if (!sensitivity.gust_charge_ah.empty()) {
    const std::vector<double> shifts = gustSocShifts(sensitivity, usable_capacity_ah);
    const GustGrid& grid = GustGrid::instance();
    double mean = 0.0, square = 0.0;
    for (std::size_t k = 0; k < shifts.size(); ++k) {
      mean += grid.weight[k] * shifts[k];
      square += grid.weight[k] * shifts[k] * shifts[k];
    }
    const double normal_std = odds.soc_std;
    odds.soc_std = std::sqrt(normal_std * normal_std + std::max(0.0, square - mean * mean));
    odds.p_land_above_reserve = mixedProbability(landing_soc, normal_std, shifts, reserve_soc);
    const auto [least, most] = shiftSpan(normal_std, shifts);
    odds.soc_p01 = bisect([&](double soc) { return mixedProbability(landing_soc, normal_std, shifts, soc); }, 0.99,
                          landing_soc - most, landing_soc - least);
    return odds;
  }
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
  const double soc_std = std::sqrt(chargeVarianceAh2(sensitivity, fit)) / usable_capacity_ah;
  if (sensitivity.gust_charge_ah.empty()) return reserve_soc + standardNormalQuantile(confidence) * soc_std;
  // The mixture's odds of landing above the reserve rise with the planned landing SOC.
  const std::vector<double> shifts = gustSocShifts(sensitivity, usable_capacity_ah);
  const auto [least, most] = shiftSpan(soc_std, shifts);
  return bisect([&](double planned) { return -mixedProbability(planned, soc_std, shifts, reserve_soc); }, -confidence,
                reserve_soc + least, reserve_soc + most);
}

bool meetsConfidence(double landing_soc, double confidence, const ChargeSensitivity& sensitivity,
                     const energy::FitUncertainty& fit, double usable_capacity_ah, double reserve_soc) {
  if (sensitivity.gust_charge_ah.empty())
    return landing_soc >= effectiveReserveSoc(reserve_soc, confidence, sensitivity, fit, usable_capacity_ah) - 1e-12;
  return landingProbability(landing_soc, sensitivity, fit, usable_capacity_ah, reserve_soc) >= confidence - 1e-12;
}

std::vector<double> relativeCurrentSensitivity(const energy::EnergyModel& model, const planner::PathSample& sample,
                                               double climb_m_s, const energy::FitUncertainty& fit,
                                               const energy::RelativeWind& wind) {
  return ParameterSteps(model, fit)
      .relativeSensitivity(sample, climb_m_s, wind, current(model, sample, climb_m_s, wind));
}

ChargeSensitivity pathChargeSensitivity(const energy::EnergyModel& model,
                                        const std::vector<planner::PathSample>& samples,
                                        const energy::FitUncertainty& fit, const SortieWind& wind) {
  ChargeSensitivity sensitivity;
  sensitivity.per_parameter_ah.assign(fit.parameters.size(), 0.0);
  if (wind.wind.gust_m_s > 0.0) sensitivity.gust_charge_ah.assign(kGustPoints, 0.0);
  const ParameterSteps steps(model, fit);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const double dt_s = stepS(samples, k);
    if (dt_s <= 0.0) continue;
    const double climb_m_s = climbAfter(samples, k);
    const StepWind step{airPerWindSpeed(wind, samples[k]), trackAfter(samples, k)};
    const energy::RelativeWind mean = step.at(wind.wind.speed_m_s);
    const double base_a = current(model, samples[k], climb_m_s, mean);
    const std::vector<double> relative = steps.relativeSensitivity(samples[k], climb_m_s, mean, base_a);
    for (std::size_t j = 0; j < relative.size(); ++j)
      sensitivity.per_parameter_ah[j] += samples[k].current_a * relative[j] * dt_s / kSecondsPerHour;
    if (!sensitivity.gust_charge_ah.empty())
      addGustCharges(model, samples[k], climb_m_s, step, wind.wind, base_a,
                     samples[k].current_a * dt_s / kSecondsPerHour, sensitivity.gust_charge_ah);
    sensitivity.flight_s += dt_s;
  }
  return sensitivity;
}

ChargeSensitivity steadyChargeSensitivity(const energy::EnergyModel& model, const planner::PathSample& condition,
                                          double charge_ah, double duration_s, const energy::FitUncertainty& fit,
                                          const SortieWind& wind) {
  ChargeSensitivity sensitivity;
  const StepWind hover{airPerWindSpeed(wind, condition), Eigen::Vector2d::Zero()};
  const energy::RelativeWind mean = hover.at(wind.wind.speed_m_s);
  const double base_a = current(model, condition, 0.0, mean);
  sensitivity.per_parameter_ah = ParameterSteps(model, fit).relativeSensitivity(condition, 0.0, mean, base_a);
  for (double& s : sensitivity.per_parameter_ah) s *= charge_ah;
  sensitivity.flight_s = duration_s;
  if (wind.wind.gust_m_s > 0.0) {
    sensitivity.gust_charge_ah.assign(kGustPoints, 0.0);
    addGustCharges(model, condition, 0.0, hover, wind.wind, base_a, charge_ah, sensitivity.gust_charge_ah);
  }
  return sensitivity;
}

SortieWind SortieWind::of(const planner::FlightCostModel& model) {
  SortieWind wind;
  wind.wind = model.options().wind;
  wind.share = [&model](const planner::PathSample& sample) {
    planner::PointConditions conditions;
    conditions.nearest_ceiling_gap_m = sample.ceiling_gap_m;
    return model.windShareAt(conditions);
  };
  return wind;
}

double SampledLanding::standardError() const {
  return draws > 0 ? std::sqrt(p_land_above_reserve * (1.0 - p_land_above_reserve) / draws) : 0.0;
}

SampledLanding sampleLanding(const energy::EnergyModel& model, const std::vector<planner::PathSample>& samples,
                             double landing_soc, double usable_capacity_ah, double reserve_soc,
                             const energy::FitUncertainty& fit, int draws, std::uint32_t seed, const SortieWind& wind) {
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
  std::vector<StepWind> step_wind(samples.size());
  const double mean_wind_m_s = wind.wind.speed_m_s;
  double flight_s = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    climb_m_s[k] = climbAfter(samples, k);
    step_s[k] = stepS(samples, k);
    step_wind[k] = {airPerWindSpeed(wind, samples[k]), trackAfter(samples, k)};
    base_a[k] = step_s[k] > 0.0 ? current(model, samples[k], climb_m_s[k], step_wind[k].at(mean_wind_m_s)) : 0.0;
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
    // Drawn only with gusts, so that without them a seed's draws are what they always were.
    const double gust_m_s = wind.wind.gust_m_s > 0.0 ? wind.wind.gust_m_s * normal(random) : 0.0;
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
          extra_ah +=
              samples[k].current_a *
              (currentInWind(perturbed, samples[k], climb_m_s[k], step_wind[k], mean_wind_m_s + gust_m_s) / base_a[k] -
               1.0) *
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
