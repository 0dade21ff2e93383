#pragma once
/// @file
/// Every constant of the current model, in SI units. A value marked [open] is a calibration
/// parameter, not a published fact: its default and source are documented in docs/models.md.

namespace ceilplan::energy {

/// How a thrust ratio kappa = T_near / T_free turns into induced power at equal thrust
/// (docs/models.md, "From thrust ratio to power").
enum class ThrustToPowerConvention {
  kMomentumTheory,  ///< P_near / P_free = kappa^(-3/2): momentum theory at constant rotor speed
  kConstantPower,   ///< P_near / P_free = 1 / kappa: the Cheeseman-Bennett convention
};

/// Which form of the ground effect the model uses (docs/models.md).
enum class GroundEffectModel {
  kCheesemanBennett,  ///< single rotor, Cheeseman & Bennett 1955 (ARC R&M 3021)
  kMultirotor,        ///< Sanchez-Cuevas et al. 2017 multirotor form (Int. J. Aerospace Eng.)
};

/// The airframe: mass, rotors and their layout, top speed.
struct AirframeParameters {
  double mass_kg = 1.4;                                   ///< take-off mass
  int rotor_count = 4;                                    ///< rotors, at most EnergyModel::kMaxRotors
  double rotor_radius_m = 0.127;                          ///< rotor radius R
  double adjacent_rotor_spacing_m = 0.31819805153394637;  ///< d = sqrt(2) x 0.225 m arm: 450 mm X frame
  double opposite_rotor_spacing_m = 0.45;                 ///< b
  double max_speed_m_s = 15.0;                            ///< beyond it the model refuses to answer
};

/// Image-method ceiling effect T_ic/T_oc = 1 / (1 - (1/K1) (R / (z + K2))^2)
/// (Sanchez-Cuevas et al., ICUAS 2017), faded out between the taper radii (docs/models.md).
struct CeilingEffectParameters {
  double k1 = 0.0;                 ///< dimensionless [open]; the defaults are solved by paperQuadParameters()
  double k2_m = 0.0;               ///< metres [open]
  double taper_start_radii = 1.5;  ///< full image-method effect below this gap (in rotor radii)
  double taper_end_radii = 2.5;    ///< no effect from this gap on
};

/// The ground effect's form and its constants.
struct GroundEffectParameters {
  GroundEffectModel model = GroundEffectModel::kCheesemanBennett;  ///< which form
  double body_lift_factor = 2.0;  ///< K_b of the multirotor form, "about 2" (Sanchez-Cuevas et al. 2017)
  double min_gap_radii = 0.5;     ///< gaps below 0.5 R are clamped: both forms are singular near R/4 [open]
};

/// Rotor power: Zeng et al.'s rotary-wing model (IEEE T-WC 2019) scaled to hover power.
struct RotorPowerParameters {
  double hover_power_w = 0.0;             ///< electrical propulsion power, free-air hover [open]
  double motor_efficiency = 0.80;         ///< shaft power / electrical power (motor + ESC) [open]
  double induced_power_correction = 0.1;  ///< k in Pi = (1 + k) W^1.5 / sqrt(2 rho A), Zeng's example
  double tip_speed_m_s = 80.0;            ///< U_tip = Omega R at hover [open]
  double drag_area_m2 = 0.03;             ///< fuselage flat-plate area d0 s A [open]
  double air_density_kg_m3 = 1.225;       ///< ISA sea level, as in Zeng's example
  double descent_power_floor = 0.75;      ///< descent never takes propulsion power below this
                                          ///< fraction of level flight [open]
  /// how thrust ratios become induced power
  ThrustToPowerConvention convention = ThrustToPowerConvention::kMomentumTheory;
};

/// Rint pack (docs/models.md, "Pack electrics") plus a constant avionics load.
struct PackParameters {
  int cell_count = 4;               ///< 4S, the founding paper's pack
  double resistance_ohm = 0.020;    ///< 12-25 mOhm for a new 4S 5.2 Ah pack [open]
  double avionics_current_a = 0.5;  ///< flight controller, radio, sensors [open]
};

/// Every constant of the energy model (a vehicle file's `energy:` part; docs/energy.md).
struct EnergyParameters {
  AirframeParameters airframe;      ///< mass, rotors, top speed
  CeilingEffectParameters ceiling;  ///< ceiling effect
  GroundEffectParameters ground;    ///< ground effect
  RotorPowerParameters rotor;       ///< rotor power against speed
  PackParameters pack;              ///< pack electrics and avionics
  double reference_soc = 0.65;      ///< SOC at which the vehicle's currents are quoted; default --soc
};

inline constexpr double kStandardGravityM_s2 = 9.80665;  ///< Standard gravity g0, m/s^2.

}  // namespace ceilplan::energy
