#include "ceilplan/planner/flight_cost_model.hpp"
#include "ceilplan/core/error.hpp"
#include "ceilplan/core/format.hpp"
#include "ceilplan/planner/standoff.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace ceilplan::planner {
namespace {

// The default integration step is never finer than this.
constexpr double kFinestDefaultStepM = 0.05;

void requireAtLeast(double value, double minimum, const char* name) {
  if (!(std::isfinite(value) && value >= minimum && value > 0.0))
    throw ceilplan::InputError(std::string("speeds: ") + name + " must be a finite number " +
                               (minimum > 0.0 ? ">= " + formatNumber(minimum) : std::string("> 0")) + ", got " +
                               formatNumber(value));
}

// The clearance of the body centre the standoff asks for (0: no standoff).
double keptClearance_m(const CostModelOptions& options, double airframe_radius_m) {
  return options.standoff_m == 0.0 ? 0.0 : options.standoff_m + airframe_radius_m;
}

}  // namespace

void FlightSpeeds::validate(double max_speed_m_s) const {
  requireAtLeast(cruise_m_s, kMinSpeed_m_s, "cruise_m_s");
  requireAtLeast(near_ceiling_m_s, kMinSpeed_m_s, "near_ceiling_m_s");
  requireAtLeast(near_ceiling_gap_radii, 0.0, "near_ceiling_gap_radii");
  requireAtLeast(climb_m_s, kMinSpeed_m_s, "climb_m_s");
  requireAtLeast(descent_m_s, kMinSpeed_m_s, "descent_m_s");
  requireAtLeast(inspection_m_s, kMinSpeed_m_s, "inspection_m_s");
  if (cruise_m_s > max_speed_m_s || near_ceiling_m_s > max_speed_m_s || inspection_m_s > max_speed_m_s)
    throw ceilplan::InputError("speeds: horizontal speeds must not exceed the vehicle's max_speed_m_s (" +
                               formatNumber(max_speed_m_s) + " m/s)");
  // Vertical rates as a mission file allows them (io/): a multirotor climbs far slower than it cruises.
  const double vertical_max_m_s = std::min(kMaxVerticalSpeed_m_s, max_speed_m_s);
  if (climb_m_s > vertical_max_m_s || descent_m_s > vertical_max_m_s)
    throw ceilplan::InputError("speeds: climb_m_s " + formatNumber(climb_m_s) + " and descent_m_s " +
                               formatNumber(descent_m_s) + " must not exceed " + formatNumber(vertical_max_m_s) +
                               " m/s");
  if (near_ceiling_gap_radii > kMaxNearCeilingGapRadii)
    throw ceilplan::InputError(
        "speeds: near_ceiling_gap_radii must be at most " + formatNumber(kMaxNearCeilingGapRadii) +
        " rotor radii (the ceiling effect has faded by 2.5), got " + formatNumber(near_ceiling_gap_radii));
}

void checkAirspeedLimit(const energy::Wind& wind, const FlightSpeeds& speeds, double max_speed_m_s) {
  wind.validate();
  const double fastest_m_s = std::max({speeds.cruise_m_s, speeds.near_ceiling_m_s, speeds.inspection_m_s});
  if (wind.speed_m_s + fastest_m_s > max_speed_m_s)
    throw ceilplan::InputError("wind: speed_m_s " + formatNumber(wind.speed_m_s) + " plus the fastest speed " +
                               formatNumber(fastest_m_s) + " m/s exceeds the vehicle's max_speed_m_s (" +
                               formatNumber(max_speed_m_s) +
                               " m/s), the fastest airspeed the energy model answers for: fly slower or in less wind");
}

