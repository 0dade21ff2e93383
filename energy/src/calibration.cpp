#include "ceilplan/energy/calibration.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"

#include <Eigen/Dense>
#include <nlopt.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

namespace ceilplan::energy {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr FreeParameter kAllParameters[] = {FreeParameter::kHoverPowerW, FreeParameter::kK1,
                                            FreeParameter::kK2M,         FreeParameter::kMotorEfficiency,
                                            FreeParameter::kDragAreaM2,  FreeParameter::kPackResistanceOhm};
// Contact thrust ratio allowed during the fit: 1 / (1 - 0.95) = 20.
constexpr double kMaxContactExcess = 0.95;
// A parameter whose 100 % change moves the RMS current less than this is not in the data.
constexpr double kMinSensitivityA = 1e-6;
// Smallest singular value of the column-normalised Jacobian below which a direction is flat
// (two columns correlated beyond 1 - 5e-7).
constexpr double kMinSingularValue = 1e-3;

double& slot(EnergyParameters& p, FreeParameter parameter) {
  switch (parameter) {
    case FreeParameter::kHoverPowerW:
      return p.rotor.hover_power_w;
    case FreeParameter::kK1:
      return p.ceiling.k1;
    case FreeParameter::kK2M:
      return p.ceiling.k2_m;
    case FreeParameter::kMotorEfficiency:
      return p.rotor.motor_efficiency;
    case FreeParameter::kDragAreaM2:
      return p.rotor.drag_area_m2;
    case FreeParameter::kPackResistanceOhm:
      return p.pack.resistance_ohm;
  }
  throw std::logic_error("unknown calibration parameter");
}

double valueOf(const EnergyParameters& p, FreeParameter parameter) {
  EnergyParameters copy = p;
  return slot(copy, parameter);
}

struct Range {
  double lower;
  double upper;
};

Range allowedRange(FreeParameter parameter, const EnergyParameters& start) {
  switch (parameter) {
    case FreeParameter::kHoverPowerW:
      return {start.rotor.hover_power_w / 4.0, start.rotor.hover_power_w * 4.0};
    case FreeParameter::kK1:
      return {0.5, 500.0};
    case FreeParameter::kK2M:
      return {1e-3, 1.0};
    case FreeParameter::kMotorEfficiency:
      return {0.3, 1.0};
    case FreeParameter::kDragAreaM2:
      return {1e-4, 1.0};
    case FreeParameter::kPackResistanceOhm:
      return {1e-4, 0.5};
  }
  throw std::logic_error("unknown calibration parameter");
}

// Momentum-theory induced power Pi of the vehicle (shaft W), independent of every free parameter.
double momentumInducedPowerW(const EnergyParameters& p) {
  const double weight_n = p.airframe.mass_kg * kStandardGravityM_s2;
  const double area_m2 = p.airframe.rotor_count * kPi * p.airframe.rotor_radius_m * p.airframe.rotor_radius_m;
  return (1.0 + p.rotor.induced_power_correction) * std::pow(weight_n, 1.5) /
         std::sqrt(2.0 * p.rotor.air_density_kg_m3 * area_m2);
}

double evaluate(const EnergyModel& model, const CalibrationSample& s) {
  FlightCondition flight;
  flight.ground_gap_m = s.ground_gap_m;
  flight.speed_m_s = s.speed_m_s;
  flight.climb_m_s = s.climb_m_s;
  flight.soc = s.soc;
  return model.currentA(s.ceiling_gap_m, s.coverage, flight);
}

std::size_t distinctCount(const std::vector<CalibrationSample>& samples, double CalibrationSample::*column) {
  std::set<double> values;
  for (const auto& s : samples) values.insert(s.*column);
  return values.size();
}

bool hasCeilingWithinReach(const EnergyParameters& start, const std::vector<CalibrationSample>& samples) {
  const double reach_m = start.ceiling.taper_end_radii * start.airframe.rotor_radius_m;
  return std::any_of(samples.begin(), samples.end(),
                     [&](const CalibrationSample& s) { return s.ceiling_gap_m < reach_m && s.coverage > 0.0; });
}

// Why the data say nothing about `parameter`, or empty when its column is varied.
std::string missingVariation(FreeParameter parameter, const EnergyParameters& start,
                             const std::vector<CalibrationSample>& samples) {
  switch (parameter) {
    case FreeParameter::kHoverPowerW:
      return {};
    case FreeParameter::kK1:
    case FreeParameter::kK2M:
      if (!hasCeilingWithinReach(start, samples))
        return "no sample has a ceiling within " + formatNumber(start.ceiling.taper_end_radii) +
               " rotor radii (column gap_m absent or too far)";
      if (distinctCount(samples, &CalibrationSample::ceiling_gap_m) < 2) return "column gap_m is not varied";
      return {};
    case FreeParameter::kMotorEfficiency:
      if (distinctCount(samples, &CalibrationSample::climb_m_s) < 2)
        return "column climb_m_s is not varied, so efficiency cannot be told apart from hover power";
      return {};
    case FreeParameter::kDragAreaM2:
      if (distinctCount(samples, &CalibrationSample::speed_m_s) < 2) return "column speed_m_s is not varied";
      return {};
    case FreeParameter::kPackResistanceOhm:
      if (distinctCount(samples, &CalibrationSample::soc) < 2) return "column soc is not varied";
      return {};
  }
  return {};
}

bool isFree(const std::vector<FreeParameter>& free, FreeParameter parameter) {
  return std::find(free.begin(), free.end(), parameter) != free.end();
}

// The fit works on x in [0, 1]^n, each coordinate log-spaced over its range. Two coordinates
// are chosen so that no point of the box is an invalid model (NLopt's gradient methods may
// evaluate outside nonlinear constraints, never outside bounds):
// - k1 is fitted through the contact excess e0 = R^2 / (K1 K2^2) = 1 - 1/kappa(0), bounded so
//   that the thrust ratio at contact stays between 1.0001 and 20;
// - hover_power_w, when fitted with motor_efficiency, through the hover shaft power, bounded
//   below by the momentum-theory induced power (profile power P0 >= 0).
class Problem {
 public:
  Problem(const EnergyParameters& start, const std::vector<CalibrationSample>& samples,
          const std::vector<FreeParameter>& free)
      : start_(start),
        samples_(samples),
        free_(free),
        radius_squared_m2_(start.airframe.rotor_radius_m * start.airframe.rotor_radius_m),
        shaft_coordinate_(isFree(free, FreeParameter::kHoverPowerW) && isFree(free, FreeParameter::kMotorEfficiency)) {
    const double induced_w = momentumInducedPowerW(start) * 1.001;
    for (FreeParameter parameter : free_) {
      Range range = allowedRange(parameter, start);
      if (parameter == FreeParameter::kK1) range = {1e-4, kMaxContactExcess};
      if (parameter == FreeParameter::kHoverPowerW) {
        if (shaft_coordinate_)
          range = {induced_w, range.upper * start.rotor.motor_efficiency};
        else
          range.lower = std::max(range.lower, induced_w / start.rotor.motor_efficiency);
      }
      if (parameter == FreeParameter::kMotorEfficiency && !isFree(free, FreeParameter::kHoverPowerW))
        range.lower = std::max(range.lower, induced_w / start.rotor.hover_power_w);
      coordinate_ranges_.push_back(range);
      log_lower_.push_back(std::log(range.lower));
      log_span_.push_back(std::log(range.upper) - std::log(range.lower));
    }
  }

