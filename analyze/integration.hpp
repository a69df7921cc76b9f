#pragma once
// Angular acceleration → angular velocity.
//
// The thesis (§7.2.1, eq. 7.2.1-8) integrates the sampled α with the plain
// trapezoid rule from a start value: any offset in α (sensor offset,
// gravity, conversion error) and the noise accumulate, which is the "offset
// at the ends of the velocity curves" it reports (ch. 8). Here the
// integration runs over each revolution in the crank-angle domain, where the
// steady-state motion is periodic:
//   dω/dθ2 = α/ω2  (ω2 the measured crank speed at that angle), ω periodic,
// and the constant is fixed by the mechanism's topology, not by a start
// value: over one crank turn a rocking link returns to its angle and a fully
// rotating link gains one turn, so (1/2π)∮ ω/ω2 dθ2 = Δθ_link/Δθ2 = `turns`
// (0 or 1). Nothing carries over from one revolution to the next, so there
// is no drift however long the record.
//   spectral: Ω_m = G_m/(j·m) for the Fourier coefficients G of α/ω2 (exact
//             for band-limited signals; the Nyquist harmonic is dropped);
//   closed trapezoid: trapezoid rule round the revolution, its closing error
//             removed linearly (second order).
// Strict periodicity drops the mean of dω/dθ2 over the turn: right in steady
// state, and it rejects a constant offset in α; but when the crank speed
// changes within the revolution, the link's ω changes over the turn too
// (ω = ω2·dθ/dθ2), which `keep_slope` follows.

#include <span>
#include <vector>

#include "analyze/fftw_plan.hpp"
#include "analyze/sensor_mount.hpp"

namespace fourbar {

/// Thesis eq. 7.2.1-8: cumulative trapezoid of uniformly spaced y (spacing
/// `step`), out[0] = initial. `out` may alias `y`.
void cumulative_trapezoid(std::span<const double> y, double step, double initial, std::span<double> out);

/// Link turns per crank turn in the nominal mechanism (Δθ_link/Δθ2 over one
/// revolution): 0 for a rocking link, 1 for one that turns with the crank.
int link_turns_per_crank_turn(const Rig& rig, SensedLink link);

enum class PeriodicMethod { spectral, closed_trapezoid };

/// Integrates revolutions sampled on a uniform crank-angle grid of N points
/// (θ2_k = θ_start + 2πk/N, increasing). Plans are made once per N.
class PeriodicIntegrator {
 public:
  explicit PeriodicIntegrator(std::size_t grid_points_per_rev);
  std::size_t grid_points_per_rev() const { return n_; }

  /// ω on the grid from α and the crank speed ω2 on the grid (same sign
  /// throughout; all spans N long; `omega` may alias `alpha`).
  /// `keep_slope`: keep the mean of dω/dθ2 over the revolution (the net
  /// change of ω over the turn when the crank speed changes: ω of a link
  /// scales with ω2) as a straight line instead of dropping it. It follows a
  /// crank speed that drifts within the revolution (measured: single
  /// revolutions 30× closer to the truth at ±2 % speed fluctuation over 17
  /// revolutions), but a constant offset in α then leaves a sawtooth, and
  /// white noise in α enters ω with twice the variance.
  void integrate(PeriodicMethod method, std::span<const double> alpha, std::span<const double> crank_speed,
                 double turns, std::span<double> omega, bool keep_slope = false);

 private:
  std::size_t n_;
  RealFft fft_;
  std::vector<double> g_;
};

/// Normal-channel anchor: the constant c with mean((ω̃ + c)²) = mean(ω²_measured)
/// for a zero-mean integrated ω̃ (same grid), the root on the side of
/// `sign_hint`; 0 when the measured mean square is below mean(ω̃²).
double omega_offset_from_normal(std::span<const double> omega_zero_mean, std::span<const double> omega_sq_measured,
                                double sign_hint);

}  // namespace fourbar
