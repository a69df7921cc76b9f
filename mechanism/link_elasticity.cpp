#include "mechanism/link_elasticity.hpp"

#include <cmath>
#include <string>

#include "common/format.hpp"
#include "common/toml_section.hpp"

namespace fourbar {

namespace {

constexpr const char* kNoStiffness =
    "gives the link no bending stiffness; give Young's modulus E_GPa (steel 210, aluminium 70) with the section "
    "(width_mm and thickness_mm, or second_moment_mm4 and area_mm2), or the tap test's mode_frequencies_Hz";

std::optional<double> stiff_value(TomlSection& t, const char* key, double scale) {
  if (!t.has(key)) return std::nullopt;
  const double v = t.number(key);
  if (!(v > 0)) t.fail(key, "= " + format_number(v) + " " + kNoStiffness);
  if (!std::isfinite(v * scale)) t.fail(key, "= " + format_number(v) + " is too large for a link");
  return v * scale;
}

}  // namespace

LinkElasticity read_link_elasticity(TomlSection& t) {
  LinkElasticity e;
  e.youngs_modulus_Pa = stiff_value(t, "E_GPa", 1e9);
  const std::optional<double> width = stiff_value(t, "width_mm", 1e-3);
  const std::optional<double> thickness = stiff_value(t, "thickness_mm", 1e-3);
  const std::optional<double> area = stiff_value(t, "area_mm2", 1e-6);
  const std::optional<double> second_moment = stiff_value(t, "second_moment_mm4", 1e-12);
  if (t.has("density_kg_m3")) {
    const double rho = t.number("density_kg_m3");
    if (!(rho > 0 && rho < 1e5))
      t.fail("density_kg_m3", "= " + format_number(rho) + " must be a density in kg/m³ (steel 7850, aluminium 2700)");
    e.density_kg_m3 = rho;
  }
  if ((width || thickness) && (area || second_moment))
    t.fail(width ? "width_mm" : "thickness_mm",
           "and area_mm2/second_moment_mm4 both describe the section; give one of the two");
  if (width.has_value() != thickness.has_value())
    t.fail(width ? "width_mm" : "thickness_mm", "needs its partner (width_mm with thickness_mm) to give the section");
  if (width) {
    e.area_m2 = *width * *thickness;
    e.second_moment_m4 = *thickness * std::pow(*width, 3) / 12;  // bending in the plane of the width
    e.depth_m = width;
  } else {
    e.area_m2 = area;
    e.second_moment_m4 = second_moment;
  }
  if (e.density_kg_m3 && !e.area_m2)
    t.fail("density_kg_m3", "needs the section's area (area_mm2, or width_mm and thickness_mm) to give a mass");

  if (t.has("mode_frequencies_Hz")) {
    e.frequencies_Hz = t.numbers("mode_frequencies_Hz");
    if (e.frequencies_Hz.empty())
      t.fail("mode_frequencies_Hz",
             "is empty; give the tap test's peaks in Hz, lowest first (fourbar tap prints them)");
    double previous = 0;
    for (std::size_t i = 0; i < e.frequencies_Hz.size(); ++i) {
      const double f = e.frequencies_Hz[i];
      if (!(f > 0))
        t.fail("mode_frequencies_Hz", "[" + std::to_string(i) + "] = " + format_number(f) +
                                          " must be > 0 Hz; give the tap test's peaks in Hz, lowest first "
                                          "(fourbar tap REC prints them)");
      if (!(f < 1e6))
        t.fail("mode_frequencies_Hz", "[" + std::to_string(i) + "] = " + format_number(f) +
                                          " Hz is beyond any link's bending mode (< 1 MHz); give the peaks in Hz");
      if (!(f > previous))
        t.fail("mode_frequencies_Hz",
               "must increase (lowest mode first): " + format_number(previous) + " then " + format_number(f) + " Hz");
      previous = f;
    }
  } else {
    const bool stiff = e.youngs_modulus_Pa && e.second_moment_m4;
    if (!stiff) {
      const char* key = e.youngs_modulus_Pa ? (width ? "width_mm" : "second_moment_mm4") : "E_GPa";
      t.fail(key, std::string("is missing: the table ") + kNoStiffness);
    }
  }
  if (t.has("damping_ratios")) {
    e.damping_ratios = t.numbers("damping_ratios");
    for (std::size_t i = 0; i < e.damping_ratios.size(); ++i) {
      const double z = e.damping_ratios[i];
      if (!(z >= 0 && z < 1))
        t.fail("damping_ratios", "[" + std::to_string(i) + "] = " + format_number(z) +
                                     " must lie in [0, 1): a link rings with ζ of about 0.001–0.05 (a tap test "
                                     "measures it); ζ >= 1 would not ring at all");
    }
  }
  const long long fallback = e.frequencies_Hz.empty() ? 4 : static_cast<long long>(e.frequencies_Hz.size());
  e.modes = static_cast<int>(t.integer("modes", 1, 16, fallback));
  if (!e.frequencies_Hz.empty() && e.modes != static_cast<int>(e.frequencies_Hz.size()))
    t.fail("modes", "= " + std::to_string(e.modes) + " but mode_frequencies_Hz has " +
                        std::to_string(e.frequencies_Hz.size()) + " values; give one frequency per mode");
  if (e.damping_ratios.size() > static_cast<std::size_t>(e.modes))
    t.fail("damping_ratios", "has " + std::to_string(e.damping_ratios.size()) + " values for " +
                                 std::to_string(e.modes) + " modes; give at most one per mode");
  t.finish();
  return e;
}

}  // namespace fourbar
