#pragma once
// Pass 3 of acquire: tags each sample with its revolution and the crank
// motion, and resamples each revolution onto the crank-angle grid as soon as
// its last sample is in (4-point Lagrange interpolation between samples).
// Holds only the samples of the revolution being built.

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <vector>

#include "acquire/angle_track.hpp"
#include "acquire/crank_angle.hpp"
#include "acquire/revolution.hpp"
#include "common/units.hpp"

namespace fourbar {

/// One complete revolution to build, in time order.
struct RevolutionPlan {
  std::size_t segment = 0;
  RevolutionCurve curve;              ///< one pulse per turn: the motion; with a track only t0, h, phase0_rad
  std::shared_ptr<const AngleTrack> track;  ///< many edges per turn: the motion (phase as curve.phase0_rad + turned)
  double t_start = 0, t_end = 0;
  bool repaired = false;

  CrankPoint at_fraction(double u) const {
    return track ? track->at_phase(curve.phase0_rad + units::kTwoPi * u) : curve.at_fraction(u);
  }
};

struct GridSettings {
  int points = 360;            ///< N per revolution; 0: no grid (revolutions carry only their times and flags)
  double direction = 1;        ///< +1 counter-clockwise crank, −1 clockwise
  double offset_rad = 0;       ///< crank angle at the pulse
  double sample_rate_hz = 0;
  double start_time_s = 0;     ///< time of frame 0
  std::uint64_t frames = 0;    ///< in the recording
};

class RevolutionBuilder {
 public:
  RevolutionBuilder(std::vector<RevolutionPlan> plan, const GridSettings& grid, std::size_t channels,
                    AcquisitionSink& sink);

  /// Frame `n` (in order, every frame once): `calibrated` holds one value per
  /// channel; `clipped` marks a sample at the input range.
  void push(std::int64_t n, const double* calibrated, bool clipped);
  /// Hands the tagged samples pushed since the last flush to the sink.
  void flush_samples();
  /// After the last frame: builds what is left.
  void finish();

  std::size_t revolutions_clipped() const { return clipped_revolutions_; }

 private:
  void resample(std::size_t r);
  void trim_buffer();

  std::vector<RevolutionPlan> plan_;
  std::vector<std::int64_t> first_frame_, last_frame_;  // frames each revolution's resampling needs
  GridSettings grid_;
  std::size_t channels_;
  AcquisitionSink& sink_;

  std::vector<double> buffer_;  // calibrated frames from buffer_base_ on
  std::int64_t buffer_base_ = 0;
  std::deque<std::int64_t> clipped_frames_;
  std::size_t pending_ = 0, current_ = 0, clipped_revolutions_ = 0;
  Revolution rev_;
  std::optional<AngleTrack::Cursor> cursor_;  // on the current revolution's track
  const AngleTrack* cursor_track_ = nullptr;

  std::vector<double> s_time_, s_crank_, s_omega_, s_alpha_;
  std::vector<std::int64_t> s_rev_;
  std::vector<std::vector<double>> s_ch_;
};

}  // namespace fourbar
