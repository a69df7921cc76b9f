#include "mechanism/rig.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/toml_section.hpp"
#include "common/units.hpp"

namespace fourbar {

const char* to_string(Assembly a) { return a == Assembly::open ? "open" : "crossed"; }

const char* to_string(GrashofClass c) {
  switch (c) {
    case GrashofClass::crank_rocker: return "crank-rocker";
    case GrashofClass::double_crank: return "double-crank";
    case GrashofClass::double_rocker: return "double-rocker";
    case GrashofClass::rocker_crank: return "rocker-crank";
    case GrashofClass::change_point: return "change-point";
    case GrashofClass::non_grashof: return "non-Grashof (triple rocker)";
  }
  return "?";
}

double toggle_margin_m(const Rig& rig) {
  const double l1 = rig.ground_length_m, l2 = rig.crank.length_m, l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  return std::min((l3 + l4) - (l1 + l2), std::abs(l1 - l2) - std::abs(l3 - l4));
}

GrashofClass grashof_class(const Rig& rig) {
  const std::array<double, 4> l{rig.ground_length_m, rig.crank.length_m, rig.coupler.length_m, rig.rocker.length_m};
  const auto [mn, mx] = std::minmax_element(l.begin(), l.end());
  const double s = *mn, big = *mx;
  const double sum = l[0] + l[1] + l[2] + l[3];
  const double lhs = s + big, rhs = sum - lhs;
  const double tol = 1e-12 * sum;
  if (std::abs(lhs - rhs) <= tol) return GrashofClass::change_point;
  if (lhs > rhs) return GrashofClass::non_grashof;
  switch (mn - l.begin()) {
    case 0: return GrashofClass::double_crank;
    case 1: return GrashofClass::crank_rocker;
    case 2: return GrashofClass::double_rocker;
    default: return GrashofClass::rocker_crank;
  }
}

namespace {

std::string where(const Rig& rig) { return rig.source.empty() ? std::string("rig") : rig.source.string(); }

std::string mm(double m) { return format_number(units::m_to_mm(m)) + " mm"; }

void require_positive(const Rig& rig, const char* key, double v) {
  if (!(v > 0) || !std::isfinite(v)) {
    std::ostringstream os;
    os << where(rig) << ": key '" << key << "' = " << v << " must be a positive number";
    throw InputError(os.str());
  }
}

}  // namespace

void validate_rig(const Rig& rig) {
  require_positive(rig, "ground.length_mm", rig.ground_length_m);
  const std::pair<const char*, const Link*> links[] = {
      {"crank", &rig.crank}, {"coupler", &rig.coupler}, {"rocker", &rig.rocker}};
  for (const auto& [name, link] : links) {
    const std::string n(name);
    require_positive(rig, (n + ".length_mm").c_str(), link->length_m);
    require_positive(rig, (n + ".mass_kg").c_str(), link->mass_kg);
    require_positive(rig, (n + ".inertia_kg_mm2").c_str(), link->inertia_cg_kg_m2);
    if (!std::isfinite(link->mass_centre_m) || link->mass_centre_m < 0 || link->mass_centre_m > link->length_m) {
      std::ostringstream os;
      os << where(rig) << ": key '" << n << ".mass_centre_mm' = " << mm(link->mass_centre_m)
         << " must lie on the link, between 0 and its length " << mm(link->length_m);
      throw InputError(os.str());
    }
  }
  if (!(rig.gravity_m_s2 >= 0) || !std::isfinite(rig.gravity_m_s2))
    throw InputError(where(rig) + ": key 'gravity_m_s2' must be a number >= 0");
  if (!(rig.radial_clearance_m >= 0) || !std::isfinite(rig.radial_clearance_m))
    throw InputError(where(rig) + ": key 'clearance.radial_mm' must be a number >= 0");

  // The crank turns fully iff the distance r from crank pin A to rocker pivot
  // O4, which sweeps [|l1 − l2|, l1 + l2], stays strictly inside the reach of
  // coupler and rocker, (|l3 − l4|, l3 + l4). Touching the bound is a toggle.
  const double l1 = rig.ground_length_m, l2 = rig.crank.length_m;
  const double l3 = rig.coupler.length_m, l4 = rig.rocker.length_m;
  const double r_min = std::abs(l1 - l2), r_max = l1 + l2;
  const double reach_min = std::abs(l3 - l4), reach_max = l3 + l4;
  if (r_max >= reach_max || r_min <= reach_min) {
    std::ostringstream os;
    os << where(rig) << ": the links cannot close over a full crank turn (" << to_string(grashof_class(rig))
       << " linkage): the crank pin comes " << mm(r_min) << " to " << mm(r_max)
       << " from the rocker pivot, but coupler and rocker only reach between " << mm(reach_min) << " and "
       << mm(reach_max) << " (exclusive); check ground/crank/coupler/rocker length_mm";
    throw InputError(os.str());
  }
}

namespace {

Link read_link(TomlSection& root, const char* name, std::optional<LinkElasticity>* elastic = nullptr) {
  TomlSection s = root.section(name);
  Link link;
  link.length_m = units::mm_to_m(s.positive("length_mm"));
  link.mass_centre_m = units::mm_to_m(s.non_negative("mass_centre_mm"));
  link.mass_kg = s.positive("mass_kg");
  link.inertia_cg_kg_m2 = units::kg_mm2_to_kg_m2(s.positive("inertia_kg_mm2"));
  if (link.mass_centre_m > link.length_m)
    s.fail("mass_centre_mm", "= " + std::to_string(units::m_to_mm(link.mass_centre_m)) +
                                 " lies beyond the link (length_mm = " +
                                 std::to_string(units::m_to_mm(link.length_m)) + ")");
  if (elastic)
    if (auto e = s.optional_section("elastic")) *elastic = read_link_elasticity(*e);
  s.finish();
  return link;
}

/// The bearing's bodies in the rig's [clearance] table (see BearingBodies).
void read_bearing_bodies(TomlSection& c, Rig& rig) {
  BearingBodies& b = rig.bearing;
  auto positive = [&](const char* key, double scale) -> std::optional<double> {
    if (!c.has(key)) return std::nullopt;
    const double v = c.number(key);
    if (!(v > 0) || !std::isfinite(v)) c.fail(key, "must be a positive number");
    // 1e300 GPa is finite but not in Pa: an infinite modulus would give the
    // compliant contact an infinite stiffness (fuzzing: tests/fuzz/regressions/rig/).
    if (!std::isfinite(v * scale)) c.fail(key, "= " + format_number(v) + " is too large to be a bearing's value");
    return v * scale;
  };
  auto poisson = [&](const char* key) -> std::optional<double> {
    if (!c.has(key)) return std::nullopt;
    const double v = c.number(key);
    if (!(v > -1 && v < 0.5))
      c.fail(key, "must lie in (-1, 0.5): an isotropic elastic solid has -1 < nu < 0.5 (steel 0.3, bronze 0.34)");
    return v;
  };
  b.pin_radius_m = positive("pin_radius_mm", 1e-3);
  b.bushing_radius_m = positive("bushing_radius_mm", 1e-3);
  b.length_m = positive("bearing_length_mm", 1e-3);
  b.pin_youngs_modulus_Pa = positive("pin_youngs_modulus_GPa", 1e9);
  b.pin_poisson_ratio = poisson("pin_poisson_ratio");
  b.bushing_youngs_modulus_Pa = positive("bushing_youngs_modulus_GPa", 1e9);
  b.bushing_poisson_ratio = poisson("bushing_poisson_ratio");
  if (c.has("lubricant_viscosity_Pa_s")) {
    const double v = c.number("lubricant_viscosity_Pa_s");
    if (!(v > 0) || !(v < 1e6))
      c.fail("lubricant_viscosity_Pa_s", "must be a positive dynamic viscosity in Pa s (e.g. 0.05 for an SAE 20 oil "
                                         "near 40 °C); remove it for a dry bearing");
    if (!b.length_m)
      c.fail("lubricant_viscosity_Pa_s", "needs bearing_length_mm in the same table (the film force grows with the "
                                         "length cubed); add bearing_length_mm");
    if (!b.pin_radius_m && !b.bushing_radius_m)
      c.fail("lubricant_viscosity_Pa_s", "needs pin_radius_mm (or bushing_radius_mm) in the same table (the film "
                                         "force grows with the journal radius); add pin_radius_mm");
    b.lubricant_viscosity_Pa_s = v;
  }
  if (b.pin_radius_m && b.bushing_radius_m) {
    const double fit = *b.bushing_radius_m - *b.pin_radius_m;
    if (!(std::abs(fit - rig.radial_clearance_m) <= 1e-9 * std::max(1e-3, *b.bushing_radius_m)))
      c.fail("pin_radius_mm", "= " + format_number(units::m_to_mm(*b.pin_radius_m)) +
                                  " does not fit the bushing with the stated clearance: bushing_radius_mm - "
                                  "pin_radius_mm = " + format_number(units::m_to_mm(fit)) + " mm but radial_mm = " +
                                  format_number(units::m_to_mm(rig.radial_clearance_m)) +
                                  "; make them agree (or give only one of the two radii)");
  }
}

}  // namespace

Rig load_rig(const std::filesystem::path& file) {
  const toml::table doc = parse_toml_file(file);
  TomlSection root(doc, file);
  Rig rig;
  rig.source = file;
  rig.name = root.optional_string("name").value_or(file.stem().string());
  rig.gravity_m_s2 = root.in_range("gravity_m_s2", 0.0, 1000.0, 9.80665);
  rig.assembly = root.choice("assembly", {"open", "crossed"}, "open") == "open" ? Assembly::open : Assembly::crossed;
  {
    TomlSection ground = root.section("ground");
    rig.ground_length_m = units::mm_to_m(ground.positive("length_mm"));
    ground.finish();
  }
  rig.crank = read_link(root, "crank");
  rig.coupler = read_link(root, "coupler", &rig.coupler_elastic);
  rig.rocker = read_link(root, "rocker", &rig.rocker_elastic);
  if (auto c = root.optional_section("clearance")) {
    rig.radial_clearance_m = units::mm_to_m(c->non_negative("radial_mm"));
    read_bearing_bodies(*c, rig);
    c->finish();
  }
  root.optional_string("notes");
  root.finish();
  validate_rig(rig);
  return rig;
}

Rig thesis_rig() {
  Rig rig;
  rig.name = "thesis rig (Table 6.1/7.1)";
  rig.ground_length_m = 0.387;
  rig.crank = {0.064, 0.009, 0.6095, 2645.0e-6};
  rig.coupler = {0.309, 0.185, 0.2439, 2950.0e-6};
  rig.rocker = {0.312, 0.134, 0.2334, 3176.0e-6};
  rig.gravity_m_s2 = 9.8145;
  rig.assembly = Assembly::open;
  rig.radial_clearance_m = 0.254e-3;
  return rig;
}

}  // namespace fourbar
