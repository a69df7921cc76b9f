// The compliant model's keys of the scene's `[clearance]` table
// (model = "compliant"): the damping law, the stiffness (or none: computed
// from the rig's bearing when the scene is loaded), the exponent and the wall
// friction. The three-mode model's impact-law keys are refused here. A key
// that is absent keeps the value `c` holds (the defaults for a scene; the
// session's [theory] values for one of its [[recording]] tables).

#include "sim/three_mode/settings.hpp"

namespace fourbar {

void read_compliant_settings(TomlSection& s, ClearanceSettings& c) {
  for (const char* key : {"contact", "following_friction"})
    if (s.has(key))
      s.fail(key, "belongs to the three-mode impact law; model = \"compliant\" takes friction_coefficient (its "
                  "wall friction) and damping instead: remove it");
  if (s.has("integrator"))
    s.fail("integrator", "is not used with model = \"compliant\" (always CVODE BDF with a dense Jacobian); remove it");
  CompliantSettings& k = c.compliant;
  const std::string damping =
      s.choice("damping", {"calibrated", "flores", "hunt-crossley", "lankarani-nikravesh"}, to_string(k.damping));
  k.damping = damping == "calibrated"      ? DampingLaw::calibrated
              : damping == "flores"        ? DampingLaw::flores
              : damping == "hunt-crossley" ? DampingLaw::hunt_crossley
                                           : DampingLaw::lankarani_nikravesh;
  if ((k.damping == DampingLaw::flores || k.damping == DampingLaw::calibrated) && !(c.restitution >= 0.01))
    s.fail("restitution", "must be >= 0.01 with damping = \"" + damping + "\" (its damping grows without bound as "
                          "e -> 0); give e >= 0.01 or damping = \"hunt-crossley\"");
  if (s.has("contact_stiffness_N_per_m_n")) {
    k.stiffness_N_per_m_n = s.number("contact_stiffness_N_per_m_n");
    if (!(k.stiffness_N_per_m_n > 0) || !(k.stiffness_N_per_m_n < 1e20))
      s.fail("contact_stiffness_N_per_m_n",
             "must be a positive number (K in N/m^n, e.g. 1e9); or remove it to compute K from the rig's bearing");
    k.stiffness_given = true;
  }
  k.exponent = s.in_range("contact_exponent", 1.0, 3.0, k.exponent);
  if (s.has("friction_coefficient")) {
    c.friction_coefficient = s.number("friction_coefficient");
    if (!(c.friction_coefficient >= 0) || c.friction_coefficient > 100)
      s.fail("friction_coefficient", "must be >= 0 (Coulomb coefficient μ of the wall)");
  }
  k.friction_stick_speed_m_s = s.in_range("friction_stick_speed_mm_s", 0.0, 1e3, k.friction_stick_speed_m_s * 1e3) * 1e-3;
  k.friction_slip_speed_m_s = s.in_range("friction_slip_speed_mm_s", 1e-6, 1e4, k.friction_slip_speed_m_s * 1e3) * 1e-3;
  k.damping_floor_speed_m_s =
      s.in_range("damping_floor_speed_mm_s", 1e-9, 1e3, k.damping_floor_speed_m_s * 1e3) * 1e-3;
  if (s.has("lubricant_viscosity_Pa_s")) {
    k.film.viscosity_Pa_s = s.number("lubricant_viscosity_Pa_s");
    if (!(k.film.viscosity_Pa_s > 0) || !(k.film.viscosity_Pa_s < 1e6))
      s.fail("lubricant_viscosity_Pa_s", "must be a positive dynamic viscosity in Pa s (e.g. 0.05); remove it to use "
                                         "the rig's (or a dry bearing)");
    k.viscosity_given = true;
  }
  if (s.has("film") || s.has("film_break_eccentricity")) k.film_keys_given = true;
  const std::string film = s.choice("film", {"cavitated", "pinkus-sternlicht", "full"}, to_string(k.film.extent));
  k.film.extent = film == "cavitated"           ? FilmExtent::cavitated
                  : film == "pinkus-sternlicht" ? FilmExtent::pinkus_sternlicht
                                                : FilmExtent::full;
  k.film.break_eccentricity = s.in_range("film_break_eccentricity", 0.5, 0.999, k.film.break_eccentricity);
  if (!(k.friction_slip_speed_m_s > k.friction_stick_speed_m_s))
    s.fail("friction_slip_speed_mm_s", "must be above friction_stick_speed_mm_s (v1 > v0 of the friction ramp)");
}

}  // namespace fourbar
