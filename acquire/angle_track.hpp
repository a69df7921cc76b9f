#pragma once
// The crank's angle, speed and acceleration at any instant from many edges
// per turn (a tooth wheel or an encoder), for one run of consecutive edges.
//
// Each edge k is at a known crank angle φ_k (its position on the wheel,
// corrected for tooth-spacing errors when they were estimated,
// tooth_spacing.hpp) and a measured time t_k with timing noise. The angles
// are exact and the times noisy, so time is fitted as a function of angle:
// a least-squares cubic spline t(φ) with uniform knots every `knot_spacing`
// edges (banded normal equations, one pass over the edges), C² and smooth
// across the knots. At each edge it gives a smoothed time t̂_k,
// t′ = dt/dφ and t″, hence
//   ω = 1/t′,   α = −t″/t′³.
// Between two edges φ(t) is the quintic Hermite polynomial that matches φ,
// ω and α at both (C² across edges, cheap per sample); since all knots are
// samples of the one spline, the quintics follow it closely. Speed changes
// within the turn are followed up to about a third of the knot rate (knots
// every 30°: the fourth order of the turn); a 60-tooth wheel at 30 dB SNR
// gives the angle to about 0.002° and α2 to a tenth of a once- and
// twice-per-turn change's (test_wheel.cpp).

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "acquire/crank_angle.hpp"

namespace fourbar {

class AngleTrack {
 public:
  struct Knot {
    double time_s = 0, phase_rad = 0, speed_rad_s = 0, accel_rad_s2 = 0;
  };
  /// `times_s` increasing, `phases_rad` increasing, same length ≥ 2;
  /// `knot_spacing`: edges between the spline's knots (≥ 2; mean spacing).
  AngleTrack(std::span<const double> times_s, std::span<const double> phases_rad, std::size_t knot_spacing);

  std::size_t size() const { return knots_.size(); }
  /// Free parameters of the fit (B-spline coefficients; 2 below four edges).
  std::size_t coefficients() const { return coefficients_; }
  const Knot& knot(std::size_t k) const { return knots_[k]; }

  /// Evaluation in increasing time: keeps the interval (and its quintic)
  /// found last, so a sample costs a polynomial, not a search.
  class Cursor {
   public:
    explicit Cursor(const AngleTrack& track) : track_(&track) {}
    CrankPoint at(double time_s);
    /// Crank motion where the phase is `phase_rad` (phases in increasing
    /// order are cheapest): Newton on the interval's quintic.
    CrankPoint at_phase(double phase_rad);

   private:
    void load(std::size_t k);
    const AngleTrack* track_;
    std::size_t k_ = static_cast<std::size_t>(-1);
    double t0_ = 0, inv_h_ = 0, phase0_ = 0;
    double c_[6] = {};
  };

  /// Crank motion where the phase is `phase_rad` (a search, then Newton).
  CrankPoint at_phase(double phase_rad) const { return Cursor(*this).at_phase(phase_rad); }

 private:
  std::vector<Knot> knots_;
  std::size_t coefficients_ = 2;
};

}  // namespace fourbar

namespace fourbar {

/// Least-squares cubic y ≈ q0 + q1·s + q2·s² + q3·s³ with s = (x − x0)/scale.
std::array<double, 4> fit_cubic(std::span<const double> x, std::span<const double> y, double x0, double scale);

}  // namespace fourbar
