#pragma once
/// @file
/// Predicted battery current from ceiling gap(s), ground gap, horizontal speed, climb rate and SOC.

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/ceiling_effect.hpp"
#include "ceilplan/energy/energy_parameters.hpp"
#include "ceilplan/energy/ground_effect.hpp"
#include "ceilplan/energy/pack_electrics.hpp"
#include "ceilplan/energy/rotary_wing_power.hpp"

#include <cmath>
#include <limits>

namespace ceilplan::energy {

/// A gap with no surface: free air.
inline constexpr double kNoSurface = std::numeric_limits<double>::infinity();

/// What one rotor sees above it.
struct RotorCeiling {
  double gap_m = kNoSurface;  ///< rotor plane to ceiling, >= 0
  double coverage = 1.0;      ///< fraction of the rotor disc under the ceiling, 0..1
};

/// The flight state besides the ceiling: ground gap, speeds, wind and state of charge.
struct FlightCondition {
  double ground_gap_m = kNoSurface;  ///< rotor plane to ground, >= 0
  double speed_m_s = 0.0;            ///< horizontal ground speed, >= 0
  double climb_m_s = 0.0;            ///< vertical, positive up
  double soc = 0.65;                 ///< state of charge, 0..1
  double headwind_m_s = 0.0;         ///< wind along the track, positive against the motion (energy/wind.hpp)
  double crosswind_m_s = 0.0;        ///< wind across the track

  /// What the forward-flight power sees: |ground velocity - wind|, 0..max_speed_m_s. With no
  /// wind it is speed_m_s exactly.
  double airspeedM_s() const {
    const double along_m_s = speed_m_s + headwind_m_s;
    return crosswind_m_s == 0.0 ? std::abs(along_m_s) : std::hypot(along_m_s, crosswind_m_s);
  }
};

/// Powers are electrical, at the pack terminals; they add up to power_w.
struct CurrentBreakdown {
  double current_a = 0.0;             ///< total pack current
  double power_w = 0.0;               ///< terminal voltage x current
  double terminal_voltage_v = 0.0;    ///< at the pack terminals
  double induced_w = 0.0;             ///< induced power
  double profile_w = 0.0;             ///< blade profile power
  double parasitic_w = 0.0;           ///< parasitic (fuselage drag) power
  double climb_w = 0.0;               ///< negative in descent, floored
  double avionics_w = 0.0;            ///< constant avionics load
  double ceiling_factor = 1.0;        ///< thrust ratio T_ceiling / T_free, mean over rotors
  double ground_factor = 1.0;         ///< thrust ratio T_ground / T_free
  double induced_power_factor = 1.0;  ///< induced power / free-air induced power, both effects

  /// Electrical propulsion power: what the pack delivers to the motors whatever its state of
  /// charge (PackElectrics turns it into current at a given SOC).
  double propulsionW() const { return induced_w + profile_w + parasitic_w + climb_w; }
};

/// Immutable once built: every evaluation is const, allocation-free and safe to call from
/// many threads at once. Evaluations throw ceilplan::InputError on bad input (negative or
/// NaN gap, coverage outside [0, 1], an airspeed beyond the vehicle's limit, ...).
class EnergyModel {
 public:
  static constexpr int kMaxRotors = 16;  ///< the most rotors a vehicle may have

  /// Validates and precomputes; throws ceilplan::InputError naming the bad parameter.
  explicit EnergyModel(const EnergyParameters& parameters);

  /// Convenience: the same gap and coverage on every rotor.
  double currentA(double ceiling_gap_m, double coverage, const FlightCondition& flight) const;
  /// The same, with the current's parts.
  CurrentBreakdown breakdown(double ceiling_gap_m, double coverage, const FlightCondition& flight) const;

  /// Per rotor: `rotors` points at exactly rotorCount() entries.
  double currentA(const RotorCeiling* rotors, int rotor_count, const FlightCondition& flight) const;
  /// The same, with the current's parts.
  CurrentBreakdown breakdown(const RotorCeiling* rotors, int rotor_count, const FlightCondition& flight) const;

  /// The parameters it was built from.
  const EnergyParameters& parameters() const noexcept { return parameters_; }
  /// Rotors of the airframe.
  int rotorCount() const noexcept { return parameters_.airframe.rotor_count; }
  /// Rotor radius, m.
  double rotorRadiusM() const noexcept { return parameters_.airframe.rotor_radius_m; }
  /// Fastest horizontal airspeed the model answers for.
  double maxSpeedM_s() const noexcept { return parameters_.airframe.max_speed_m_s; }
  /// The ceiling effect's thrust ratio.
  const CeilingEffect& ceilingEffect() const noexcept { return ceiling_; }
  /// The ground effect's thrust ratio.
  const GroundEffect& groundEffect() const noexcept { return ground_; }
  const RotaryWingPower& rotaryWingPower() const noexcept { return rotor_power_; }  ///< shaft power
  /// The pack's electrics (Rint and open-circuit voltage).
  const PackElectrics& pack() const noexcept { return pack_; }

 private:
  void checkFlight(const FlightCondition& flight) const;
  CurrentBreakdown combine(double ceiling_factor, double induced_power_factor, double ground_factor,
                           const FlightCondition& flight) const;

  EnergyParameters parameters_;
  CeilingEffect ceiling_;
  GroundEffect ground_;
  RotaryWingPower rotor_power_;
  PackElectrics pack_;
  double inverse_efficiency_;
  double weight_n_;
};

}  // namespace ceilplan::energy