  std::size_t size() const { return free_.size(); }
  double logSpan(std::size_t j) const { return log_span_[j]; }

  // Start point of the fit, inside the box.
  std::vector<double> startX() const {
    std::vector<double> x(free_.size());
    for (std::size_t j = 0; j < free_.size(); ++j) {
      const Range& range = coordinate_ranges_[j];
      const double clamped = std::clamp(coordinate(start_, free_[j]), range.lower, range.upper);
      x[j] = (std::log(clamped) - log_lower_[j]) / log_span_[j];
    }
    return x;
  }

  EnergyParameters parametersAt(const std::vector<double>& x) const {
    EnergyParameters p = start_;
    for (std::size_t j = 0; j < free_.size(); ++j) slot(p, free_[j]) = std::exp(log_lower_[j] + x[j] * log_span_[j]);
    // Coordinates to parameters, after the parameters they depend on are in place.
    if (isFree(free_, FreeParameter::kK1))
      p.ceiling.k1 = radius_squared_m2_ / (p.ceiling.k1 * p.ceiling.k2_m * p.ceiling.k2_m);
    if (shaft_coordinate_) p.rotor.hover_power_w /= p.rotor.motor_efficiency;
    return p;
  }

  // The range parameter j was allowed, in its own units (at the fitted value of the others for
  // the two transformed coordinates).
  Range allowedParameterRange(std::size_t j, const EnergyParameters& fitted) const {
    const Range& range = coordinate_ranges_[j];
    if (free_[j] == FreeParameter::kK1) {
      const double k2_squared = fitted.ceiling.k2_m * fitted.ceiling.k2_m;
      return {radius_squared_m2_ / (range.upper * k2_squared), radius_squared_m2_ / (range.lower * k2_squared)};
    }
    if (free_[j] == FreeParameter::kHoverPowerW && shaft_coordinate_)
      return {range.lower / fitted.rotor.motor_efficiency, range.upper / fitted.rotor.motor_efficiency};
    return range;
  }