FlightCostModel::FlightCostModel(const environment::Environment& environment, const energy::EnergyModel& energy,
                                 CostModelOptions options)
    : environment_(environment), energy_(energy), options_(options) {
  options_.speeds.validate(energy_.maxSpeedM_s());
  checkAirspeedLimit(options_.wind, options_.speeds, energy_.maxSpeedM_s());
  air_velocity_m_s_ = options_.wind.airVelocityM_s();
  if (!(options_.planning_soc > 0.0 && options_.planning_soc <= 1.0))
    throw ceilplan::InputError("planning SOC must lie in (0, 1], got " + formatNumber(options_.planning_soc));
  if (!(std::isfinite(options_.step_m) && options_.step_m >= 0.0))
    throw ceilplan::InputError("integration step must be >= 0 (0: half a voxel)");
  if (!(std::isfinite(options_.standoff_m) && options_.standoff_m >= 0.0))
    throw ceilplan::InputError("standoff must be a finite number >= 0 m, got " + formatNumber(options_.standoff_m));
  if (!(std::isfinite(options_.standoff_weight) && options_.standoff_weight > 0.0))
    throw ceilplan::InputError("standoff weight must be a positive number, got " +
                               formatNumber(options_.standoff_weight));
  if (static_cast<int>(environment_.vehicle().rotor_positions_m.size()) != energy_.rotorCount())
    throw ceilplan::InputError("the vehicle geometry has " +
                               std::to_string(environment_.vehicle().rotor_positions_m.size()) +
                               " rotors but the energy model " + std::to_string(energy_.rotorCount()));
  if (options_.step_m > 0.0) {
    step_m_ = options_.step_m;
  } else {
    // Half a voxel, or as many half voxels as fit in kFinestDefaultStepM: the current varies
    // over a rotor disc (25 cm), so sampling a 2 cm map every centimetre only costs time.
    const double half_voxel = 0.5 * environment_.grid().frame().resolution_m();
    step_m_ = half_voxel * std::max(1.0, std::floor(kFinestDefaultStepM / half_voxel + 1e-9));
  }
  const environment::VehicleGeometry& vehicle = environment_.vehicle();
  near_ceiling_gap_m_ = options_.speeds.near_ceiling_gap_radii * vehicle.rotor_radius_m;
  // A surface matters to a rotor if it lies over (under) the disc within the environment's
  // reach of the rotor plane, or within the speed rule's gap: bound that region by a sphere.
  double disc_reach = 0.0;
  for (const Eigen::Vector2d& rotor : vehicle.rotor_positions_m)
    disc_reach = std::max(disc_reach, rotor.norm() + vehicle.rotor_radius_m);
  // With the proximity effects off only the speed rule's ceiling matters: a surface less than its
  // gap over the disc.
  const environment::EnvironmentOptions& reach = environment_.options();
  const double plane = vehicle.rotor_plane_height_m;
  double vertical = std::max(std::abs(plane), std::abs(plane + near_ceiling_gap_m_));
  if (options_.proximity_effects)
    vertical = std::max({vertical, plane + reach.ceiling_reach_radii * vehicle.rotor_radius_m,
                         reach.ground_reach_radii * vehicle.rotor_radius_m - plane});
  free_air_clearance_m_ = std::hypot(disc_reach, vertical) + environment_.grid().frame().resolution_m();
  // A ceiling in the speed rule's band over a disc (rotor plane to near_ceiling_gap_m_ above it)
  // lies within the band's half height and the disc's reach of the band's middle.
  speed_rule_probe_m_ = plane + 0.5 * near_ceiling_gap_m_;
  speed_rule_clearance_m_ =
      std::hypot(disc_reach, 0.5 * near_ceiling_gap_m_) + environment_.grid().frame().resolution_m();
  airframe_radius_m_ = airframeRadius_m(vehicle);
}

double FlightCostModel::standoffShortfall_m(const Eigen::Vector3d& body_m) const {
  return options_.standoff_m == 0.0 ? 0.0 : standoffShortfall_m(body_m, environment_.clearanceLowerBound_m(body_m));
}

double FlightCostModel::standoffShortfall_m(const Eigen::Vector3d& body_m, double clear_m) const {
  if (options_.standoff_m == 0.0) return 0.0;
  const double wanted_m = keptClearance_m(options_, airframe_radius_m_);
  if (clear_m >= wanted_m) return 0.0;
  return std::max(0.0, wanted_m - environment_.clearance_m(body_m));
}

PointConditions FlightCostModel::conditionsAt(const Eigen::Vector3d& body_m) const {
  const double clear_m = environment_.clearanceLowerBound_m(body_m);  // as farFromStructure
  if (clear_m > free_air_clearance_m_) return freeAirConditions(standoffShortfall_m(body_m, clear_m));
  return options_.proximity_effects ? exactConditionsAt(body_m) : speedRuleConditionsAt(body_m, clear_m);
}

PointConditions FlightCostModel::speedRuleConditionsAt(const Eigen::Vector3d& body_m, double clear_m) const {
  // Near the ground or a wall the band above the discs is mostly clear: one lookup says so,
  // instead of a column search under every disc.
  PointConditions conditions = freeAirConditions(standoffShortfall_m(body_m, clear_m));
  const Eigen::Vector3d probe_m = body_m + speed_rule_probe_m_ * Eigen::Vector3d::UnitZ();
  if (!environment_.contains(probe_m) || environment_.clearanceLowerBound_m(probe_m) <= speed_rule_clearance_m_)
    conditions.nearest_ceiling_gap_m = environment_.nearestCeilingGap_m(body_m);
  return conditions;
}

