#pragma once
// The compliant bearing's contact force law: a Hertz-type normal force with
// hysteresis damping along the line of centres, and a regularised Coulomb
// friction force along the wall. Pure functions of the contact's state; the
// compliant simulator (compliant_simulator.hpp) applies them at the pin.
//
// Normal force, penetration δ = |e| − ξ > 0, rate δ̇, approach speed v⁻ (δ̇ at
// the onset of this contact):
//   F_n = K·δⁿ·(1 + χ·δ̇),  χ = c(e)/v⁻,  F_n clamped at 0 (no adhesion)
// with the hysteresis factor c(e) of the chosen law:
//   calibrated (default): c solved so that the collision really rebounds
//                         with e (restitution_calibration.hpp)
//   Hunt & Crossley (1975), as usually quoted:   c = 3(1 − e)/2
//   Lankarani & Nikravesh (1990):                c = 3(1 − e²)/4
//   Flores, Machado, Silva & Martins (2011):     c = 8(1 − e)/(5e)
// (the two older ones from an energy balance valid for e near 1; Flores et
// al.'s from an approximate integration of both phases, meant for any e.
// tests/sim/contact/test_contact_force.cpp measures the restitution each
// one really gives: with n = 1.5 Flores et al.'s gives 0.47 for e = 0.5 and
// 0.26 for 0.3, which is why the calibrated law is the default.) The elastic part K·δⁿ stores
// K·δⁿ⁺¹/(n + 1); everything else is dissipated: (F_n − K·δⁿ)·δ̇ ≥ 0.
//
// Friction (Ambrósio 2002, "modified Coulomb law"): F_t = −μ·c_d(|v_t|)·F_n·
// sign(v_t) with c_d = 0 below v0, 1 above v1. Ambrósio ramps c_d linearly
// between them; here the ramp is the C¹ cubic 3x² − 2x³ (x = (|v_t| − v0)/
// (v1 − v0)), so the force is C¹ in the slip speed and the BDF integrator's
// Newton iteration sees a continuous Jacobian. Chosen over a bristle (LuGre)
// model because it adds no state (a bristle state is itself stiff) and the
// pin sticks only briefly in this bearing; the price is that a pin cannot
// stay stuck: below v0 it creeps (documented in docs/clearance-model.md "Compliant contact").

namespace fourbar {

enum class DampingLaw { calibrated, hunt_crossley, lankarani_nikravesh, flores };

const char* to_string(DampingLaw d);

struct NormalForceLaw {
  double stiffness = 0;   ///< K, N/mⁿ
  double exponent = 1.5;  ///< n
  DampingLaw damping = DampingLaw::calibrated;
  double restitution = 1;  ///< e the damping is derived from
};

/// c(e) above: χ·v⁻ (n, the exponent, matters for the calibrated law only).
/// 0 at e = 1; +∞ for Flores et al. and the calibrated law at e = 0.
double hysteresis_factor(DampingLaw law, double restitution, double exponent = 1.5);

/// K·δⁿ for δ > 0, else 0.
double elastic_force_N(const NormalForceLaw& law, double penetration_m);
/// K·δⁿ⁺¹/(n + 1) for δ > 0, else 0.
double elastic_energy_J(const NormalForceLaw& law, double penetration_m);

/// F_n ≥ 0 at penetration δ, rate δ̇ and damping coefficient χ = c(e)/v⁻ (s/m).
double normal_force_N(const NormalForceLaw& law, double penetration_m, double penetration_rate_m_s,
                      double damping_s_per_m);

struct FrictionLaw {
  double mu = 0;               ///< Coulomb μ
  double stick_speed_m_s = 0;  ///< v0: no friction force below
  double slip_speed_m_s = 0;   ///< v1: full μ·F_n above
};

/// c_d(|v_t|) ∈ [0, 1] above.
double friction_ramp(const FrictionLaw& law, double slip_speed_m_s);
/// Tangential force on the pin along t: −μ·c_d·F_n·sign(v_t).
double friction_force_N(const FrictionLaw& law, double normal_force_N, double slip_speed_m_s);

}  // namespace fourbar
