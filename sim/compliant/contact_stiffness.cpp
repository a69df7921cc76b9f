#include "sim/compliant/contact_stiffness.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "common/format.hpp"
#include "common/units.hpp"

namespace fourbar {

double composite_modulus_Pa(double pin_E, double pin_nu, double bushing_E, double bushing_nu) {
  return 1.0 / ((1.0 - pin_nu * pin_nu) / pin_E + (1.0 - bushing_nu * bushing_nu) / bushing_E);
}

double conformal_cylinder_stiffness(double e_star, double length_m, double clearance_m) {
  return units::kPi * e_star * length_m / (2.0 * std::sqrt(2.0 * clearance_m));
}

namespace {

/// The lubricated bearing's film from the scene's or the rig's viscosity and
/// the rig's bearing (see CompliantSettings::film).
template <class Fail>
void resolve_film(const Rig& rig, double clearance_m, CompliantSettings& k, const Fail& fail) {
  const BearingBodies& b = rig.bearing;
  const std::string rig_file = rig.source.empty() ? std::string("the rig") : rig.source.string();
  JournalFilm& f = k.film;
  if (!k.viscosity_given) f.viscosity_Pa_s = b.lubricant_viscosity_Pa_s.value_or(0.0);
  if (!(f.viscosity_Pa_s > 0)) {
    if (k.film_keys_given)
      fail("film", "and film_break_eccentricity describe a lubricant film, but the bearing is dry (no "
                   "lubricant_viscosity_Pa_s here or in " + rig_file + "'s [clearance]); give the viscosity or remove them");
    return;
  }
  if (!b.length_m)
    fail("lubricant_viscosity_Pa_s", "needs the bearing's length, and " + rig_file + " has no [clearance] "
                                     "bearing_length_mm (the film force grows with the length cubed); add "
                                     "bearing_length_mm to the rig");
  if (!b.pin_radius_m && !b.bushing_radius_m)
    fail("lubricant_viscosity_Pa_s", "needs the journal radius, and " + rig_file + " has no [clearance] "
                                     "pin_radius_mm or bushing_radius_mm; add pin_radius_mm to the rig");
  f.length_m = *b.length_m;
  f.radius_m = b.pin_radius_m ? *b.pin_radius_m : *b.bushing_radius_m - clearance_m;
  f.clearance_m = clearance_m;
}

}  // namespace

void resolve_contact_stiffness(TomlSection& s, const Rig& rig, double clearance_m, ClearanceSettings& settings) {
  resolve_contact_stiffness(rig, clearance_m, settings,
                            [&s](const char* key, const std::string& what) { s.fail(key, what); });
}

void resolve_contact_stiffness(const Rig& rig, double clearance_m, ClearanceSettings& settings,
                               const std::function<void(const char* key, const std::string& what)>& report) {
  auto fail = [&report](const char* key, const std::string& what) {
    report(key, what);
    throw std::logic_error("resolve_contact_stiffness: the failure callback returned");
  };
  const BearingBodies& b = rig.bearing;
  const std::string rig_file = rig.source.empty() ? std::string("the rig") : rig.source.string();
  if (b.pin_radius_m && b.bushing_radius_m) {
    const double fit = *b.bushing_radius_m - *b.pin_radius_m;
    if (!(std::abs(fit - clearance_m) <= 1e-9 * std::max(1e-3, *b.bushing_radius_m)))
      fail("radial_mm", "= " + format_number(units::m_to_mm(clearance_m)) + " mm does not fit " + rig_file +
                              "'s bearing: its bushing_radius_mm - pin_radius_mm = " +
                              format_number(units::m_to_mm(fit)) +
                              " mm; remove radial_mm here or change the rig's radii");
  }
  CompliantSettings& k = settings.compliant;
  resolve_film(rig, clearance_m, k, fail);
  if (k.stiffness_given) return;
  const std::pair<const char*, bool> needed[] = {
      {"bearing_length_mm", b.length_m.has_value()},
      {"pin_youngs_modulus_GPa", b.pin_youngs_modulus_Pa.has_value()},
      {"pin_poisson_ratio", b.pin_poisson_ratio.has_value()},
      {"bushing_youngs_modulus_GPa", b.bushing_youngs_modulus_Pa.has_value()},
      {"bushing_poisson_ratio", b.bushing_poisson_ratio.has_value()}};
  for (const auto& [key, present] : needed)
    if (!present)
      fail("contact_stiffness_N_per_m_n",
             std::string("is not given and ") + rig_file + " has no [clearance] " + key +
                 " to compute it from; give contact_stiffness_N_per_m_n (N/m^n) here or the rig's bearing keys "
                 "(bearing_length_mm, pin/bushing_youngs_modulus_GPa, pin/bushing_poisson_ratio)");
  if (k.exponent != 1.5)
    fail("contact_exponent", "must be 1.5 (or absent) when the stiffness is computed from the rig's bearing (the "
                               "conformal-cylinder law is a 1.5 power law); or give contact_stiffness_N_per_m_n");
  const double e_star = composite_modulus_Pa(*b.pin_youngs_modulus_Pa, *b.pin_poisson_ratio,
                                             *b.bushing_youngs_modulus_Pa, *b.bushing_poisson_ratio);
  k.stiffness_N_per_m_n = conformal_cylinder_stiffness(e_star, *b.length_m, clearance_m);
}

}  // namespace fourbar