PointConditions FlightCostModel::freeAirConditions(double standoff_shortfall_m) const {
  PointConditions conditions;
  conditions.rotor_count = energy_.rotorCount();
  conditions.standoff_shortfall_m = standoff_shortfall_m;
  return conditions;
}

PointConditions surfaceConditions(const environment::SurfaceGaps& ceiling, const environment::SurfaceGaps& ground) {
  PointConditions conditions;
  conditions.rotor_count = static_cast<int>(std::min(ceiling.rotors.size(), conditions.rotors.size()));
  conditions.nearest_ceiling_gap_m = ceiling.nearest_gap_m;
  for (int r = 0; r < conditions.rotor_count; ++r) {
    const environment::RotorGap& rotor = ceiling.rotors[r];
    // Coverage 0 has an infinite mean gap: free air for that rotor.
    conditions.rotors[r] = rotor.coverage > 0.0 ? energy::RotorCeiling{rotor.mean_gap_m, rotor.coverage}
                                                : energy::RotorCeiling{energy::kNoSurface, 0.0};
  }
  conditions.ground_gap_m = ground.coverage > 0.0 ? ground.mean_gap_m : energy::kNoSurface;
  return conditions;
}

std::vector<PointConditions> FlightCostModel::conditionsAlong(const Eigen::Vector3d& from_m,
                                                              const Eigen::Vector3d& to_m) const {
  return sampleConditions(from_m, to_m, Lookups::NearStructure);
}

std::vector<PointConditions> FlightCostModel::exactConditionsAlong(const Eigen::Vector3d& from_m,
                                                                   const Eigen::Vector3d& to_m) const {
  return sampleConditions(from_m, to_m, Lookups::Every);
}

std::vector<PointConditions> FlightCostModel::sampleConditions(const Eigen::Vector3d& from_m,
                                                               const Eigen::Vector3d& to_m, Lookups lookups) const {
  const int intervals = intervalCount(from_m, to_m);
  std::vector<PointConditions> conditions;
  conditions.reserve(intervals + 1);
  std::vector<Eigen::Vector3d> near;  // the samples whose gaps are looked up, together
  std::vector<std::size_t> near_index;
  std::vector<double> near_clear_m;
  // clear_m is a lower bound on the sample's clearance, for free air and the standoff (or -inf
  // where neither asks). Clearance is 1-Lipschitz: a lookup's bound, less the way flown since,
  // still bounds the samples that follow (the way between samples rounded up). Traced, while that
  // stays beyond free_air_clearance_m_ they are in free air without a lookup of their own (their
  // exact conditions cost the same, as freeAirAlong's), and while it stays beyond the standoff
  // they keep it.
  const bool skip_free_air = lookups != Lookups::Every, traced = lookups == Lookups::NearStructureTraced;
  const double interval_m = (to_m - from_m).norm() / intervals * (1.0 + 1e-9) + 1e-12;
  double clear_m = -std::numeric_limits<double>::infinity();
  forEachSample(from_m, to_m, intervals, [&](const Eigen::Vector3d& point) {
    clear_m -= interval_m;
    const bool look_up = skip_free_air ? !traced || !(clear_m > free_air_clearance_m_) || !environment_.contains(point)
                                       : options_.standoff_m != 0.0;
    if (look_up) clear_m = environment_.clearanceLowerBound_m(point);  // outside the map: throws, as ever
    if (skip_free_air && clear_m > free_air_clearance_m_) {
      conditions.push_back(freeAirConditions(standoffShortfall_m(point, clear_m)));
    } else if (!options_.proximity_effects) {
      conditions.push_back(speedRuleConditionsAt(point, clear_m));
    } else {
      near.push_back(point);
      near_index.push_back(conditions.size());
      near_clear_m.push_back(clear_m);
      conditions.emplace_back();
    }
  });
  environment_.ceilingAndGroundAlong(near, [&](std::size_t k, const environment::Environment::CeilingAndGround& gaps) {
    PointConditions& at = conditions[near_index[k]];
    at = surfaceConditions(gaps.ceiling, gaps.ground);  // as exactConditionsAt
    at.standoff_shortfall_m = standoffShortfall_m(near[k], near_clear_m[k]);
  });
  return conditions;
}

