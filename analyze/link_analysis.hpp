#pragma once
// The analysis chain for the channels of one record:
//   restore (AC-coupled sensor) → convert to α (measured crank state,
//   nominal link angles, gravity) → zero-phase FFT filter → resample onto
//   the crank-angle grid → integrate each revolution to ω (periodic,
//   constant from the topology) → synchronous average with spread.
// Input is plain data (samples with their crank state), so acquire's output
// plugs in directly. What all channels share is made once per record: the
// crank-angle grid, the crank speed on it, the nominal motion of each link
// per sample, the filters (kernel and FFTW plans) per spec.

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "analyze/angle_resampler.hpp"
#include "analyze/averaging.hpp"
#include "analyze/conversion.hpp"
#include "analyze/fft_filter.hpp"
#include "analyze/integration.hpp"

namespace fourbar {

struct AngleGridSpec {
  std::size_t points_per_rev = 720;
  double start_rad = 0;  ///< crank angle of grid point 0 (the pulse position: 0)
};

struct ChannelOptions {
  FilterSpec filter;                        ///< per sample (default all-pass)
  Boundary boundary = Boundary::periodic;   ///< whole-record filter boundary
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
  std::vector<double> alpha_grid, omega_grid;  ///< revolutions × N, row-major
  AngleAverage alpha, omega;         ///< over the revolutions, less the guard revolutions
};

/// A normal (centripetal) channel: ω² of the link per sample, filtered (use
/// a low-pass: ω² has a mean), on the grid and averaged. An independent
/// check of the integrated ω (|ω| = √ω²). For a rocking link the mean ω is
/// fixed exactly by the topology, and a normal-channel anchor
/// (omega_offset_from_normal) would only add noise; it pays for a link that
/// turns fully.
struct NormalChannelAnalysis {
  std::size_t points_per_rev = 0, revolutions = 0;
  std::vector<double> omega_sq_grid;  ///< revolutions × N
  AngleAverage omega_sq;              ///< less the guard revolutions
};

class RecordAnalyzer {
 public:
  /// Plans the grid over the record's crank track (kept by reference: the
  /// spans must outlive the analyzer). Throws InputError for a bad track.
  RecordAnalyzer(const Rig& rig, const CrankTrack& crank, double sample_rate_hz, const AngleGridSpec& grid);

  const RevolutionResampler& grid() const { return grid_; }
  /// Crank speed on the grid, revolutions × N.
  const std::vector<double>& crank_speed_grid() const { return speed_grid_; }

  /// A tangential channel. Throws InputError for a bad mount, filter or length.
  LinkAnalysis tangential(const AccelerometerMount& mount, std::span<const double> reading_m_s2,
                          const ChannelOptions& options);

  /// A normal channel. `link_alpha_rad_s2` (per sample, e.g.
  /// LinkAnalysis::alpha_rad_s2) is needed only when the sensor is offset
  /// from the link line; `options.integration` is unused.
  NormalChannelAnalysis normal(const AccelerometerMount& mount, std::span<const double> reading_m_s2,
                               std::span<const double> link_alpha_rad_s2, const ChannelOptions& options);

 private:
  const std::vector<LinkMotion>& track(SensedLink link);
  FftFilter& filter(const FilterSpec& spec, Boundary boundary);
  /// restore → convert → filter, per sample.
  std::vector<double> converted(const AccelerometerMount& mount, std::span<const double> reading,
                                std::span<const double> link_alpha, const ChannelOptions& options);

  const Rig& rig_;
  CrankTrack crank_;
  double fs_;
  RevolutionResampler grid_;
  std::vector<double> speed_grid_;
  std::optional<NominalTracks> tracks_;  // both links, made on first use
  struct CachedFilter {
    FilterSpec spec;
    Boundary boundary;
    std::unique_ptr<FftFilter> filter;
  };
  std::vector<CachedFilter> filters_;
};

}  // namespace fourbar
