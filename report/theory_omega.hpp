#pragma once
// The clearance model's ω made the way a measurement's ω is made.
//
// analyze cannot measure ω: it integrates the measured α revolution by
// revolution in the crank angle (analyze/integration.hpp), with the constant
// from the mechanism's topology (mean ω/ω2 over the turn = the link's turns
// per crank turn, 0 for the rocking coupler and rocker) and, by default, the
// revolution's mean slope kept as a straight line. The model's sampled ω has
// what that integration cannot see: the turn's net rotation of the link
// through the clearance (Δθ/T, a per-turn offset) and a start value that
// carries over from the turn before. Drawn beside the measured band, the
// sampled ω made the model's band several times wider and its mean wander
// over the turn (issue 26; mostly the pass band's ideal filter over the 20
// turns one after the other). Here the model's α revolutions, before the
// pass band, go through the same integration as the measurement's, so that
// the two bands compare like with like (sample session: model/measured band
// 0.8-1.1; about 5 before, as filed). The nominal response is left as it is.

#include "analyze/pipeline.hpp"
#include "compare/matched_theory.hpp"
#include "mechanism/rig.hpp"

namespace fourbar {

/// Replaces the model's ω3 and ω4 revolutions, and their average and spread,
/// by its α3 and α4 revolutions integrated as analyze integrates a recording
/// with `method` (spectral: mean slope kept; periodic; closed trapezoid). The
/// thesis's running trapezoid (`trapezoid`) drifts in time and has no
/// per-turn counterpart: the sampled ω is kept then. Returns whether it was
/// replaced.
bool integrate_theory_omega(MatchedTheory& theory, const Rig& rig, IntegrationMethod method);

}  // namespace fourbar
