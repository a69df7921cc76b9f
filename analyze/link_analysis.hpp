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
  std::size_t grid_points_per_rev = 720;
  double start_rad = 0;   ///< crank angle of grid point 0 (the pulse position: 0)
  double direction = 1;   ///< +1: the crank turns counter-clockwise (θ2 increases); −1 clockwise
};

struct ChannelOptions {
  FilterSpec filter;                        ///< per sample (default all-pass)
  Boundary boundary = Boundary::periodic;   ///< whole-record filter boundary
  PeriodicMethod integration = PeriodicMethod::spectral;
  bool keep_slope = false;                  ///< see PeriodicIntegrator::integrate
  /// Revolutions left out of the average at each end of the record (they
  /// stay in the per-revolution grids): the filter rings there, mostly from
  /// mains hum that the record cuts off mid-period. Measured on the thesis rig
  /// at 350 rpm, 60 Hz hum at 10 % of the channel RMS, 1 Hz notches: 2 guard
  /// revolutions halve the averaged α error (tests/analyze/test_accuracy.cpp).
  std::size_t guard_revolutions = 0;
};

/// α and ω of one link on the crank-angle grid, revolution by revolution.
struct LinkGrids {
  std::size_t grid_points_per_rev = 0, revolutions = 0;
  long first_revolution = 0;                   ///< index of grid revolution 0 (see RevolutionResampler)
  std::vector<double> alpha_grid, omega_grid;  ///< revolutions × N, row-major
};

struct LinkAnalysis : LinkGrids {
  SensedLink link = SensedLink::coupler;
  std::vector<double> alpha_rad_s2;  ///< per sample: converted and filtered
  AngleAverage alpha, omega;         ///< over the revolutions, less the guard revolutions
};

/// A normal (centripetal) channel: ω² of the link per sample, filtered (use
/// a low-pass: ω² has a mean), on the grid and averaged. An independent
/// check of the integrated ω (|ω| = √ω²). For a rocking link the mean ω is
/// fixed exactly by the topology, and a normal-channel anchor
/// (omega_offset_from_normal) would only add noise; it pays for a link that
/// turns fully.
struct NormalChannelAnalysis {
  std::size_t grid_points_per_rev = 0, revolutions = 0;
  std::vector<double> omega_sq_grid;  ///< revolutions × N
  AngleAverage omega_sq;              ///< less the guard revolutions
};

/// The nominal-motion tables of both links for one rig (link_motion.hpp),
/// made once and shared by every record (or chunk of a record) analysed.
struct RigTables {
  explicit RigTables(const Rig& rig) : coupler(rig, SensedLink::coupler), rocker(rig, SensedLink::rocker) {}
  const LinkTable& operator[](SensedLink link) const { return link == SensedLink::coupler ? coupler : rocker; }
  LinkTable coupler, rocker;
};

class RecordAnalyzer {
 public:
  /// Plans the grid over the record's crank track (kept by reference: the
  /// spans must outlive the analyzer). `tables`: the rig's nominal-motion
  /// tables when already made (else made here). Throws InputError for a bad
  /// track.
  RecordAnalyzer(const Rig& rig, const CrankTrack& crank, double sample_rate_hz, const AngleGridSpec& grid,
                 std::shared_ptr<const RigTables> tables = nullptr);

  /// Moves the analyzer to another record of the same rig, rate and grid
  /// (the next chunk of a long one), as if made anew for it, in the memory
  /// of this one: the grid and the crank speed on it are planned again
  /// without allocating once a record as long was seen.
  void reset(const CrankTrack& crank);

  const RevolutionResampler& grid() const { return grid_; }
  /// Crank speed ω2 on the grid, revolutions × N.
  const std::vector<double>& crank_speed_grid() const { return speed_grid_; }

  /// A tangential channel: converted → filtered → on the grid and integrated
  /// → averaged. Throws InputError for a bad mount, filter or length.
  LinkAnalysis tangential(const AccelerometerMount& mount, std::span<const double> reading_m_s2,
                          const ChannelOptions& options);

  /// A normal channel. `link_alpha_rad_s2` (per sample, e.g.
  /// LinkAnalysis::alpha_rad_s2) is needed only when the sensor is offset
  /// from the link line; `options.integration` is unused.
  NormalChannelAnalysis normal(const AccelerometerMount& mount, std::span<const double> reading_m_s2,
                               std::span<const double> link_alpha_rad_s2, const ChannelOptions& options);

  // The steps, for callers that filter or average themselves (the streaming
  // pipeline, pipeline.hpp):
  /// Restored (AC-coupled mount) and converted, per sample: α for a
  /// tangential mount, ω² for a normal one (`link_alpha_rad_s2` as in normal()).
  std::vector<double> converted(const AccelerometerMount& mount, std::span<const double> reading_m_s2,
                                std::span<const double> link_alpha_rad_s2 = {});
  /// The same into `out` (one value per sample; may alias the reading).
  void converted(const AccelerometerMount& mount, std::span<const double> reading_m_s2,
                 std::span<const double> link_alpha_rad_s2, std::span<double> out);
  /// Filters `x` (one value per sample) in place with a filter made once per
  /// spec and boundary.
  void filter(const FilterSpec& spec, Boundary boundary, std::span<double> x);
  /// α per sample (filtered) of `link` onto the grid, each revolution
  /// integrated to ω (periodic, the constant from the mechanism's topology).
  LinkGrids on_grid(SensedLink link, std::span<const double> alpha_rad_s2, PeriodicMethod method,
                    bool keep_slope = false);
  /// The same into `out` (its vectors' memory reused).
  void on_grid(SensedLink link, std::span<const double> alpha_rad_s2, PeriodicMethod method, bool keep_slope,
               LinkGrids& out);

 private:
  const Rig& rig_;
  CrankTrack crank_;
  double fs_;
  double direction_;
  RevolutionResampler grid_;
  std::vector<double> speed_grid_;
  std::shared_ptr<const RigTables> tables_;
  struct CachedFilter {
    FilterSpec spec;
    Boundary boundary;
    std::unique_ptr<FftFilter> filter;
  };
  std::vector<CachedFilter> filters_;
};

}  // namespace fourbar
