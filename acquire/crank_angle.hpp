#pragma once
// The crank's angle, speed and acceleration at any instant between the
// pulses of one segment — not constant speed within a revolution.
//
// The pulses fix the time t_k at which the crank passes its reference angle
// for the k-th time. Time as a function of the number of turns x, t(x), is
// then known on a uniform grid (x = 0, 1, 2, …), so an interpolating cubic
// B-spline through (k, t_k) gives a smooth t(x) with continuous first and
// second derivatives (Boost.Math cardinal_cubic_b_spline; end slopes from
// one-sided differences, fourth order from five pulses, second from three).
// Its inverse is the crank phase φ(t) = 2π·x(t):
//   ω2 = dφ/dt = 2π / t′(x),   α2 = d²φ/dt² = −2π·t″(x) / t′(x)³.
// Within revolution k, φ(t) is evaluated per sample by the quintic Hermite
// polynomial that matches φ, ω2 and α2 at both pulses (so it is C² across
// pulses and cheap per sample).
//
// What one pulse per revolution can and cannot see: speed changes slower
// than about half the revolution rate (drift, a sinusoidal fluctuation over
// several turns) are followed; a fluctuation that repeats every revolution
// (e.g. from the mechanism's own torque demand) is invisible in the pulse
// times and is averaged out (its Nyquist limit is half a cycle per turn).

#include <array>
#include <memory>
#include <span>
#include <vector>

namespace fourbar {

/// Crank motion at one instant; `phase_rad` counts from the segment's first pulse.
struct CrankPoint {
  double time_s = 0;
  double phase_rad = 0;     ///< φ ≥ 0, increasing with time
  double speed_rad_s = 0;   ///< dφ/dt > 0
  double accel_rad_s2 = 0;  ///< d²φ/dt²
};

/// One revolution of the crank motion, both ways round:
///  • φ(t), a quintic in τ = (t − t0)/h matching φ, ω2, α2 at both pulses,
///    for per-sample evaluation;
///  • t(u) at the fraction u ∈ [0, 1] of the turn, the spline's own cubic on
///    this interval, for points at given crank angles.
struct RevolutionCurve {
  double t0 = 0, h = 0, inv_h = 0;
  double phase0_rad = 0;            ///< φ at t0 (2π·k)
  std::array<double, 6> c{};        ///< φ − phase0 = Σ c_i τ^i
  std::array<double, 4> t_of_u{};   ///< t − t0 = Σ b_i u^i
  /// Crank motion at a time within the revolution (inline: once per sample).
  CrankPoint at(double time_s) const {
    const double tau = (time_s - t0) * inv_h;
    const double p = c[0] + tau * (c[1] + tau * (c[2] + tau * (c[3] + tau * (c[4] + tau * c[5]))));
    const double dp = c[1] + tau * (2 * c[2] + tau * (3 * c[3] + tau * (4 * c[4] + tau * 5 * c[5])));
    const double ddp = 2 * c[2] + tau * (6 * c[3] + tau * (12 * c[4] + tau * 20 * c[5]));
    return {time_s, phase0_rad + p, dp * inv_h, ddp * inv_h * inv_h};
  }
  /// Crank motion where the crank has turned the fraction u of this revolution.
  CrankPoint at_fraction(double u) const;
};

class CrankAngleModel {
 public:
  /// `pulse_times_s`: at least two, increasing, one revolution apart.
  explicit CrankAngleModel(std::vector<double> pulse_times_s);
  ~CrankAngleModel();
  CrankAngleModel(CrankAngleModel&&) noexcept;
  CrankAngleModel& operator=(CrankAngleModel&&) noexcept;

  std::size_t revolutions() const { return times_.size() - 1; }
  double pulse_time(std::size_t k) const { return times_[k]; }

  /// Time, speed and acceleration where the crank has turned `turns`
  /// (0 … revolutions()) since the first pulse.
  CrankPoint at_turns(double turns) const;
  /// The per-sample curve of revolution k (between pulses k and k+1).
  RevolutionCurve revolution(std::size_t k) const;

 private:
  struct Spline;
  std::vector<double> times_;
  std::unique_ptr<Spline> spline_;  // null for a single revolution (constant speed)
};

}  // namespace fourbar