  Eigen::VectorXd residuals(const std::vector<double>& x) const {
    ++evaluations_;
    const EnergyModel model(parametersAt(x));
    Eigen::VectorXd r(samples_.size());
    for (std::size_t i = 0; i < samples_.size(); ++i) r[i] = evaluate(model, samples_[i]) - samples_[i].current_a;
    return r;
  }

  // Forward/central differences that stay inside [0, 1].
  Eigen::MatrixXd jacobian(const std::vector<double>& x) const {
    constexpr double kStep = 1e-7;
    Eigen::MatrixXd j(samples_.size(), free_.size());
    for (std::size_t c = 0; c < free_.size(); ++c) {
      std::vector<double> up = x;
      std::vector<double> down = x;
      up[c] = std::min(1.0, x[c] + kStep);
      down[c] = std::max(0.0, x[c] - kStep);
      j.col(static_cast<Eigen::Index>(c)) = (residuals(up) - residuals(down)) / (up[c] - down[c]);
    }
    return j;
  }

  int evaluations() const { return evaluations_; }

 private:
  double coordinate(const EnergyParameters& p, FreeParameter parameter) const {
    if (parameter == FreeParameter::kK1) return radius_squared_m2_ / (p.ceiling.k1 * p.ceiling.k2_m * p.ceiling.k2_m);
    if (parameter == FreeParameter::kHoverPowerW && shaft_coordinate_)
      return p.rotor.hover_power_w * p.rotor.motor_efficiency;
    return valueOf(p, parameter);
  }

