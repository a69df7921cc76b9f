#pragma once
// Samples tagged with their crank angle → whole revolutions on a uniform
// crank-angle grid (θ_k = θ_start ± 2π(r + k/N)), for synchronous averaging
// and the periodic integration. A stand-in for acquire's resampler, kept
// separate so that one can replace it: it needs only the per-sample crank
// angle (continuous, strictly increasing) and the channel values.
//
// Interpolation: 4-point Lagrange cubic in the angle (non-uniform nodes),
// error O(Δθ⁴·f⁗). Band-limit the channel below N/2 orders first (the FFT
// filter's low-pass), or the grid aliases it.

#include <span>
#include <vector>

namespace fourbar {

class RevolutionResampler {
 public:
  /// Plans the grid for this crank-angle track: every revolution whose grid
  /// points the samples cover (a point up to one sample step beyond the
  /// first or last sample counts as covered: a revolution cut at a crank
  /// pulse starts just before the first sample). `direction` −1: a clockwise
  /// crank, the angle decreasing and the grid running θ_start − 2π(r + k/N).
  /// Throws InputError when the angle is not finite, not strictly monotonic
  /// in `direction`, N < 4, or no whole revolution fits.
  RevolutionResampler(std::span<const double> crank_angle_rad, std::size_t grid_points_per_rev, double start_angle_rad,
                      double direction = 1.0);

  /// Plans the same grid (points per revolution, start, direction) for
  /// another track, as the constructor would, in the memory of this one
  /// (no allocation once it has held a track as long: for chunk after chunk).
  void plan(std::span<const double> crank_angle_rad);

  std::size_t grid_points_per_rev() const { return n_; }
  std::size_t revolutions() const { return revs_; }
  /// Index of the first covered revolution (θ_start ± 2π·first is its start).
  long first_revolution() const { return first_; }
  /// Grid angle of point k of covered revolution r (continuous).
  double grid_angle_rad(std::size_t r, std::size_t k) const;

  /// revolutions() × N values, row-major (row = revolution), of a channel with
  /// one value per crank-angle sample.
  std::vector<double> resample(std::span<const double> channel) const;
  /// The same into `out` (resized; its memory reused).
  void resample(std::span<const double> channel, std::vector<double>& out) const;

 private:
  std::size_t n_, revs_ = 0, samples_;
  long first_ = 0;
  double start_, direction_;
  std::vector<std::size_t> base_;       // first stencil sample per grid point
  std::vector<double> weights_;         // 4 per grid point
};

/// The continuation of a crank-locked signal beyond one end of a record by
/// its periodicity in the crank angle: `pad` samples before the first
/// (`before`) or after the last, their angles extrapolated at the end
/// sample's angle step, each value read one or more turns back inside the
/// record (the first or the last revolution), 4-point Lagrange in the angle.
/// A record of whole revolutions in steady state continues seamlessly, so a
/// filter run over the extended record does not ring at its ends (a
/// mirrored record would: α is not symmetric about the cut). Returned in
/// time order. `crank_angle_rad` as for RevolutionResampler; the record must
/// be at least 4 samples long.
std::vector<double> crank_periodic_extension(std::span<const double> crank_angle_rad, std::span<const double> values,
                                             std::size_t pad, double direction, bool before);

}  // namespace fourbar
