#include "ceilplan/energy/energy_model.hpp"

#include "ceilplan/core/error.hpp"
#include "ceilplan/energy/thrust_to_power.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace ceilplan::energy {
namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void refuse(const char* what, double value, const char* rule) {
  std::ostringstream message;
  message << what << ' ' << value << ' ' << rule;
  throw ceilplan::InputError(message.str());
}

const EnergyParameters& checked(const EnergyParameters& p) {
  const AirframeParameters& v = p.airframe;
  if (!(v.mass_kg > 0.0) || !std::isfinite(v.mass_kg)) refuse("vehicle mass_kg", v.mass_kg, "must be positive");
  if (v.rotor_count < 1 || v.rotor_count > EnergyModel::kMaxRotors)
    throw ceilplan::InputError("vehicle rotor count " + std::to_string(v.rotor_count) + " must be between 1 and " +
                               std::to_string(EnergyModel::kMaxRotors));
  if (!(v.rotor_radius_m > 0.0) || !std::isfinite(v.rotor_radius_m))
    refuse("rotor radius_m", v.rotor_radius_m, "must be positive");
  if (!(v.max_speed_m_s >= 0.0) || !std::isfinite(v.max_speed_m_s))
    refuse("max_speed_m_s", v.max_speed_m_s, "must be >= 0 and finite");
  const RotorPowerParameters& r = p.rotor;
  if (!(r.hover_power_w > 0.0) || !std::isfinite(r.hover_power_w))
    refuse("hover_power_w", r.hover_power_w, "must be positive");
  if (!(r.motor_efficiency > 0.0 && r.motor_efficiency <= 1.0))
    refuse("motor_efficiency", r.motor_efficiency, "must be in (0, 1]");
  if (!(r.induced_power_correction >= 0.0))
    refuse("induced_power_correction", r.induced_power_correction, "must be >= 0");
  if (!(r.drag_area_m2 >= 0.0) || !std::isfinite(r.drag_area_m2))
    refuse("drag_area_m2", r.drag_area_m2, "must be >= 0");
  if (!(r.air_density_kg_m3 > 0.0)) refuse("air_density_kg_m3", r.air_density_kg_m3, "must be positive");
  if (!(r.descent_power_floor > 0.0 && r.descent_power_floor <= 1.0))
    refuse("descent_power_floor", r.descent_power_floor, "must be in (0, 1]");
  if (!(p.reference_soc >= 0.0 && p.reference_soc <= 1.0))
    refuse("reference_soc", p.reference_soc, "must be in [0, 1]");
  return p;
}

void checkGap(const char* what, double gap_m) {
  if (std::isnan(gap_m)) refuse(what, gap_m, "is not a number");
  if (gap_m < 0.0) refuse(what, gap_m, "m is negative: gaps are measured from the rotor plane and are >= 0");
}

}  // namespace

EnergyModel::EnergyModel(const EnergyParameters& parameters)
    : parameters_(checked(parameters)),
      ceiling_(parameters.ceiling, parameters.airframe.rotor_radius_m),
      ground_(parameters.ground, parameters.airframe),
      rotor_power_(
          RotaryWingPower::scaledToHover(parameters.rotor.hover_power_w * parameters.rotor.motor_efficiency,
                                         parameters.airframe.mass_kg * kStandardGravityM_s2,
                                         parameters.airframe.rotor_count * kPi * parameters.airframe.rotor_radius_m *
                                             parameters.airframe.rotor_radius_m,
                                         parameters.rotor.induced_power_correction, parameters.rotor.tip_speed_m_s,
                                         parameters.rotor.drag_area_m2, parameters.rotor.air_density_kg_m3)),
      pack_(parameters.pack),
      inverse_efficiency_(1.0 / parameters.rotor.motor_efficiency),
      weight_n_(parameters.airframe.mass_kg * kStandardGravityM_s2) {}

void EnergyModel::checkFlight(const FlightCondition& flight) const {
  checkGap("ground gap", flight.ground_gap_m);
  if (!(flight.speed_m_s >= 0.0)) refuse("speed", flight.speed_m_s, "m/s must be >= 0");
  if (!std::isfinite(flight.headwind_m_s)) refuse("headwind", flight.headwind_m_s, "m/s must be finite");
  if (!std::isfinite(flight.crosswind_m_s)) refuse("crosswind", flight.crosswind_m_s, "m/s must be finite");
  const double airspeed_m_s = flight.airspeedM_s();
  if (airspeed_m_s > parameters_.airframe.max_speed_m_s) {
    std::ostringstream message;
    if (flight.headwind_m_s == 0.0 && flight.crosswind_m_s == 0.0)
      message << "speed " << flight.speed_m_s << " m/s";
    else
      message << "airspeed " << airspeed_m_s << " m/s (ground speed " << flight.speed_m_s << " m/s, headwind "
              << flight.headwind_m_s << " m/s, crosswind " << flight.crosswind_m_s << " m/s)";
    message << " is beyond the vehicle's max_speed_m_s (" << parameters_.airframe.max_speed_m_s << " m/s)";
    throw ceilplan::InputError(message.str());
  }
  if (!std::isfinite(flight.climb_m_s)) refuse("climb rate", flight.climb_m_s, "m/s must be finite");
  if (!(flight.soc >= 0.0 && flight.soc <= 1.0)) refuse("state of charge", flight.soc, "is outside [0, 1]");
}