  EnergyParameters start_;
  const std::vector<CalibrationSample>& samples_;
  std::vector<FreeParameter> free_;
  double radius_squared_m2_;
  bool shaft_coordinate_;
  std::vector<Range> coordinate_ranges_;
  std::vector<double> log_lower_;
  std::vector<double> log_span_;
  mutable int evaluations_ = 0;
};

double objective(const std::vector<double>& x, std::vector<double>& gradient, void* data) {
  const auto& problem = *static_cast<const Problem*>(data);
  const Eigen::VectorXd r = problem.residuals(x);
  if (!gradient.empty()) {
    const Eigen::VectorXd g = 2.0 * problem.jacobian(x).transpose() * r;
    std::copy(g.data(), g.data() + g.size(), gradient.begin());
  }
  return r.squaredNorm();
}

// Why NLopt gave up, in words a user can act on: NLopt itself only says "nlopt failure".
std::string fitFailure(const Problem& problem, const std::vector<double>& start_x,
                       const std::vector<CalibrationSample>& samples, const std::exception& e) {
  if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr)
    return "the least-squares fit ran out of memory with " + std::to_string(samples.size()) +
           " samples; fit a subset of the data";
  double largest_a = 0.0;
  for (const CalibrationSample& s : samples) largest_a = std::max(largest_a, s.current_a);
  const std::string head = "the least-squares fit failed: NLopt's L-BFGS gave up (" + std::string(e.what()) +
                           ") after " + std::to_string(problem.evaluations()) + " model evaluations";
  if (!std::isfinite(problem.residuals(start_x).squaredNorm()))
    return head + ", because the squared errors overflow: current_a reaches " + formatNumber(largest_a) +
           " A; give every current in amperes (a multirotor hovers at about 10 A) and remove the outlier";
  return head + "; the data may hold currents no setting of the model can approach (largest current_a " +
         formatNumber(largest_a) +
         " A: an outlier, or mA given as A?) or contradict each other: check the "
         "data, or fit fewer parameters with --fit";
}

// Whether x is a least-squares optimum by the relative offset criterion (Bates & Watts 1988,
// section 2.2.3): the residuals are orthogonal to the Jacobian's columns, |J^T r| <= 1e-4 |J| |r|.
// On noisy data L-BFGS's line search may give up there (a generic NLopt failure) with x at the
// optimum it cannot improve.
bool atLeastSquaresOptimum(const Problem& problem, const std::vector<double>& x) {
  const Eigen::VectorXd r = problem.residuals(x);
  const Eigen::MatrixXd j = problem.jacobian(x);
  const double scale = j.norm() * r.norm();
  return std::isfinite(scale) && scale > 0.0 && (j.transpose() * r).norm() <= 1e-4 * scale;
}

// Refuses when the Jacobian at the fit has a column of zeros or a (near) flat direction.
void checkIdentifiable(const Problem& problem, const std::vector<FreeParameter>& free, const Eigen::MatrixXd& j) {
  const double rows = static_cast<double>(j.rows());
  Eigen::MatrixXd normalised = j;
  for (Eigen::Index c = 0; c < j.cols(); ++c) {
    // RMS current change per 100 % change of the parameter (x is log-spaced over the range).
    const double sensitivity_a = j.col(c).norm() / std::sqrt(rows) / problem.logSpan(static_cast<std::size_t>(c));
    if (sensitivity_a < kMinSensitivityA)
      throw ceilplan::InputError("cannot identify " + parameterName(free[static_cast<std::size_t>(c)]) +
                                 ": the measured currents do not depend on it; fix it instead of fitting it");
    normalised.col(c) /= j.col(c).norm();
  }
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(normalised, Eigen::ComputeThinV);
  const Eigen::Index last = svd.singularValues().size() - 1;
  if (svd.singularValues()[last] >= kMinSingularValue) return;
  const Eigen::VectorXd direction = svd.matrixV().col(last).cwiseAbs();
  std::vector<Eigen::Index> order(static_cast<std::size_t>(direction.size()));
  for (Eigen::Index c = 0; c < direction.size(); ++c) order[static_cast<std::size_t>(c)] = c;
  std::sort(order.begin(), order.end(), [&](Eigen::Index a, Eigen::Index b) { return direction[a] > direction[b]; });
  std::string message = "cannot identify " + parameterName(free[static_cast<std::size_t>(order[0])]) +
                        ": the data leave it interchangeable with " +
                        parameterName(free[static_cast<std::size_t>(order[1])]) +
                        "; vary more columns in the measurements or fit fewer parameters (--fit)";
  throw ceilplan::InputError(message);
}

