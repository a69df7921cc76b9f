#pragma once
// The compliant contact's stiffness K (N/mⁿ) from the bearing's bodies: a
// pin of radius R_p in a bushing of radius R_b = R_p + ΔR (ΔR the radial
// clearance ξ), bearing length L, Young's moduli E and Poisson ratios ν.
//
// Law used (conformal cylinders, internal contact): Liu, Zhang, Bai & Yang
// (2006/2007, "A simple formula of the contact force between the pin and the
// hole", the law of their elastic-foundation analysis of a pin in a hole):
//   F = ½·π·E*·L·δ·√(δ / (2·(ΔR + δ)))
// with the composite modulus 1/E* = (1 − ν_p²)/E_p + (1 − ν_b²)/E_b. For
// δ ≪ ΔR (every penetration this model meets: δ is micrometres, ΔR tenths of
// a millimetre) it is the power law F = K·δ^1.5 with
//   K = π·E*·L / (2·√(2·ΔR)),   n = 1.5,
// which is what the compliant model uses. It depends on the clearance and
// the length but not on the radius itself (the radius enters the exact
// conformal solution only through ΔR at this order).
// Cited from memory, not checked against the paper here (no copy at hand):
// the form and the small-penetration limit above are as the clearance-joint
// literature quotes it (e.g. Bai & Zhao; Flores's surveys of cylindrical
// contact laws). Alternatives not implemented: the Hertz sphere law with the
// conformal radius R* = R_p·R_b/ΔR (Lankarani & Nikravesh 1990; Flores et al.
// 2006), K = (4/3)·E*·√R*, and the implicit ESDU-78035 / Johnson line-contact
// law (logarithmic, no power form). For the thesis rig's bearing with steel
// on steel (L = 10 mm, ξ = 0.254 mm) this law and the sphere law with
// R_p = 10 mm give K = 8.0e10 and 9.8e10 N/m^1.5 (same order).

#include <functional>
#include <string>

#include "common/toml_section.hpp"
#include "mechanism/rig.hpp"
#include "sim/three_mode/settings.hpp"

namespace fourbar {

/// E* from the two bodies' moduli and Poisson ratios.
double composite_modulus_Pa(double pin_E_Pa, double pin_nu, double bushing_E_Pa, double bushing_nu);

/// K = π·E*·L / (2·√(2·ΔR)) (N/m^1.5).
double conformal_cylinder_stiffness(double composite_modulus_Pa, double length_m, double clearance_m);

/// With model = "compliant": fills `settings.compliant.stiffness_N_per_m_n`
/// from the rig's bearing when the scene did not give it (then the exponent
/// must be 1.5), and checks the rig's pin and bushing radii against the
/// clearance the scene uses. Fails on `section` naming the missing or
/// contradicting key.
void resolve_contact_stiffness(TomlSection& section, const Rig& rig, double clearance_m, ClearanceSettings& settings);

/// The same outside a scene (a session's matched theory): `fail(key, what)`
/// reports the problem and must throw.
void resolve_contact_stiffness(const Rig& rig, double clearance_m, ClearanceSettings& settings,
                               const std::function<void(const char* key, const std::string& what)>& fail);

}  // namespace fourbar
