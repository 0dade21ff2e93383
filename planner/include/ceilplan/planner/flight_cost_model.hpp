#pragma once
/// @file
/// What a straight motion through the map costs the vehicle: how fast it flies (speed rules),
/// how much current it draws on the way (energy model fed with the map's ceiling and ground
/// gaps), and so how long it takes and how much charge it takes out of the pack. Every planner
/// objective is a weighted sum of these totals; see docs/planner.md.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/wind.hpp"
#include "ceilplan/environment/environment.hpp"

#include <Eigen/Core>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace ceilplan::planner {

/// The speed rules (mission files' `speeds:` block, docs/missions.md).
struct FlightSpeeds {
  static constexpr double kMaxVerticalSpeed_m_s = 10.0;  ///< fastest climb or descent accepted
  /// Slower is hovering, not flying: times and charges of a route at 1e-300 m/s overflow.
  static constexpr double kMinSpeed_m_s = 0.01;
  static constexpr double kMaxNearCeilingGapRadii = 10.0;  ///< widest slow zone accepted, rotor radii

  double cruise_m_s = 2.0;        ///< horizontal, in free air
  double near_ceiling_m_s = 1.8;  ///< horizontal, when a rotor is closer than near_ceiling_gap_radii R to a ceiling
                                  /// (docs/planner.md: break-even)
  double near_ceiling_gap_radii =
      2.0;                      ///< where the ceiling effect has nearly faded (docs/models.md, "Ceiling effect")
  double climb_m_s = 1.0;       ///< vertical rate limits
  double descent_m_s = 0.8;     ///< vertical rate limit, descending
  double inspection_m_s = 0.5;  ///< near a target: between a coverage tour's photos, the autopilot files' hover speed

  /// Throws ceilplan::InputError naming the bad field (a speed under kMinSpeed_m_s, a non-positive
  /// slow zone, non-finite, a horizontal
  /// speed beyond `max_speed_m_s`, the energy model's limit, a vertical rate beyond
  /// kMaxVerticalSpeed_m_s or `max_speed_m_s`, or a slow zone beyond kMaxNearCeilingGapRadii).
  void validate(double max_speed_m_s) const;
};

/// Throws ceilplan::InputError when the wind's speed plus the fastest horizontal speed of `speeds`
/// exceeds `max_speed_m_s`, the energy model's limit: a motion into the wind would ask it for an
/// airspeed it does not answer for. Checked before planning (docs/energy.md, "Wind").
void checkAirspeedLimit(const energy::Wind& wind, const FlightSpeeds& speeds, double max_speed_m_s);

/// How a FlightCostModel predicts a motion's time and charge.
struct CostModelOptions {
  FlightSpeeds speeds;  ///< the speed rules
  /// SOC at which currents are predicted while planning (the final evaluation integrates it):
  /// the battery's start SOC by default, so planning currents never exceed the evaluated ones.
  double planning_soc = 0.95;
  /// false: "free" mode, currents predicted as in free air whatever the map says.
  bool proximity_effects = true;
  /// Samples a motion at most this far apart along every axis; 0: half the map resolution, or
  /// the largest multiple of it up to 5 cm (on maps finer than 0.1 m).
  double step_m = 0.0;
  /// Free mode's standoff preference (0: none): every metre flown with the airframe's bounding
  /// sphere closer than `standoff_m` to a structure (standoffAt, standoff.hpp) costs, per metre
  /// short, as much as `standoff_weight` metres of level cruise in free air. The conventional
  /// standoff where it fits, the largest that fits where it does not (docs/planner.md, "Free mode").
  double standoff_m = 0.0;
  double standoff_weight = 100.0;  ///< metres of level cruise each metre of standoff shortfall costs
  energy::Wind wind;               ///< the air the motions are flown in (calm: still air)
};

