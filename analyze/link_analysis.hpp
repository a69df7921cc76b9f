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
};

struct LinkAnalysis {
  SensedLink link = SensedLink::coupler;
  std::vector<double> alpha_rad_s2;  ///< per sample: converted and filtered
  std::size_t points_per_rev = 0, revolutions = 0;
  long first_revolution = 0;         ///< index of grid revolution 0 (see RevolutionResampler)
  std::vector<double> alpha_grid, omega_grid, crank_speed_grid;  ///< revolutions × N, row-major
  AngleAverage alpha, omega;         ///< over the revolutions
};

/// Runs the chain on a whole record held in memory. Throws InputError for a
/// bad mount, filter or crank track.
LinkAnalysis analyze_tangential_channel(const Rig& rig, const AccelerometerMount& mount, const CrankTrack& crank,
                                        double sample_rate_hz, std::span<const double> reading_m_s2,
                                        const LinkAnalysisOptions& options);

}  // namespace fourbar
