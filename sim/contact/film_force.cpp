#include "sim/contact/film_force.hpp"

#include <cmath>

#include "common/units.hpp"

namespace fourbar {

const char* to_string(FilmExtent f) {
  switch (f) {
    case FilmExtent::cavitated: return "cavitated";
    case FilmExtent::pinkus_sternlicht: return "pinkus-sternlicht";
    case FilmExtent::full: return "full";
  }
  return "?";
}

namespace {

/// Sommerfeld's substitution for 1 − ε·cos θ: tan(ψ/2) = k·tan(θ/2),
/// k = √((1 + ε)/(1 − ε)); continuous and increasing for θ ∈ (−2π, 2π).
double sommerfeld_angle(double theta, double k) {
  return 2.0 * std::atan2(k * std::sin(0.5 * theta), std::cos(0.5 * theta));
}

/// With it, dθ/(1 − ε cos θ) = dψ/√(1 − ε²) and
///   ∫ cos²θ/s³ dθ = (1 − ε²)^(−5/2)·∫ (cos ψ + ε)² dψ
///   ∫ sin θ cos θ/s³ dθ = (1 − ε²)^(−2)·∫ sin ψ·(cos ψ + ε) dψ
///   ∫ sin²θ/s³ dθ = (1 − ε²)^(−3/2)·∫ sin²ψ dψ
/// (s = 1 − ε cos θ); the antiderivatives in ψ:
struct Antiderivatives {
  double cc, sc, ss;
};
Antiderivatives antiderivatives(double psi, double eps) {
  const double s = std::sin(psi), c = std::cos(psi), s2 = std::sin(2.0 * psi);
  return {0.5 * psi + 0.25 * s2 + 2.0 * eps * s + eps * eps * psi, 0.5 * s * s - eps * c, 0.5 * psi - 0.25 * s2};
}

}  // namespace

FilmForce short_bearing_force(const JournalFilm& f, double eps, double eps_rate, double eps_whirl) {
  double a = -units::kPi, b = units::kPi;  // the film's extent in θ
  switch (f.extent) {
    case FilmExtent::full: break;
    case FilmExtent::pinkus_sternlicht: b = 0; break;
    case FilmExtent::cavitated: {
      if (eps_rate == 0 && eps_whirl == 0) return {};
      const double centre = std::atan2(-eps_whirl, 2.0 * eps_rate);
      a = centre - 0.5 * units::kPi;
      b = centre + 0.5 * units::kPi;
      break;
    }
  }
  const double q = 1.0 - eps * eps;
  const double k = std::sqrt((1.0 + eps) / (1.0 - eps));
  const Antiderivatives A = antiderivatives(sommerfeld_angle(a, k), eps);
  const Antiderivatives B = antiderivatives(sommerfeld_angle(b, k), eps);
  const double sq = std::sqrt(q);
  const double i_cc = (B.cc - A.cc) / (q * q * sq);
  const double i_sc = (B.sc - A.sc) / (q * q);
  const double i_ss = (B.ss - A.ss) / (q * sq);
  const double g = f.viscosity_Pa_s * f.radius_m * f.length_m * f.length_m * f.length_m /
                   (2.0 * f.clearance_m * f.clearance_m);
  return {-g * (2.0 * eps_rate * i_cc - eps_whirl * i_sc), -g * (2.0 * eps_rate * i_sc - eps_whirl * i_ss)};
}

double film_weight(const JournalFilm& f, double eps) {
  if (eps <= f.break_eccentricity) return 1.0;
  if (eps >= 1.0) return 0.0;
  const double x = (eps - f.break_eccentricity) / (1.0 - f.break_eccentricity);
  return 1.0 - x * x * (3.0 - 2.0 * x);
}

FilmForce film_force(const JournalFilm& f, double eps, double eps_rate, double eps_whirl) {
  if (!(f.viscosity_Pa_s > 0) || eps >= 1.0) return {};
  if (eps <= f.break_eccentricity) return short_bearing_force(f, eps, eps_rate, eps_whirl);
  // Beyond ε_t: the film frozen there (ε·ω̄ taken at ε_t), faded out.
  const double et = f.break_eccentricity;
  const FilmForce frozen = short_bearing_force(f, et, eps_rate, eps_whirl * (et / eps));
  const double w = film_weight(f, eps);
  return {w * frozen.radial_N, w * frozen.tangential_N};
}

}  // namespace fourbar
