#pragma once
// The integrators' own options: which library advances the three-mode
// model's smooth phases and which method advances the compliant model. They
// are the integrators' vocabulary, not the scene's: ClearanceSettings
// (settings.hpp) holds one of each, and the integrators need nothing else
// from it.

namespace fourbar {

/// Which integrator library advances the smooth phases.
enum class IntegratorKind {
  cvode,  ///< SUNDIALS CVODE, variable-order Adams–Moulton (orders 1–12)
  odeint  ///< Boost.Odeint, Dormand–Prince 5(4) with dense output
};

/// Which method advances the compliant model. CVODE's BDF with Newton
/// iteration is the product's (the contact is stiff: docs/compliant.md "Why
/// BDF"); the two Adams modes and Radau IIA exist for bench_compliant's
/// comparison and have no scene key.
enum class StiffMethod {
  bdf,                ///< BDF orders 1–5, Newton iteration, dense Jacobian
  adams_fixed_point,  ///< Adams–Moulton orders 1–12, fixed-point (functional) iteration
  adams_newton,       ///< Adams–Moulton orders 1–12, Newton iteration, dense Jacobian
  radau5              ///< Radau IIA, 3 stages, order 5 (not CVODE: radau_integrator.hpp)
};

inline const char* to_string(IntegratorKind k) { return k == IntegratorKind::cvode ? "cvode" : "odeint"; }

}  // namespace fourbar
