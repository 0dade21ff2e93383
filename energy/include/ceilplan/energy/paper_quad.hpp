#pragma once
/// @file
/// The default vehicle, anchored on the founding paper's measurement (Kocer et al. 2019,
/// arXiv 1812.11707): 9.5 A hovering in free air, 8.0 A close under a ceiling. How the anchors
/// fix the constants: docs/models.md, "The default vehicle".

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_parameters.hpp"

namespace ceilplan::energy {

inline constexpr double kPaperFreeAirCurrentA = 9.5;  ///< The founding paper's hover current in free air, A.
/// The founding paper's hover current within 10 cm of a ceiling, A.
inline constexpr double kPaperCeilingCurrentA = 8.0;
inline constexpr double kPaperCeilingGapM = 0.05;  ///< "within 10 cm": the middle of that range
/// About the middle of the paper's free-flight mission: 95 % -> 34.1 % SOC at constant current.
inline constexpr double kPaperReferenceSoc = 0.65;
/// Reach (AIAA J., doi 10.2514/1.J062568): "nearly 2x thrust at contact".
inline constexpr double kContactThrustRatio = 2.0;

/// The electrical propulsion power that makes the pack deliver `current_a` in free-air hover at
/// `soc`, with the pack and avionics of `parameters` (the inverse of the Rint step).
double hoverPowerForCurrentW(const EnergyParameters& parameters, double current_a, double soc);

/// K1 and K2 such that a fully covered hover at `gap_m` (no ground, at rest) draws exactly
/// `current_a` at `soc` and the thrust ratio at contact is `contact_thrust_ratio`. Both follow in
/// closed form from 1 - 1/kappa(z) = (R^2/K1) / (z + K2)^2 at z = gap and z = 0. Every other
/// parameter (hover power included) is taken from `parameters`. Throws ceilplan::InputError when
/// no such curve exists (the current is not below free air, or the gap is in or past the taper).
CeilingEffectParameters ceilingThroughAnchor(const EnergyParameters& parameters, double gap_m, double current_a,
                                             double soc, double contact_thrust_ratio);

/// The founding paper's quadrotor (maps/vehicles/quad.yaml): hover power solved for 9.5 A and
/// K1, K2 for 8.0 A at 5 cm, both at SOC 0.65, with the default [open] values elsewhere.
EnergyParameters paperQuadParameters();

}  // namespace ceilplan::energy