Eigen::VectorXd residualsFor(const EnergyParameters& p, const std::vector<CalibrationSample>& samples) {
  const EnergyModel model(p);
  Eigen::VectorXd r(static_cast<Eigen::Index>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
    r[static_cast<Eigen::Index>(i)] = evaluate(model, samples[i]) - samples[i].current_a;
  return r;
}

// Gauss-Newton covariance at the optimum (Bates & Watts 1988, section 2.3): the Jacobian in the
// parameters' own units, so that the covariance is the one a user reads against the values.
FitUncertainty fitUncertainty(const EnergyParameters& fitted, const std::vector<CalibrationSample>& samples,
                              const std::vector<FittedParameter>& parameters) {
  FitUncertainty u;
  const Eigen::VectorXd r = residualsFor(fitted, samples);
  const auto n = static_cast<double>(samples.size());
  const auto p = static_cast<double>(parameters.size());
  u.samples = static_cast<int>(samples.size());
  u.residual_rms_a = std::sqrt(r.squaredNorm() / n);
  u.residual_std_a = std::sqrt(r.squaredNorm() / (n - p));  // calibrate refuses n <= p
  for (const FittedParameter& f : parameters)
    if (f.atBound()) {
      u.unavailable = parameterName(f.parameter) + " ended at " +
                      (f.value <= f.lower * (1 + 1e-6) ? "the lower" : "the upper") + " end of its range (" +
                      formatNumber(f.value) +
                      "), where the fit's covariance does not describe its uncertainty; fix it instead of fitting it";
      return u;
    }
  Eigen::MatrixXd j(r.size(), static_cast<Eigen::Index>(parameters.size()));
  for (std::size_t c = 0; c < parameters.size(); ++c) {
    const FittedParameter& f = parameters[c];
    const double step = kCovarianceRelativeStep * std::fabs(f.value);
    j.col(static_cast<Eigen::Index>(c)) = (residualsFor(withParameter(fitted, f.parameter, f.value + step), samples) -
                                           residualsFor(withParameter(fitted, f.parameter, f.value - step), samples)) /
                                          (2.0 * step);
  }
  const Eigen::MatrixXd normal = j.transpose() * j;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(normal);
  if (!lu.isInvertible()) {
    u.unavailable = "the fit's J^T J is singular: the data do not separate the fitted parameters; fit fewer (--fit)";
    return u;
  }
  const Eigen::MatrixXd covariance = u.residual_std_a * u.residual_std_a * lu.inverse();
  for (std::size_t a = 0; a < parameters.size(); ++a) {
    u.parameters.push_back(parameters[a].parameter);
    const auto ia = static_cast<Eigen::Index>(a);
    u.standard_errors.push_back(std::sqrt(std::max(0.0, covariance(ia, ia))));
    u.covariance.emplace_back();
    for (std::size_t b = 0; b < parameters.size(); ++b)
      u.covariance.back().push_back(covariance(ia, static_cast<Eigen::Index>(b)));
  }
  return u;
}

}  // namespace

EnergyParameters withParameter(const EnergyParameters& parameters, FreeParameter parameter, double value) {
  EnergyParameters copy = parameters;
  slot(copy, parameter) = value;
  return copy;
}

double parameterValue(const EnergyParameters& parameters, FreeParameter parameter) {
  return valueOf(parameters, parameter);
}

std::string parameterName(FreeParameter parameter) {
  switch (parameter) {
    case FreeParameter::kHoverPowerW:
      return "hover_power_w";
    case FreeParameter::kK1:
      return "k1";
    case FreeParameter::kK2M:
      return "k2_m";
    case FreeParameter::kMotorEfficiency:
      return "motor_efficiency";
    case FreeParameter::kDragAreaM2:
      return "drag_area_m2";
    case FreeParameter::kPackResistanceOhm:
      return "pack_resistance_ohm";
  }
  throw std::logic_error("unknown calibration parameter");
}

