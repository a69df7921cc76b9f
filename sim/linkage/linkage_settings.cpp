#include "sim/linkage/linkage_settings.hpp"

#include <cmath>
#include <string>

#include "common/number_text.hpp"
#include "sim/three_mode/settings.hpp"

namespace fourbar {

LinkageSettings read_linkage_settings(TomlSection& s, const Rig& rig) {
  LinkageSettings out;
  LinkageSpec& spec = out.spec;
  const char* keys[kJoints] = {"crank_coupler_radial_mm", "coupler_rocker_radial_mm", "rocker_ground_radial_mm"};
  const double defaults[kJoints] = {0.0, rig.radial_clearance_m * 1e3, 0.0};
  const double margin_mm = toggle_margin_m(rig) * 1e3;
  double sum_mm = 0;
  for (int j = 0; j < kJoints; ++j) {
    const double mm = s.in_range(keys[j], 0.0, 1e3, defaults[j]);
    spec.clearance_m[static_cast<std::size_t>(j)] = mm * 1e-3;
    sum_mm += mm;
  }
  if (sum_mm == 0)
    s.fail("coupler_rocker_radial_mm", "and the other two joints' clearances are all 0; give at least one joint a "
                                       "clearance > 0 (or use model = \"nominal\")");
  if (!(sum_mm < margin_mm)) {
    int largest = 0;
    for (int j = 1; j < kJoints; ++j)
      if (spec.clearance_m[static_cast<std::size_t>(j)] > spec.clearance_m[static_cast<std::size_t>(largest)]) largest = j;
    s.fail(keys[largest], "makes the joints' clearances add up to " + format_double(sum_mm) +
                              " mm, not below the rig's distance to a toggle (" + format_double(margin_mm) +
                              " mm); use smaller clearances");
  }
  // The compliant contact law, read by the compliant model's own reader.
  ClearanceSettings c;
  c.model = ClearanceKind::compliant;
  c.restitution = s.number("restitution");
  if (!(c.restitution >= 0 && c.restitution <= 1)) s.fail("restitution", "must be in [0, 1] (1 = elastic, 0 = plastic)");
  read_compliant_settings(s, c);
  if (!c.compliant.stiffness_given)
    s.fail("contact_stiffness_N_per_m_n", "is required with model = \"linkage\" (K in N/m^n > 0, e.g. 1e10)");
  const CompliantSettings& k = c.compliant;
  spec.law = {k.stiffness_N_per_m_n, k.exponent, k.damping, c.restitution};
  spec.friction = {c.friction_coefficient, k.friction_stick_speed_m_s, k.friction_slip_speed_m_s};
  spec.damping_floor_speed_m_s = k.damping_floor_speed_m_s;
  spec.film = k.film;
  if (!k.viscosity_given && rig.bearing.lubricant_viscosity_Pa_s) spec.film.viscosity_Pa_s = *rig.bearing.lubricant_viscosity_Pa_s;
  if (spec.film.viscosity_Pa_s > 0) {
    if (!rig.bearing.pin_radius_m || !rig.bearing.length_m)
      s.fail("lubricant_viscosity_Pa_s", "needs the rig's [clearance] pin_radius_mm and bearing_length_mm (the film "
                                         "force depends on both); add them to the rig or remove the viscosity");
    spec.film.radius_m = *rig.bearing.pin_radius_m;
    spec.film.length_m = *rig.bearing.length_m;
  }
  if (s.has("elastic_links")) {
    for (const std::string& name : s.strings("elastic_links")) {
      const bool coupler = name == "coupler";
      if (!coupler && name != "rocker")
        s.fail("elastic_links", "names \"" + name + "\"; only \"coupler\" and \"rocker\" can be elastic");
      if (!(coupler ? rig.coupler_elastic : rig.rocker_elastic))
        s.fail("elastic_links", "names \"" + name + "\" but the rig has no [" + name +
                                    ".elastic] table; add one (docs/flex.md) or remove the link");
      spec.elastic[coupler ? 1U : 2U] = true;
    }
  }
  if (s.has("elastic_modes")) {
    const double modes = s.in_range("elastic_modes", 1.0, 4.0);
    if (modes != std::floor(modes)) s.fail("elastic_modes", "must be a whole number of modes, 1 to 4");
    spec.elastic_modes = static_cast<int>(modes);
    for (int b : {1, 2}) {
      const auto& e = b == 1 ? rig.coupler_elastic : rig.rocker_elastic;
      if (spec.elastic[static_cast<std::size_t>(b)] && e && e->modes < spec.elastic_modes)
        s.fail("elastic_modes", "asks for " + std::to_string(spec.elastic_modes) + " modes but the rig's [" +
                                    (b == 1 ? "coupler" : "rocker") + ".elastic] gives " + std::to_string(e->modes) +
                                    "; lower elastic_modes or raise the table's modes");
    }
  }
  for (int b : {1, 2}) {
    const std::string key = b == 1 ? "coupler_sensors_mm" : "rocker_sensors_mm";
    if (!s.has(key)) continue;
    const std::vector<double> v = s.numbers(key);
    const double L_mm = (b == 1 ? rig.coupler.length_m : rig.rocker.length_m) * 1e3;
    if (v.empty() || v.size() % 2 != 0)
      s.fail(key, "must hold (distance_mm, offset_mm) pairs, e.g. [154.5, 0.0, 300.0, 5.0]");
    for (std::size_t i = 0; i < v.size(); i += 2) {
      if (!(v[i] > 0 && v[i] <= L_mm))
        s.fail(key, "has a distance of " + format_double(v[i]) + " mm; it must be in (0, " + format_double(L_mm) +
                        "] mm, measured from the link's first joint");
      out.sensors.push_back({b, v[i] * 1e-3, v[i + 1] * 1e-3});
    }
  }
  spec.tolerance = s.in_range("tolerance", 1e-14, 1e-3, 1e-10);
  spec.settle_speed_m_s = s.in_range("settle_speed_mm_s", 0.0, 1e6, 1e-3) * 1e-3;
  if (s.has("crank_motion")) out.crank_table = s.path("crank_motion");
  if (s.has("duration_s")) {
    if (out.crank_table.empty()) s.fail("duration_s", "is only used with crank_motion; remove it (the run lasts the scene's revolutions)");
    out.duration_s = s.in_range("duration_s", 1e-6, 1e6);
  }
  return out;
}

}  // namespace fourbar
