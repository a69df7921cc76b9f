#pragma once
// The impact law (thesis ch. 5): momentum exchange at the pin–bushing contact
// with Newton's restitution on the normal relative velocity, for the smooth,
// rough (no slip) and stick-slip (Coulomb) cases of eq. 5.4-1.
//
// Let W = [l3·u3⊥, −(B − O4)⊥] map (ω3, ω4) to the relative velocity of pin and
// bushing at B, M = diag(I_A3, I_O4) and K = W·M⁻¹·Wᵀ (the contact's inverse
// mass). An impulse P = −F·n + f·t on the pin (−P on the rocker) changes the
// rates by M⁻¹·Wᵀ·P and the relative velocity by K·P. The crank speed is held
// by the motor, whose angular impulse τ̂ = m3·l2·S3·cos(θ2−θ3)·Δω3 − P·(l2·u2⊥)
// does work ω2·τ̂ (THESIS-ERRATA: "the motor supplies an angular impulse").
//   smooth:  f = 0, F = (1+e)·v_n/K_nn                      (eq. 5.4-2, μ0 = 0)
//   rough:   v_t⁺ = 0 and v_n⁺ = −e·v_n (2×2 solve)         (eq. 5.4-3)
//   slip:    f = −σ·μ·F, σ = sign(v_t) before the impact    (eq. 5.4-2, μ11, μ12)
// The thesis's f is the tangential impulse on the bushing along t, i.e. −f here.

#include "sim/record/impact_result.hpp"
#include "sim/three_mode/model.hpp"
#include "sim/three_mode/settings.hpp"

namespace fourbar {

struct ImpactLaw {
  double restitution = 1.0;
  ContactLaw contact = ContactLaw::smooth;
  double friction_coefficient = 0.0;
};

/// Resolves one impact at the current configuration (positions unchanged).
/// `before` must have the pin approaching the wall (normal speed > 0) for a
/// physical impact; with normal speed ≤ 0 the law returns a zero impulse.
ImpactResult resolve_impact(const ClearanceModel& model, const CrankState& crank, const LinkMotion& before,
                            const ImpactLaw& law);

/// Applies an impulse P (on the pin; −P on the rocker) and reports the result
/// fields that follow from it (rates after, speeds, motor impulse, loss).
ImpactResult apply_impulse(const ClearanceModel& model, const CrankState& crank, const LinkMotion& before,
                           double normal_impulse_Ns, double tangential_impulse_Ns);

}  // namespace fourbar
