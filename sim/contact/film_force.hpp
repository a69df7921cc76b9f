#pragma once
// The lubricated bearing's hydrodynamic film force: the short-bearing
// (Ocvirk) solution of Reynolds' equation, as Pinkus & Sternlicht give it
// and as Flores et al. use it for clearance joints. Pure functions; the
// compliant simulator adds the force to the dry contact's
// (docs/compliant.md "Lubricated bearing" derives the formulas).
//
// Journal (the pin, on the coupler) of radius R and length L in a bushing
// (on the rocker) with radial clearance c; eccentricity e = ε·c along n (from
// the bushing centre to the pin centre), t = n turned +90°. θ is measured
// from n towards t, so the film is h(θ) = c·(1 − ε·cos θ) (thinnest at
// θ = 0). With ω̄ = ω_pin + ω_bushing − 2·φ̇ (φ the angle of e; Flores's
// ω − 2γ̇ with both rates taken relative to the bushing), the short-bearing
// pressure, zero at both ends z = ±L/2, is
//   p(θ, z) = (3μ/c²)·(L²/4 − z²)·(2ε̇·cos θ − εω̄·sin θ)/(1 − ε·cos θ)³
// and the force on the pin F = −∫∫ p·(cos θ, sin θ)·R dθ dz over the film:
//   F_r = −G·(2ε̇·I_cc − εω̄·I_sc),  F_t = −G·(2ε̇·I_sc − εω̄·I_ss),
//   G = μ·R·L³/(2c²),  I_xy = ∫ x(θ)·y(θ)/(1 − ε·cos θ)³ dθ over the film,
// in closed form through Sommerfeld's substitution. Film extents:
//   cavitated (default): the film where p > 0 (Gümbel's condition applied
//       pointwise: an arc of π centred at θc = atan2(−εω̄, 2ε̇), moving with
//       the rates, cf. Daniel, Machado & Cavalca, Mech. Mach. Theory 99
//       (2016)); continuous in all arguments.
//   pinkus-sternlicht: the fixed π-film θ ∈ [−π, 0], from the thickest to
//       the thinnest film on the side the surfaces drag into when ω̄ > 0:
//       Flores et al.'s formulas, for either sign of ω̄ as they use them,
//         F_r = −G·[2ε²ω̄/(1 − ε²)² + π·ε̇·(1 + 2ε²)/(1 − ε²)^(5/2)]
//         F_t =  G·[π·ε·ω̄/(2·(1 − ε²)^(3/2)) + 4·ε·ε̇/(1 − ε²)²]
//       Equal to the cavitated film when ε̇ = 0 and ω̄ > 0; with ω̄ < 0 the
//       film sits on the diverging side (its rotation term pulls the pin
//       outwards). Mirroring the half film with the sign of ω̄ instead makes
//       F_t jump when ω̄ changes sign while ε̇ ≠ 0, and the BDF integrator
//       stalls on that jump (measured on the thesis rig), so it is not offered.
//   full: the whole 2π film, negative pressures kept (Sommerfeld).

namespace fourbar {

enum class FilmExtent { cavitated, pinkus_sternlicht, full };

const char* to_string(FilmExtent f);

struct JournalFilm {
  double viscosity_Pa_s = 0;  ///< μ; 0 = a dry bearing
  double radius_m = 0;        ///< R, the pin's
  double length_m = 0;        ///< L
  double clearance_m = 0;     ///< c
  FilmExtent extent = FilmExtent::cavitated;
  /// ε_t: the film carries the full short-bearing force up to here, fades
  /// to none at the wall (ε = 1), where the dry contact begins.
  double break_eccentricity = 0.95;
};

/// Force on the pin along n (radial) and t (tangential), N.
struct FilmForce {
  double radial_N = 0, tangential_N = 0;
};

/// The short-bearing force at ε ∈ [0, 1), ε̇ (1/s) and εω̄ (1/s) above.
FilmForce short_bearing_force(const JournalFilm& film, double eps, double eps_rate, double eps_whirl);

/// w(ε): 1 up to ε_t, the C¹ ramp 1 − (3x² − 2x³) with x = (ε − ε_t)/(1 − ε_t)
/// to 0 at the wall, 0 beyond.
double film_weight(const JournalFilm& film, double eps);

/// The force the simulator applies: the short-bearing force up to ε_t; from
/// ε_t to the wall the force of the film frozen at ε_t (same rates) times
/// w(ε); none in dry contact (ε ≥ 1). Continuous in ε, ε̇ and εω̄.
FilmForce film_force(const JournalFilm& film, double eps, double eps_rate, double eps_whirl);

}  // namespace fourbar