/// What the map says at one body position, as the energy model needs it.
struct PointConditions {
  /// each rotor's mean ceiling gap and coverage
  std::array<energy::RotorCeiling, energy::EnergyModel::kMaxRotors> rotors{};
  int rotor_count = 0;                                ///< rotors in use in `rotors`
  double ground_gap_m = energy::kNoSurface;           ///< area-weighted mean gap of the ground under the discs
  double nearest_ceiling_gap_m = energy::kNoSurface;  ///< rotor plane to the nearest ceiling, any rotor (speed rule)
  double standoff_shortfall_m = 0.0;  ///< how far the standoff preference is from kept here (0 without one)
};

/// The map's gaps at a body position as the energy model takes them: each rotor's mean gap and
/// coverage above (free air where nothing covers it), the area-weighted mean gap below, and the
/// nearest rotor-plane gap above. The one mapping from environment to energy model.
PointConditions surfaceConditions(const environment::SurfaceGaps& ceiling, const environment::SurfaceGaps& ground);

/// The vehicle's velocity along a motion direction at a point, and the wind it meets there.
struct Velocity {
  double along_m_s = 0.0;       ///< along the path
  double horizontal_m_s = 0.0;  ///< horizontal ground speed
  double climb_m_s = 0.0;       ///< positive up
  energy::RelativeWind wind;    ///< the wind against the horizontal track (none in still air)
};

/// What a motion costs: length, time, charge and standoff shortfall.
struct MotionTotals {
  double length_m = 0.0;      ///< length flown
  double duration_s = 0.0;    ///< time taken
  double charge_ah = 0.0;     ///< charge drawn
  double shortfall_m2 = 0.0;  ///< the standoff shortfall integrated along the motion

  /// Adds another motion's totals.
  MotionTotals& operator+=(const MotionTotals& other) {
    length_m += other.length_m;
    duration_s += other.duration_s;
    charge_ah += other.charge_ah;
    shortfall_m2 += other.shortfall_m2;
    return *this;
  }
};

/// An objective as a weighted sum of motion totals: cost = per_m L + per_s T + per_ah Q + per_m2 S.
struct CostWeights {
  double per_m = 0.0;             ///< cost per metre flown
  double per_s = 0.0;             ///< cost per second
  double per_ah = 0.0;            ///< cost per ampere-hour
  double per_shortfall_m2 = 0.0;  ///< the standoff preference (free mode), set by FlightObjective
  /// The cost of `totals` under these weights.
  double of(const MotionTotals& totals) const {
    return per_m * totals.length_m + per_s * totals.duration_s + per_ah * totals.charge_ah +
           per_shortfall_m2 * totals.shortfall_m2;
  }
};

/// Time and charge of motions through the map: the energy model fed the map's gaps under the speed rules. Read only;
/// safe to share between threads.
class FlightCostModel {
 public:
  /// Keeps references to `environment` and `energy`: both must outlive the model.
  /// Throws ceilplan::InputError on bad speeds or options.
  FlightCostModel(const environment::Environment& environment, const energy::EnergyModel& energy,
                  CostModelOptions options);

  /// The map it reads.
  const environment::Environment& environment() const { return environment_; }
  /// The current model it feeds.
  const energy::EnergyModel& energy() const { return energy_; }
  /// The options it was built with.
  const CostModelOptions& options() const { return options_; }
  /// Distance between samples along a motion, m.
  double step_m() const { return step_m_; }

  /// Gaps around a body position from the map (ceiling and ground discs); with proximity
  /// effects off, every rotor sees free air (the speed rule still sees the real ceiling). With a
  /// standoff preference, its shortfall there.
  /// Where no structure lies within reach of any rotor disc (the distance field's lower bound
  /// says so) the gap queries are skipped: free air, and nearest_ceiling_gap_m is +inf instead of
  /// a gap beyond the reach. Throws ceilplan::InputError outside the map.
  PointConditions conditionsAt(const Eigen::Vector3d& body_m) const;
  /// Whether conditionsAt answers without querying the map (no structure within reach).
  bool farFromStructure(const Eigen::Vector3d& body_m) const {
    return environment_.clearanceLowerBound_m(body_m) > free_air_clearance_m_;
  }
  /// Same, always querying the map, so nearest_ceiling_gap_m is exact (reports).
  PointConditions exactConditionsAt(const Eigen::Vector3d& body_m) const;

