#pragma once
// The analysis chain for one tangential accelerometer channel:
//   restore (AC-coupled sensor) → convert to α (measured crank state,
//   nominal link angles, gravity) → zero-phase FFT filter → resample onto
//   the crank-angle grid → integrate each revolution to ω (periodic,
//   constant from the topology) → synchronous average with spread.
// Input is plain data (samples with their crank state), so acquire's output
// plugs in directly.

#include <span>
#include <vector>

#include "analyze/averaging.hpp"
#include "analyze/conversion.hpp"
#include "analyze/fft_filter.hpp"
#include "analyze/integration.hpp"

namespace fourbar {

struct LinkAnalysisOptions {
  FilterSpec filter;                        ///< applied to α per sample (default all-pass)
  Boundary boundary = Boundary::periodic;   ///< whole-record filter boundary
  std::size_t points_per_rev = 720;         ///< crank-angle grid
  double grid_start_rad = 0;                ///< crank angle of grid point 0
  PeriodicMethod integration = PeriodicMethod::spectral;
  /// Revolutions left out of the average at each end of the record (they
  /// stay in the per-revolution grids): the filter rings there, mostly from
  /// mains hum that the record cuts off mid-period. Measured on the thesis rig
  /// at 350 rpm, 60 Hz hum at 10 % of the channel RMS, 1 Hz notches: 2 guard
  /// revolutions halve the averaged α error (tests/analyze/test_accuracy.cpp).
  std::size_t guard_revolutions = 0;
};

struct LinkAnalysis {
  SensedLink link = SensedLink::coupler;
  std::vector<double> alpha_rad_s2;  ///< per sample: converted and filtered
  std::size_t points_per_rev = 0, revolutions = 0;
  long first_revolution = 0;         ///< index of grid revolution 0 (see RevolutionResampler)
  std::vector<double> alpha_grid, omega_grid, crank_speed_grid;  ///< revolutions × N, row-major
  AngleAverage alpha, omega;         ///< over the revolutions, less the guard revolutions
};

/// A normal (centripetal) channel: ω² of the link per sample, filtered (use
/// a low-pass: ω² has a mean), on the grid and averaged. An independent
/// check of the integrated ω (|ω| = √ω²). For a rocking link the mean ω is
/// fixed exactly by the topology, and a normal-channel anchor
/// (omega_offset_from_normal) would only add noise; it pays for a link that
/// turns fully, or when the crank speed is unknown.
struct NormalChannelAnalysis {
  std::size_t points_per_rev = 0, revolutions = 0;
  std::vector<double> omega_sq_grid;  ///< revolutions × N
  AngleAverage omega_sq;  ///< less the guard revolutions
};

/// `link_alpha_rad_s2` (per sample, e.g. LinkAnalysis::alpha_rad_s2) is needed
/// only when the sensor is offset from the link line. The grid follows
/// `options.points_per_rev` and `grid_start_rad`; `options.filter` applies.
NormalChannelAnalysis analyze_normal_channel(const Rig& rig, const AccelerometerMount& mount, const CrankTrack& crank,
                                             double sample_rate_hz, std::span<const double> reading_m_s2,
                                             std::span<const double> link_alpha_rad_s2,
                                             const LinkAnalysisOptions& options);

/// Runs the chain on a whole record held in memory. Throws InputError for a
/// bad mount, filter or crank track.
LinkAnalysis analyze_tangential_channel(const Rig& rig, const AccelerometerMount& mount, const CrankTrack& crank,
                                        double sample_rate_hz, std::span<const double> reading_m_s2,
                                        const LinkAnalysisOptions& options);

}  // namespace fourbar
