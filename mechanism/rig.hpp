#pragma once
// The rig: an immutable, validated description of one four-bar mechanism.
//
// Geometry (DESIGN.md conventions): O2 = (0, 0) crank pivot, O4 = (l1, 0)
// rocker pivot, so the ground line O2→O4 is the +x axis; link angles are
// measured counter-clockwise from it. Gravity acts along −y with magnitude
// `gravity_m_s2` (0 for a rig lying flat). Mass centres lie on the link lines:
// the crank's at S2 from O2, the coupler's at S3 from the crank pin A, the
// rocker's at S4 from O4. All values SI.

#include <filesystem>
#include <optional>
#include <string>

#include "mechanism/link_elasticity.hpp"

namespace fourbar {

/// One moving link. `inertia_cg_kg_m2` is about the mass centre.
struct Link {
  double length_m = 0;
  double mass_centre_m = 0;  ///< from the link's first joint along the link
  double mass_kg = 0;
  double inertia_cg_kg_m2 = 0;

  /// Moment of inertia about the link's first joint (I_G + m·S²).
  double inertia_about_joint() const { return inertia_cg_kg_m2 + mass_kg * mass_centre_m * mass_centre_m; }
};

/// Which of the two assemblies of the loop the rig is built in.
/// `open`: the coupler–rocker joint B lies counter-clockwise of the line from
/// the crank pin A to the rocker pivot O4 (for a crank-rocker drawn with the
/// joints above the ground line this is the convex, uncrossed quadrilateral).
enum class Assembly { open, crossed };

/// Grashof classification of the linkage with the crank as input.
enum class GrashofClass { crank_rocker, double_crank, double_rocker, rocker_crank, change_point, non_grashof };

const char* to_string(Assembly a);
const char* to_string(GrashofClass c);

/// The coupler–rocker bearing's pin and bushing as elastic bodies, for the
/// compliant contact model's stiffness (rig file `[clearance]`, all optional;
/// validated at load: radii, length and moduli > 0, Poisson ratios in
/// (−1, 0.5), bushing radius = pin radius + radial clearance), and the
/// lubricant's dynamic viscosity when the bearing is lubricated (> 0; needs
/// the length and a radius: the hydrodynamic film force depends on both).
struct BearingBodies {
  std::optional<double> pin_radius_m, bushing_radius_m, length_m;
  std::optional<double> pin_youngs_modulus_Pa, pin_poisson_ratio;
  std::optional<double> bushing_youngs_modulus_Pa, bushing_poisson_ratio;
  std::optional<double> lubricant_viscosity_Pa_s;
};

struct Rig {
  std::string name;
  double ground_length_m = 0;  ///< l1, O2→O4
  Link crank;                  ///< l2, S2, m2, I_G2
  Link coupler;                ///< l3, S3, m3, I_G3
  Link rocker;                 ///< l4, S4, m4, I_G4
  double gravity_m_s2 = 9.80665;
  Assembly assembly = Assembly::open;
  double radial_clearance_m = 0;  ///< coupler–rocker bearing, pin vs bushing
  BearingBodies bearing;          ///< the bearing's bodies (compliant contact only)
  /// `[coupler.elastic]`, `[rocker.elastic]`: absent = a rigid link.
  std::optional<LinkElasticity> coupler_elastic, rocker_elastic;
  std::filesystem::path source;   ///< the file it was read from (may be empty)

  /// +1 for the open assembly, −1 for the crossed one.
  double assembly_sign() const { return assembly == Assembly::open ? 1.0 : -1.0; }
};

/// Grashof class from the four lengths.
GrashofClass grashof_class(const Rig& rig);

/// Checks that every value is physical and that the loop assembles at every
/// crank angle (the crank turns fully, never reaching a toggle). Throws
/// InputError naming `rig.source`, the key and the value.
void validate_rig(const Rig& rig);

/// How close the loop comes to a toggle, as a distance (m): the least
/// distance by which the crank pin to rocker pivot distance (|l1 − l2| …
/// l1 + l2 over a turn) stays inside the coupler–rocker reach (|l3 − l4| …
/// l3 + l4). A radial clearance ξ moves the rocker end by up to ξ, so the
/// clearance model needs ξ below this margin (issue 7: beyond it the loop
/// with the pin on the bushing wall cannot close and the run is garbage).
double toggle_margin_m(const Rig& rig);

/// Reads and validates a rig TOML file (keys in docs/reference.md "Rig file").
Rig load_rig(const std::filesystem::path& file);

/// The thesis rig of Table 6.1 / 7.1 (clearance 0.254 mm), for tests and benches.
Rig thesis_rig();

}  // namespace fourbar
