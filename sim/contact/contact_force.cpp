#include "sim/contact/contact_force.hpp"

#include <cmath>
#include <limits>

#include "sim/contact/restitution_calibration.hpp"

namespace fourbar {

const char* to_string(DampingLaw d) {
  switch (d) {
    case DampingLaw::calibrated: return "calibrated";
    case DampingLaw::hunt_crossley: return "hunt-crossley";
    case DampingLaw::lankarani_nikravesh: return "lankarani-nikravesh";
    case DampingLaw::flores: return "flores";
  }
  return "?";
}

double hysteresis_factor(DampingLaw law, double e, double n) {
  switch (law) {
    case DampingLaw::calibrated:
      return e > 0 ? calibrated_hysteresis(e, n) : std::numeric_limits<double>::infinity();
    case DampingLaw::hunt_crossley: return 1.5 * (1.0 - e);
    case DampingLaw::lankarani_nikravesh: return 0.75 * (1.0 - e * e);
    case DampingLaw::flores:
      return e > 0 ? 1.6 * (1.0 - e) / e : std::numeric_limits<double>::infinity();
  }
  return 0;
}

namespace {

/// δ^n for δ > 0: Hertz's 1.5 and its energy's 2.5 through √δ (within an
/// ulp or two of pow, at a fifth of its cost: pow was 2 % of the elastic
/// linkage's instructions, bench/elastic_linkage_work_precision), else pow.
double penetration_power(double pen, double exponent) {
  if (exponent == 1.5) return pen * std::sqrt(pen);
  if (exponent == 2.5) return pen * pen * std::sqrt(pen);
  return std::pow(pen, exponent);
}

}  // namespace

double elastic_force_N(const NormalForceLaw& law, double pen) {
  return pen > 0 ? law.stiffness * penetration_power(pen, law.exponent) : 0.0;
}

double elastic_energy_J(const NormalForceLaw& law, double pen) {
  return pen > 0 ? law.stiffness * penetration_power(pen, law.exponent + 1.0) / (law.exponent + 1.0) : 0.0;
}

double normal_force_N(const NormalForceLaw& law, double pen, double rate, double chi) {
  if (!(pen > 0)) return 0.0;
  const double f = law.stiffness * penetration_power(pen, law.exponent) * (1.0 + chi * rate);
  return f > 0 ? f : 0.0;
}

double friction_ramp(const FrictionLaw& law, double v) {
  const double a = std::abs(v);
  if (a <= law.stick_speed_m_s) return 0.0;
  if (a >= law.slip_speed_m_s) return 1.0;
  const double x = (a - law.stick_speed_m_s) / (law.slip_speed_m_s - law.stick_speed_m_s);
  return x * x * (3.0 - 2.0 * x);
}

double friction_force_N(const FrictionLaw& law, double fn, double v) {
  if (law.mu == 0 || fn == 0) return 0.0;
  const double f = law.mu * friction_ramp(law, v) * fn;
  return v > 0 ? -f : v < 0 ? f : 0.0;
}

}  // namespace fourbar
