#include "ceilplan/energy/paper_quad.hpp"
#include "ceilplan/core/format.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/energy_model.hpp"
#include "ceilplan/energy/thrust_to_power.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace ceilplan::energy {

double hoverPowerForCurrentW(const EnergyParameters& parameters, double current_a, double soc) {
  if (!(soc >= 0.0 && soc <= 1.0)) throw ceilplan::InputError("hover SOC must be in [0, 1]");
  const double power_w = PackElectrics(parameters.pack).propulsionPowerForCurrentW(current_a, soc);
  if (!(power_w > 0.0) || !std::isfinite(power_w))
    throw ceilplan::InputError("hover current " + formatNumber(current_a) +
                               " A leaves no propulsion power after the avionics current and pack losses");
  return power_w;
}

CeilingEffectParameters ceilingThroughAnchor(const EnergyParameters& parameters, double gap_m, double current_a,
                                             double soc, double contact_thrust_ratio) {
  const double radius_m = parameters.airframe.rotor_radius_m;
  CeilingEffectParameters result = parameters.ceiling;
  if (!(gap_m > 0.0 && gap_m < result.taper_start_radii * radius_m))
    throw ceilplan::InputError("ceiling anchor gap " + formatNumber(gap_m) +
                               " m must lie above 0 and below the taper start (" +
                               formatNumber(result.taper_start_radii * radius_m) + " m)");
  // The free-air model (its ceiling constants are not used on this path).
  EnergyParameters free_air = parameters;
  free_air.ceiling = {1.0, 10.0 * radius_m, result.taper_start_radii, result.taper_end_radii};
  const EnergyModel model(free_air);
  const double shaft_w =
      PackElectrics(parameters.pack).propulsionPowerForCurrentW(current_a, soc) * parameters.rotor.motor_efficiency;
  const RotaryWingPower& rotor = model.rotaryWingPower();
  const double induced_ratio = (shaft_w - rotor.hoverProfilePowerW()) / rotor.hoverInducedPowerW();
  if (!(induced_ratio > 0.0 && induced_ratio < 1.0))
    throw ceilplan::InputError("ceiling anchor current " + formatNumber(current_a) +
                               " A must lie between the free-air hover current and the profile-power floor");
  const double kappa = thrustRatioForInducedPowerRatio(induced_ratio, parameters.rotor.convention);
  const double excess_at_gap = 1.0 - 1.0 / kappa;
  const double excess_at_contact = 1.0 - 1.0 / contact_thrust_ratio;
  if (!(excess_at_contact > excess_at_gap))
    throw ceilplan::InputError("the contact thrust ratio " + formatNumber(contact_thrust_ratio) +
                               " must exceed the anchor's thrust ratio " + formatNumber(kappa));
  const double r = std::sqrt(excess_at_gap / excess_at_contact);  // = K2 / (gap + K2)
  result.k2_m = gap_m * r / (1.0 - r);
  result.k1 = radius_m * radius_m / (excess_at_contact * result.k2_m * result.k2_m);
  return result;
}

EnergyParameters paperQuadParameters() {
  EnergyParameters p;
  p.reference_soc = kPaperReferenceSoc;
  p.rotor.hover_power_w = hoverPowerForCurrentW(p, kPaperFreeAirCurrentA, kPaperReferenceSoc);
  p.ceiling =
      ceilingThroughAnchor(p, kPaperCeilingGapM, kPaperCeilingCurrentA, kPaperReferenceSoc, kContactThrustRatio);
  return p;
}

}  // namespace ceilplan::energy