  /// Velocity along unit `direction_m` at a point: as fast as the horizontal speed rule and the
  /// climb or descent rate both allow.
  Velocity velocityAt(const PointConditions& conditions, const Eigen::Vector3d& direction_m) const;
  /// Hovering at a point: no ground speed, the local wind as headwind.
  Velocity hoverAt(const PointConditions& conditions) const;
  /// The air's horizontal velocity at a point, m/s: the wind, less its sheltered fraction where
  /// the speed rule sees a ceiling (nearCeiling).
  Eigen::Vector2d airVelocityAt(const PointConditions& conditions) const;
  /// The share of the wind's speed met at a point, in [0, 1]: 1 less the sheltered fraction where
  /// the speed rule sees a ceiling (nearCeiling), 1 elsewhere.
  double windShareAt(const PointConditions& conditions) const;

  /// Pack current at a point for a velocity and state of charge.
  double currentA(const PointConditions& conditions, const Velocity& velocity, double soc) const;
  /// Same, with the power terms (for reports).
  energy::CurrentBreakdown breakdown(const PointConditions& conditions, const Velocity& velocity, double soc) const;

  /// Whether the speed rule sees a ceiling close enough to slow down for.
  bool nearCeiling(const PointConditions& conditions) const {
    return conditions.nearest_ceiling_gap_m < near_ceiling_gap_m_;
  }