std::optional<PointConditions> FlightCostModel::freeAirAlong(const Eigen::Vector3d& from_m,
                                                             const Eigen::Vector3d& to_m) const {
  // Clearance is 1-Lipschitz: every point of the motion is at least the midpoint's lower bound
  // less half the length from structure. Beyond free_air_clearance_m_ every sample's exact
  // conditions are free air's, and beyond the standoff its shortfall is 0, so one conditions
  // serves every sample, the same to the bit as looking each up.
  const Eigen::Vector3d middle_m = 0.5 * (from_m + to_m);
  if (!environment_.contains(from_m) || !environment_.contains(to_m)) return std::nullopt;
  const double clear_m = environment_.clearanceLowerBound_m(middle_m) - 0.5 * (to_m - from_m).norm();
  if (!(clear_m > free_air_clearance_m_ && clear_m >= keptClearance_m(options_, airframe_radius_m_)))
    return std::nullopt;
  return freeAirConditions(0.0);
}

template <typename IntegrateWith>
auto FlightCostModel::integrateMotion(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                      IntegrateWith&& integrate_with) const {
  if (const std::optional<PointConditions> air = freeAirAlong(from_m, to_m))
    return integrate_with([&](const Eigen::Vector3d&) -> const PointConditions& { return *air; });
  const std::vector<PointConditions> conditions = sampleConditions(from_m, to_m, Lookups::NearStructureTraced);
  std::size_t next = 0;  // the integration visits the samples in their order
  return integrate_with([&](const Eigen::Vector3d&) -> const PointConditions& { return conditions[next++]; });
}

std::pair<MotionTotals, MotionTotals> FlightCostModel::integrateBothWays(const Eigen::Vector3d& from_m,
                                                                         const Eigen::Vector3d& to_m) const {
  if ((to_m - from_m).norm() == 0.0) return {};
  return integrateMotion(from_m, to_m,
                         [&](const auto& conditions_at) { return integrateBothWays(from_m, to_m, conditions_at); });
}

PointConditions FlightCostModel::exactConditionsAt(const Eigen::Vector3d& body_m) const {
  PointConditions conditions;  // rotors and ground default to free air; the speed rule sees the ceiling
  if (options_.proximity_effects) {
    const environment::Environment::CeilingAndGround gaps = environment_.ceilingAndGround(body_m);
    conditions = surfaceConditions(gaps.ceiling, gaps.ground);
  } else {
    // Free air under every rotor: only the speed rule's nearest ceiling counts.
    conditions.rotor_count = static_cast<int>(environment_.vehicle().rotor_positions_m.size());
    conditions.nearest_ceiling_gap_m = environment_.nearestCeilingGap_m(body_m);
  }
  conditions.standoff_shortfall_m = standoffShortfall_m(body_m);
  return conditions;
}

Velocity FlightCostModel::velocityAt(const PointConditions& conditions, const Eigen::Vector3d& direction_m) const {
  const FlightSpeeds& speeds = options_.speeds;
  const double horizontal_limit = nearCeiling(conditions) ? speeds.near_ceiling_m_s : speeds.cruise_m_s;
  const double horizontal = direction_m.head<2>().norm();
  const double vertical = direction_m.z();
  double along = std::numeric_limits<double>::infinity();
  if (horizontal > 0.0) along = horizontal_limit / horizontal;
  if (vertical > 0.0) along = std::min(along, speeds.climb_m_s / vertical);
  if (vertical < 0.0) along = std::min(along, speeds.descent_m_s / -vertical);
  // Guard the energy model's speed limit against rounding at the horizontal extreme.
  Velocity velocity{along, std::min(along * horizontal, horizontal_limit), along * vertical, {}};
  if (!options_.wind.calm())
    velocity.wind = energy::relativeWind(
        airVelocityAt(conditions),
        horizontal > 0.0 ? Eigen::Vector2d(direction_m.head<2>() / horizontal) : Eigen::Vector2d::Zero());
  return velocity;
}

Velocity FlightCostModel::hoverAt(const PointConditions& conditions) const {
  Velocity velocity;
  if (!options_.wind.calm()) velocity.wind = energy::relativeWind(airVelocityAt(conditions), Eigen::Vector2d::Zero());
  return velocity;
}

Eigen::Vector2d FlightCostModel::airVelocityAt(const PointConditions& conditions) const {
  return windShareAt(conditions) * air_velocity_m_s_;
}

double FlightCostModel::windShareAt(const PointConditions& conditions) const {
  // "Under overhead structure": where the speed rule sees a ceiling, in both modes alike.
  return nearCeiling(conditions) ? 1.0 - options_.wind.sheltered_fraction : 1.0;
}

namespace {
energy::FlightCondition flightCondition(const PointConditions& conditions, const Velocity& velocity, double soc) {
  energy::FlightCondition flight;
  flight.ground_gap_m = conditions.ground_gap_m;
  flight.speed_m_s = velocity.horizontal_m_s;
  flight.climb_m_s = velocity.climb_m_s;
  flight.soc = soc;
  flight.headwind_m_s = velocity.wind.headwind_m_s;
  flight.crosswind_m_s = velocity.wind.crosswind_m_s;
  return flight;
}
}  // namespace

