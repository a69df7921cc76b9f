#pragma once
// What acquire hands to analyze: calibrated accelerometer channels tagged
// with the crank motion sample by sample, and each complete revolution
// resampled onto a uniform crank-angle grid.
//
// Units and conventions (docs/acquire.md):
//   crank_rad     θ2 = crank_offset + direction·φ, where φ ∈ [0, 2π) is the
//                 angle turned since the revolution's pulse; so a revolution
//                 runs from the pulse angle through one turn (not wrapped);
//   omega2_rad_s  dθ2/dt (negative for a clockwise crank), from the pulses;
//   alpha2_rad_s2 d²θ2/dt²;
//   channels      specific force (acceleration minus gravity) along the
//                 sensor's link axis in m/s², axis sign applied: tangential
//                 = +n (link direction turned +90°), normal = +u (away from
//                 the link's first joint). AC-coupled channels are as
//                 recorded, i.e. without their DC part and with the phase
//                 lead of their high-pass (see AcquiredChannel).

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"

namespace fourbar {

struct AcquisitionReport;

/// A calibrated accelerometer channel.
struct AcquiredChannel {
  std::string name;            ///< from the manifest; CSV column "<name>_m_s2"
  ChannelRole role = ChannelRole::ignore;
  int index = 0;               ///< channel in the recording
  double position_m = 0;       ///< along the link from its first joint (coupler: crank pin A; rocker: pivot O4)
  double offset_m = 0;         ///< perpendicular, +n side
  bool ac_coupled = false;
  double highpass_hz = 0;      ///< first-order high-pass corner when ac_coupled

  std::string column() const { return name + "_m_s2"; }
};

/// One complete revolution on a uniform crank-angle grid of N points
/// (j = 0 … N−1 at φ = 2π·j/N; the next revolution's pulse is not repeated).
struct Revolution {
  std::size_t number = 0;      ///< 0-based among the kept revolutions, in time order
  std::size_t segment = 0;     ///< pulse-train segment (a new one after each gap)
  double start_time_s = 0;     ///< its pulse
  double period_s = 0;         ///< to the next pulse
  bool repaired = false;       ///< starts or ends at an inserted (missed) pulse
  bool clipped = false;        ///< some accelerometer sample in it hit the input range

  std::vector<double> crank_rad, time_s, omega2_rad_s, alpha2_rad_s2;  ///< N each
  std::vector<std::vector<double>> channels_m_s2;  ///< [channel][j], channels as in the report

  double speed_rpm() const { return 60.0 / period_s; }
};

/// Consecutive samples that lie inside kept revolutions, with their crank
/// motion (samples outside — before the first pulse, after the last, in a
/// gap — are not passed).
struct SampleBlock {
  std::span<const double> time_s, crank_rad, omega2_rad_s, alpha2_rad_s2;
  std::span<const std::int64_t> revolution;     ///< Revolution::number
  std::vector<std::span<const double>> channels_m_s2;  ///< per channel
  std::size_t size() const { return time_s.size(); }
};

/// Receives the results as they are produced (time order), so that nothing
/// but one revolution needs to be held in memory.
class AcquisitionSink {
 public:
  virtual ~AcquisitionSink() = default;
  /// Once, before the first sample: the report so far (recording, channels,
  /// pulses, revolutions, speed statistics, N; not yet the clipping counts),
  /// so that a consumer can size its work (e.g. filters that follow the
  /// crank speed) before the samples arrive.
  virtual void on_plan(const AcquisitionReport&) {}
  virtual void on_samples(const SampleBlock&) {}
  /// Each complete revolution; its crank-angle grid is empty when the sink
  /// wants none (its time, period, segment and clipping flags are set).
  virtual void on_revolution(const Revolution&) {}
  /// Whether the revolutions are to be resampled onto acquire's crank-angle
  /// grid. A sink that resamples on a grid of its own (analyze) says no.
  virtual bool wants_grid() const { return true; }
};

}  // namespace fourbar
