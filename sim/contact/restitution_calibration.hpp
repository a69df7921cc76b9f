#pragma once
// The restitution a hysteresis-damped contact really gives, and the damping
// that gives a requested one. With F = K·δⁿ·(1 + χ·δ̇), χ = c/v⁻, a mass m
// hitting at v⁻ obeys, in δ = δ*·x, t = (δ*/v⁻)·τ with δ*ⁿ⁺¹ = m·v⁻²/K,
//   x″ = −xⁿ·(1 + c·x′)⁺,   x(0) = 0, x′(0) = 1,
// so the rebound speed ratio depends on c and n only. effective_restitution
// integrates this (CVODE BDF, root finding on x = 0, tolerance 1e-12);
// calibrated_hysteresis inverts it by TOMS 748 on c (once per (e, n) in a
// process, then remembered). This is the default
// damping law ("calibrated"): the published closed forms c(e) are
// approximations of this map, measured in tests/sim/contact/
// test_contact_force.cpp and docs/clearance-model.md "Compliant contact".

namespace fourbar {

/// Rebound / approach speed of the scaled collision above.
double effective_restitution(double hysteresis_factor, double exponent);

/// c with effective_restitution(c, n) = e to ~1e-10 (e in (0, 1]; 0 at e = 1).
double calibrated_hysteresis(double restitution, double exponent);

}  // namespace fourbar
