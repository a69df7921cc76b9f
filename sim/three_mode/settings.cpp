#include "sim/three_mode/settings.hpp"

#include <algorithm>

#include "common/units.hpp"

namespace fourbar {

const char* to_string(ContactLaw c) {
  switch (c) {
    case ContactLaw::smooth: return "smooth";
    case ContactLaw::rough: return "rough";
    case ContactLaw::stick_slip: return "stick-slip";
  }
  return "?";
}

const char* to_string(ClearanceKind k) { return k == ClearanceKind::compliant ? "compliant" : "three-mode"; }

const char* to_string(ClearanceSettings::SteadyCriterion c) {
  switch (c) {
    case ClearanceSettings::SteadyCriterion::periodic: return "periodic";
    case ClearanceSettings::SteadyCriterion::statistical: return "statistical";
    case ClearanceSettings::SteadyCriterion::either: return "either";
  }
  return "?";
}

namespace {

/// The three-mode model's impact law keys; the compliant model's own keys are refused.
void read_three_mode_settings(TomlSection& s, ClearanceSettings& c) {
  for (const char* key : {"damping", "contact_stiffness_N_per_m_n", "contact_exponent", "friction_stick_speed_mm_s",
                          "friction_slip_speed_mm_s", "damping_floor_speed_mm_s"})
    if (s.has(key)) s.fail(key, "is only used with model = \"compliant\"; remove it or set model = \"compliant\"");
  const std::string contact = s.choice("contact", {"smooth", "rough", "stick-slip"}, "smooth");
  c.contact = contact == "smooth" ? ContactLaw::smooth : contact == "rough" ? ContactLaw::rough : ContactLaw::stick_slip;
  if (s.has("friction_coefficient")) {
    c.friction_coefficient = s.number("friction_coefficient");
    if (!(c.friction_coefficient >= 0) || c.friction_coefficient > 100)
      s.fail("friction_coefficient", "must be >= 0 (Coulomb coefficient μ)");
    if (c.contact != ContactLaw::stick_slip)
      s.fail("friction_coefficient", "is only used with contact = \"stick-slip\"; remove it or change contact");
  } else if (c.contact == ContactLaw::stick_slip) {
    s.fail("friction_coefficient", "is required with contact = \"stick-slip\" (Coulomb coefficient μ >= 0)");
  }
  c.following_friction = s.boolean("following_friction", false);
  if (c.following_friction && c.contact != ContactLaw::stick_slip)
    s.fail("following_friction", "needs contact = \"stick-slip\" and its friction_coefficient (the wall's Coulomb mu)");
}

}  // namespace

ClearanceSettings read_clearance_settings(TomlSection& s, double rig_clearance_m) {
  ClearanceSettings c;
  if (s.has("radial_mm")) {
    const double mm = s.number("radial_mm");
    if (!(mm > 0) || mm > 100)
      s.fail("radial_mm", "must be > 0 and at most 100 mm (use model = \"nominal\" for no clearance)");
    c.radial_clearance_m = units::mm_to_m(mm);
  } else if (!(rig_clearance_m > 0)) {
    s.fail("radial_mm", "is missing and the rig has no [clearance] radial_mm > 0; give the radial clearance in mm");
  }
  c.restitution = s.number("restitution");
  if (!(c.restitution >= 0 && c.restitution <= 1))
    s.fail("restitution", "must be in [0, 1] (1 = elastic, 0 = plastic)");
  c.model = s.choice("model", {"three-mode", "compliant"}, "three-mode") == "compliant" ? ClearanceKind::compliant
                                                                                     : ClearanceKind::three_mode;
  if (c.model == ClearanceKind::compliant) read_compliant_settings(s, c);
  else read_three_mode_settings(s, c);
  c.tolerance = s.in_range("tolerance", 1e-14, 1e-3, 1e-10);
  if (c.model == ClearanceKind::three_mode)
    c.integrator = s.choice("integrator", {"cvode", "odeint"}, "odeint") == "cvode" ? IntegratorKind::cvode
                                                                                 : IntegratorKind::odeint;
  c.settle_speed_m_s = s.in_range("settle_speed_mm_s", 1e-9, 1e3, 1e-3) * 1e-3;
  c.steady_state = s.boolean("steady_state", false);
  c.max_revolutions = static_cast<int>(s.integer("max_revolutions", 1, 1'000'000, 200));
  c.steady_tolerance = s.in_range("steady_tolerance", 1e-14, 1.0, 1e-6);
  c.max_period = static_cast<int>(s.integer("max_period", 1, 64, 8));
  const std::string criterion = s.choice("steady_criterion", {"periodic", "statistical", "either"}, "either");
  c.steady_criterion = criterion == "periodic"      ? ClearanceSettings::SteadyCriterion::periodic
                       : criterion == "statistical" ? ClearanceSettings::SteadyCriterion::statistical
                                                    : ClearanceSettings::SteadyCriterion::either;
  c.statistical_window = static_cast<int>(s.integer("statistical_window", 2, 100'000, 20));
  c.statistical_tolerance = s.in_range("statistical_tolerance", 1e-6, 1.0, 0.05);
  if (s.has("tables")) {
    for (const auto& t : s.strings("tables")) {
      if (t == "impacts") c.write_impacts = true;
      else if (t == "revolutions") c.write_revolutions = true;
      else s.fail("tables", "names unknown table '" + t + "'; use \"impacts\" and/or \"revolutions\"");
    }
  }
  return c;
}

}  // namespace fourbar
