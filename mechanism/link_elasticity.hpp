#pragma once
// What the rig file says about a link's elasticity (`[coupler.elastic]`,
// `[rocker.elastic]`; docs/reference.md "Rig file"): either its section and
// material, or the frequencies and damping ratios a tap test measured
// (`fourbar tap REC` prints them), or both (then the measured frequencies set
// the stiffness and the section the mass). The elastic link model
// (sim/flex/rig_elastic_link.hpp) turns this into modes. All values SI.

#include <optional>
#include <vector>

namespace fourbar {

class TomlSection;

struct LinkElasticity {
  int modes = 0;  ///< pinned–pinned bending modes
  std::optional<double> youngs_modulus_Pa;
  std::optional<double> density_kg_m3;  ///< absent: the link's mass_kg spread over its length
  std::optional<double> area_m2;
  std::optional<double> second_moment_m4;  ///< in-plane bending
  std::optional<double> depth_m;           ///< in-plane width (width_mm), for the rotary inertia
  std::vector<double> frequencies_Hz;      ///< measured, lowest first
  std::vector<double> damping_ratios;      ///< per mode; the last repeats; empty: undamped
};

/// Reads and checks one `[<link>.elastic]` table: exit-2 errors name the key
/// and the fix (no stiffness, frequencies <= 0 or not increasing, ζ outside
/// [0, 1), more ratios than modes, neither a section nor frequencies).
LinkElasticity read_link_elasticity(TomlSection& table);

}  // namespace fourbar