FreeParameter parseFreeParameter(const std::string& name) {
  std::string known;
  for (FreeParameter parameter : kAllParameters) {
    if (parameterName(parameter) == name) return parameter;
    known += (known.empty() ? "" : ", ") + parameterName(parameter);
  }
  throw ceilplan::InputError("unknown calibration parameter '" + name + "'; known: " + known);
}

std::vector<FreeParameter> identifiableParameters(const EnergyParameters& start,
                                                  const std::vector<CalibrationSample>& samples) {
  std::vector<FreeParameter> free;
  for (FreeParameter parameter : kAllParameters) {
    if (parameter == FreeParameter::kPackResistanceOhm) continue;  // only on request: weakly identified
    if (missingVariation(parameter, start, samples).empty()) free.push_back(parameter);
  }
  return free;
}

CalibrationResult calibrate(const EnergyParameters& start, const std::vector<CalibrationSample>& samples,
                            const std::vector<FreeParameter>& free) {
  if (free.empty()) throw ceilplan::InputError("nothing to fit: name at least one parameter");
  for (std::size_t a = 0; a < free.size(); ++a)
    for (std::size_t b = a + 1; b < free.size(); ++b)
      if (free[a] == free[b]) throw ceilplan::InputError(parameterName(free[a]) + " is listed twice");
  if (samples.size() <= free.size())
    throw ceilplan::InputError(std::to_string(samples.size()) + " samples cannot identify " +
                               std::to_string(free.size()) + " parameters: give more samples than parameters");
  for (FreeParameter parameter : free) {
    const std::string why = missingVariation(parameter, start, samples);
    if (!why.empty()) throw ceilplan::InputError("cannot identify " + parameterName(parameter) + ": " + why);
  }
  {
    const EnergyModel start_model(start);  // every sample must be valid input to begin with
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!std::isfinite(samples[i].current_a) || samples[i].current_a < 0.0)
        throw ceilplan::InputError("sample " + std::to_string(i + 1) +
                                   ": current_a must be a finite, non-negative number");
      try {
        evaluate(start_model, samples[i]);
      } catch (const std::exception& e) {
        throw ceilplan::InputError("sample " + std::to_string(i + 1) + ": " + e.what());
      }
    }
  }

  Problem problem(start, samples, free);
  std::vector<double> x = problem.startX();

  nlopt::opt optimizer(nlopt::LD_LBFGS, static_cast<unsigned>(free.size()));
  optimizer.set_lower_bounds(0.0);
  optimizer.set_upper_bounds(1.0);
  optimizer.set_min_objective(objective, &problem);
  optimizer.set_xtol_rel(1e-12);
  optimizer.set_ftol_abs(1e-26);
  optimizer.set_maxeval(2000);
  double sum_of_squares = 0.0;
  try {
    optimizer.optimize(x, sum_of_squares);
  } catch (const nlopt::roundoff_limited&) {
    // Converged as far as floating point allows: x holds the best point found.
  } catch (const std::exception& e) {
    if (!atLeastSquaresOptimum(problem, x)) throw ceilplan::Error(fitFailure(problem, problem.startX(), samples, e));
  }

  checkIdentifiable(problem, free, problem.jacobian(x));

  CalibrationResult result;
  result.parameters = problem.parametersAt(x);
  const Eigen::VectorXd r = problem.residuals(x);
  result.rmse_a = std::sqrt(r.squaredNorm() / static_cast<double>(r.size()));
  result.max_abs_error_a = r.cwiseAbs().maxCoeff();
  for (std::size_t j = 0; j < free.size(); ++j) {
    const Range range = problem.allowedParameterRange(j, result.parameters);
    result.fitted.push_back(
        {free[j], slot(result.parameters, free[j]), range.lower, range.upper, valueOf(start, free[j])});
  }
  result.evaluations = problem.evaluations();
  result.uncertainty = fitUncertainty(result.parameters, samples, result.fitted);
  return result;
}

}  // namespace ceilplan::energy