double FlightCostModel::currentA(const PointConditions& conditions, const Velocity& velocity, double soc) const {
  return energy_.currentA(conditions.rotors.data(), energy_.rotorCount(), flightCondition(conditions, velocity, soc));
}

energy::CurrentBreakdown FlightCostModel::breakdown(const PointConditions& conditions, const Velocity& velocity,
                                                    double soc) const {
  return energy_.breakdown(conditions.rotors.data(), energy_.rotorCount(), flightCondition(conditions, velocity, soc));
}

MotionTotals FlightCostModel::integrate(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
  if ((to_m - from_m).norm() == 0.0) return {};
  return integrateMotion(from_m, to_m,
                         [&](const auto& conditions_at) { return integrate(from_m, to_m, conditions_at); });
}

int FlightCostModel::intervalCount(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const {
  const double chebyshev = (to_m - from_m).cwiseAbs().maxCoeff();
  // The small tolerance keeps a lattice edge of exactly k steps at k intervals despite rounding.
  return std::max(1, static_cast<int>(std::ceil(chebyshev / step_m_ - 1e-9)));
}

double FlightCostModel::costPerMetre(const CostWeights& weights, double current_a, double speed_m_s) const {
  return weights.per_m + weights.per_s / speed_m_s + weights.per_ah * current_a / (3600.0 * speed_m_s);
}

double FlightCostModel::cruiseCostPerMetre(const CostWeights& weights) const {
  PointConditions free_air;
  free_air.rotor_count = energy_.rotorCount();
  const Velocity velocity = velocityAt(free_air, Eigen::Vector3d::UnitX());
  return costPerMetre(weights, currentA(free_air, velocity, options_.planning_soc), velocity.along_m_s);
}

double FlightCostModel::minCostPerMetreAt(const CostWeights& weights, double elevation_rad) const {
  PointConditions best;  // the most favourable conditions the energy model can see
  best.rotor_count = energy_.rotorCount();
  if (options_.proximity_effects) {
    for (int r = 0; r < best.rotor_count; ++r) best.rotors[r] = energy::RotorCeiling{0.0, 1.0};
    best.ground_gap_m = 0.5 * energy_.rotorRadiusM();  // the ground model clamps below 0.5 R
  }
  // In wind the cost depends on the heading too: every 5 degrees of it.
  const int headings = options_.wind.calm() ? 1 : 72;
  double minimum = std::numeric_limits<double>::infinity();
  for (const double gap : {0.0, energy::kNoSurface}) {  // both sides of the speed rule
    best.nearest_ceiling_gap_m = gap;
    for (int h = 0; h < headings; ++h) {
      const double heading = 2.0 * M_PI * h / headings;
      const Eigen::Vector3d direction(std::cos(elevation_rad) * std::cos(heading),
                                      std::cos(elevation_rad) * std::sin(heading), std::sin(elevation_rad));
      const Velocity velocity = velocityAt(best, direction);
      minimum =
          std::min(minimum, costPerMetre(weights, currentA(best, velocity, options_.planning_soc), velocity.along_m_s));
    }
  }
  return minimum;
}

std::vector<double> FlightCostModel::costFanElevations_rad() const {
  const FlightSpeeds& speeds = options_.speeds;
  // A dense fan of elevation angles plus the corners where the horizontal limit and the climb or
  // descent limit bind together (the fastest directions, where the minimum sits); in wind a
  // coarser fan, as each elevation weighs every heading.
  const int fan = options_.wind.calm() ? 3600 : 360;
  std::vector<double> elevations;
  for (int k = 0; k <= fan; ++k) elevations.push_back(-M_PI / 2 + M_PI * k / fan);
  for (const double horizontal : {speeds.cruise_m_s, speeds.near_ceiling_m_s}) {
    elevations.push_back(std::atan2(speeds.climb_m_s, horizontal));
    elevations.push_back(-std::atan2(speeds.descent_m_s, horizontal));
  }
  return elevations;
}

double FlightCostModel::minCostPerMetre(const CostWeights& weights) const {
  double minimum = std::numeric_limits<double>::infinity();
  for (const double elevation : costFanElevations_rad())
    minimum = std::min(minimum, minCostPerMetreAt(weights, elevation));
  // Between fan directions the cost per metre is smooth; 0.5 % (2 % for the wind's coarser fan)
  // covers what the fan can miss.
  return (options_.wind.calm() ? 0.995 : 0.98) * minimum;
}

}  // namespace ceilplan::planner