  /// Totals of the straight motion from `from_m` to `to_m` at the planning SOC: sampled at
  /// step_m() along every axis, trapezoid rule on 1/speed and current/speed.
  MotionTotals integrate(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  /// Same, with the conditions at each sample point given by `conditions_at(point)` (a cache).
  template <typename ConditionsAt>
  MotionTotals integrate(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                         ConditionsAt&& conditions_at) const;

  /// Both directions of one straight motion (first from -> to, second to -> from), querying the
  /// conditions once per sample: what a roadmap needs for its directed edges.
  template <typename ConditionsAt>
  std::pair<MotionTotals, MotionTotals> integrateBothWays(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                                          ConditionsAt&& conditions_at) const;
  /// The same with conditionsAt at every sample, the same to the bit; the samples near structure
  /// share their columns' gap lookups (Environment::ceilingAndGroundAlong).
  std::pair<MotionTotals, MotionTotals> integrateBothWays(const Eigen::Vector3d& from_m,
                                                          const Eigen::Vector3d& to_m) const;
  /// conditionsAt at each of the samples integrate() takes on the motion, from_m first.
  std::vector<PointConditions> conditionsAlong(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;
  /// exactConditionsAt at the same samples, the same to the bit: every sample's gaps looked up
  /// (the samples share their columns' lookups), for reports that give the ceiling gap everywhere.
  std::vector<PointConditions> exactConditionsAlong(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  /// Number of sample intervals integrate() uses for a motion: the axis-wise (Chebyshev) length
  /// over step_m(), so lattice motions (between voxel centres, whole voxels apart) sample a
  /// lattice of step_m() anchored at a voxel centre exactly.
  int intervalCount(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;

  /// The cheapest cost per metre under `weights` anywhere, in any direction: the current at
  /// contact with a full ceiling (gap 0, coverage 1 on every rotor, ground at 0.5 R) at the
  /// planning SOC, with every speed the rules allow. c_min x distance is an admissible cost-to-go.
  double minCostPerMetre(const CostWeights& weights) const;
  /// The cheapest cost per metre under `weights` of a motion at `elevation_rad` above the horizontal
  /// (-pi/2 straight down to pi/2 straight up), in any heading, under the most favourable
  /// conditions (as minCostPerMetre, without its margin): climbing costs more than descending.
  double minCostPerMetreAt(const CostWeights& weights, double elevation_rad) const;
  /// The elevations minCostPerMetre weighs, radians: a fan from straight down to straight up and
  /// the corners where the horizontal and vertical speed limits bind together.
  std::vector<double> costFanElevations_rad() const;
  /// The cost per metre of level cruise in free air under `weights`: the standoff preference's unit.
  double cruiseCostPerMetre(const CostWeights& weights) const;

 private:
  double costPerMetre(const CostWeights& weights, double current_a, double speed_m_s) const;
  /// Which samples of a motion look their conditions up.
  enum class Lookups {
    Every,          ///< exactConditionsAlong
    NearStructure,  ///< conditionsAlong: each sample unless farFromStructure holds there
    /// What integrate() reads: also none while an earlier lookup's bound, less the way flown
    /// since, keeps the samples in free air (conditions that cost the same as conditionsAt's).
    NearStructureTraced
  };
  std::vector<PointConditions> sampleConditions(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                                Lookups lookups) const;

  /// One direction's totals over the samples of a motion, by the trapezoid rule on 1/speed and
  /// current/speed; samples may come in either order.
  class Trapezoid {
   public:
    Trapezoid(const FlightCostModel& model, const Eigen::Vector3d& direction, double length_m, int intervals)
        : model_(model), direction_(direction), interval_m_(length_m / intervals) {
      totals_.length_m = length_m;
    }
    void add(const PointConditions& conditions) {
      // In free air, or under a flat ceiling, neighbouring samples see the same conditions and
      // so draw the same current: the energy model is asked once for them.
      if (!started_ || !sameConditions(conditions, previous_conditions_, model_.energy_.rotorCount())) {
        const Velocity velocity = model_.velocityAt(conditions, direction_);
        s_per_m_ = 1.0 / velocity.along_m_s;
        as_per_m_ = model_.currentA(conditions, velocity, model_.options_.planning_soc) * s_per_m_;
        previous_conditions_ = conditions;
      }
      const double s_per_m = s_per_m_, as_per_m = as_per_m_;
      if (started_) {
        totals_.duration_s += 0.5 * (previous_s_per_m_ + s_per_m) * interval_m_;
        totals_.charge_ah += 0.5 * (previous_as_per_m_ + as_per_m) * interval_m_ / 3600.0;
        totals_.shortfall_m2 += 0.5 * (previous_shortfall_m_ + conditions.standoff_shortfall_m) * interval_m_;
      }
      started_ = true;
      previous_s_per_m_ = s_per_m;
      previous_as_per_m_ = as_per_m;
      previous_shortfall_m_ = conditions.standoff_shortfall_m;
    }
    const MotionTotals& totals() const { return totals_; }

   private:
    // Whether the speed rule and the energy model see the same at both (standoff aside).
    static bool sameConditions(const PointConditions& a, const PointConditions& b, int rotor_count) {
      if (a.rotor_count != b.rotor_count || a.ground_gap_m != b.ground_gap_m ||
          a.nearest_ceiling_gap_m != b.nearest_ceiling_gap_m)
        return false;
      for (int r = 0; r < rotor_count; ++r)  // the rotors the energy model reads
        if (a.rotors[r].gap_m != b.rotors[r].gap_m || a.rotors[r].coverage != b.rotors[r].coverage) return false;
      return true;
    }

    const FlightCostModel& model_;
    Eigen::Vector3d direction_;
    double interval_m_;
    MotionTotals totals_;
    bool started_ = false;
    double previous_s_per_m_ = 0.0, previous_as_per_m_ = 0.0, previous_shortfall_m_ = 0.0;
    PointConditions previous_conditions_;  ///< those s_per_m_ and as_per_m_ were found for
    double s_per_m_ = 0.0, as_per_m_ = 0.0;
  };

  /// Visits the sample points of a motion in order, from_m first and to_m last.
  template <typename Visit>
  void forEachSample(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m, int intervals, Visit&& visit) const {
    const Eigen::Vector3d delta = to_m - from_m;
    for (int k = 0; k <= intervals; ++k)
      visit(k == intervals ? to_m : Eigen::Vector3d(from_m + delta * (double(k) / intervals)));
  }

  const environment::Environment& environment_;
  const energy::EnergyModel& energy_;
  CostModelOptions options_;
  double step_m_;
  /// How far the body at `body_m` lacks the standoff (0 without one).
  double standoffShortfall_m(const Eigen::Vector3d& body_m) const;
  /// The same where its clearance is known to be at least `clear_m`: looked up exactly only when
  /// that bound is within the standoff.
  double standoffShortfall_m(const Eigen::Vector3d& body_m, double clear_m) const;
  /// Free air's conditions when they hold at every sample of the motion, from one lookup.
  std::optional<PointConditions> freeAirAlong(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m) const;
  /// Free air under every rotor, with the standoff's shortfall: conditionsAt where
  /// farFromStructure holds.
  PointConditions freeAirConditions(double standoff_shortfall_m) const;
  /// conditionsAt near structure with the proximity effects off, the body's clearance at least
  /// `clear_m`: the speed rule's ceiling only, its columns searched unless one lookup above the
  /// rotor planes finds none within its gap.
  PointConditions speedRuleConditionsAt(const Eigen::Vector3d& body_m, double clear_m) const;
  /// `integrate_with(conditions_at)` over a motion's samples: free air's conditions from one
  /// lookup where freeAirAlong holds, else each sample's (Lookups::NearStructureTraced).
  template <typename IntegrateWith>
  auto integrateMotion(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                       IntegrateWith&& integrate_with) const;

  double near_ceiling_gap_m_;
  double free_air_clearance_m_;       ///< beyond it from the body centre, no surface can affect a rotor
  double speed_rule_probe_m_;         ///< above the body centre, the middle of the speed rule's band over the discs
  double speed_rule_clearance_m_;     ///< beyond it from there, no ceiling lies in that band
  double airframe_radius_m_;          ///< the airframe's bounding sphere, which the standoff is kept from
  Eigen::Vector2d air_velocity_m_s_;  ///< the wind in free air
};

template <typename ConditionsAt>
MotionTotals FlightCostModel::integrate(const Eigen::Vector3d& from_m, const Eigen::Vector3d& to_m,
                                        ConditionsAt&& conditions_at) const {
  const double length_m = (to_m - from_m).norm();
  if (length_m == 0.0) return {};
  const int intervals = intervalCount(from_m, to_m);
  Trapezoid forward(*this, (to_m - from_m) / length_m, length_m, intervals);
  forEachSample(from_m, to_m, intervals, [&](const Eigen::Vector3d& point) { forward.add(conditions_at(point)); });
  return forward.totals();
}

template <typename ConditionsAt>
std::pair<MotionTotals, MotionTotals> FlightCostModel::integrateBothWays(const Eigen::Vector3d& from_m,
                                                                         const Eigen::Vector3d& to_m,
                                                                         ConditionsAt&& conditions_at) const {
  const double length_m = (to_m - from_m).norm();
  if (length_m == 0.0) return {};
  const int intervals = intervalCount(from_m, to_m);
  const Eigen::Vector3d direction = (to_m - from_m) / length_m;
  Trapezoid forward(*this, direction, length_m, intervals), backward(*this, -direction, length_m, intervals);
  forEachSample(from_m, to_m, intervals, [&](const Eigen::Vector3d& point) {
    const PointConditions& conditions = conditions_at(point);
    forward.add(conditions);
    backward.add(conditions);
  });
  return {forward.totals(), backward.totals()};
}

}  // namespace ceilplan::planner