double EnergyModel::currentA(double ceiling_gap_m, double coverage, const FlightCondition& flight) const {
  return breakdown(ceiling_gap_m, coverage, flight).current_a;
}

double EnergyModel::currentA(const RotorCeiling* rotors, int rotor_count, const FlightCondition& flight) const {
  return breakdown(rotors, rotor_count, flight).current_a;
}

CurrentBreakdown EnergyModel::breakdown(double ceiling_gap_m, double coverage, const FlightCondition& flight) const {
  checkGap("ceiling gap", ceiling_gap_m);
  if (!(coverage >= 0.0 && coverage <= 1.0)) refuse("ceiling coverage", coverage, "is outside [0, 1]");
  checkFlight(flight);
  const double ground_factor = ground_.thrustRatio(flight.ground_gap_m);
  const double ceiling_factor = ceiling_.thrustRatio(ceiling_gap_m, coverage);
  const double induced = inducedPowerRatio(ceiling_factor * ground_factor, parameters_.rotor.convention);
  return combine(ceiling_factor, induced, ground_factor, flight);
}

CurrentBreakdown EnergyModel::breakdown(const RotorCeiling* rotors, int rotor_count,
                                        const FlightCondition& flight) const {
  if (rotor_count != parameters_.airframe.rotor_count)
    throw ceilplan::InputError("got ceiling gaps for " + std::to_string(rotor_count) + " rotors, the vehicle has " +
                               std::to_string(parameters_.airframe.rotor_count));
  checkFlight(flight);
  const double ground_factor = ground_.thrustRatio(flight.ground_gap_m);
  double ceiling_sum = 0.0;
  double induced_sum = 0.0;
  for (int i = 0; i < rotor_count; ++i) {
    checkGap("ceiling gap", rotors[i].gap_m);
    if (!(rotors[i].coverage >= 0.0 && rotors[i].coverage <= 1.0))
      refuse("ceiling coverage", rotors[i].coverage, "is outside [0, 1]");
    const double ceiling_factor = ceiling_.thrustRatio(rotors[i].gap_m, rotors[i].coverage);
    ceiling_sum += ceiling_factor;
    // Each rotor still carries its share of the thrust, so the power ratios average.
    induced_sum += inducedPowerRatio(ceiling_factor * ground_factor, parameters_.rotor.convention);
  }
  const double inverse_count = 1.0 / rotor_count;
  return combine(ceiling_sum * inverse_count, induced_sum * inverse_count, ground_factor, flight);
}

CurrentBreakdown EnergyModel::combine(double ceiling_factor, double induced_power_factor, double ground_factor,
                                      const FlightCondition& flight) const {
  // Forward-flight power is a function of airspeed (docs/models.md, "Wind").
  const double v = flight.airspeedM_s();
  const double induced_shaft_w = induced_power_factor * rotor_power_.inducedPowerW(v);
  const double profile_shaft_w = rotor_power_.profilePowerW(v);
  const double parasitic_shaft_w = rotor_power_.parasiticPowerW(v);
  const double level_shaft_w = induced_shaft_w + profile_shaft_w + parasitic_shaft_w;
  // Climb adds m g v_z (docs/models.md, "Power against speed, climb and descent"); descent
  // gives some back, never below the floor.
  const double climb_shaft_w =
      std::max(weight_n_ * flight.climb_m_s, -(1.0 - parameters_.rotor.descent_power_floor) * level_shaft_w);

  CurrentBreakdown out;
  out.induced_w = induced_shaft_w * inverse_efficiency_;
  out.profile_w = profile_shaft_w * inverse_efficiency_;
  out.parasitic_w = parasitic_shaft_w * inverse_efficiency_;
  out.climb_w = climb_shaft_w * inverse_efficiency_;
  const double propulsion_w = out.propulsionW();
  const PackOperatingPoint point = pack_.operatingPoint(propulsion_w, flight.soc);
  out.current_a = point.current_a;
  out.terminal_voltage_v = point.terminal_voltage_v;
  out.avionics_w = point.terminal_voltage_v * pack_.avionicsCurrentA();
  out.power_w = propulsion_w + out.avionics_w;
  out.ceiling_factor = ceiling_factor;
  out.ground_factor = ground_factor;
  out.induced_power_factor = induced_power_factor;
  return out;
}

}  // namespace ceilplan::energy
