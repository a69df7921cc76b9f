#pragma once
// The analyze stage for one recording, end to end — what `fourbar analyze`
// and the comparison report call:
//
//   acquire (acquire/acquisition.hpp): calibrated channels, crank pulses,
//     θ2, ω2, α2 for every sample inside a complete revolution;
//   per link (coupler, rocker) with a tangential channel: restore an
//     AC-coupled sensor, convert to α with the measured crank state, the
//     nominal link angle, the sensor position and gravity (conversion.hpp;
//     thesis eq. 7.2.1-6 / 7.2.2-1 done in full), zero-phase FFT filter,
//     onto the crank-angle grid, each revolution integrated to ω (periodic,
//     the constant from the mechanism's topology: no drift), synchronous
//     average with the spread per angle;
//   per normal channel: ω² from the centripetal term, a check on |ω|;
//   amplitude spectra of the converted α on frequency and order axes.
//
// Memory is bounded whatever the length: the samples are analysed as acquire
// streams them, in chunks of whole revolutions, each with at least half a
// filter kernel of real samples on both sides, so a chunk's revolutions get
// the values a whole-record filter would give (at the ends of a pulse-train
// segment the record is mirrored). Revolutions are averaged as they come
// (Welford); per-revolution grids are kept only when asked for, or handed to
// a RevolutionObserver.
//
// Errors: InputError (exit 2) for a missing coupler tangential channel, a
// sensor outside its link, a filter band at or above the Nyquist frequency,
// a window parameter out of range, a record too short for the filter;
// raised before the long sample pass where the inputs allow.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "acquire/acquisition.hpp"
#include "analyze/analysis_defaults.hpp"
#include "analyze/averaging.hpp"
#include "analyze/filter_design.hpp"
#include "analyze/turn_repeat.hpp"
#include "analyze/sensor_mount.hpp"
#include "analyze/setup_check.hpp"
#include "analyze/unseen_speed_change.hpp"

namespace fourbar {

/// How α is obtained from a tangential reading.
enum class ConversionMethod {
  full,    ///< measured crank speed and acceleration, sensor position and offset, gravity, AC-coupling restored
  thesis,  ///< thesis eq. 7.2.1-6 / 7.2.2-1: constant (mean) crank speed, sensor at the far joint, no gravity, as recorded
};

/// How α becomes ω. The first three integrate each revolution on its own in
/// the crank angle (dω/dθ2 = α/ω2, the constant from the mechanism's
/// topology): nothing carries over, so nothing drifts (integration.hpp).
enum class IntegrationMethod {
  spectral,          ///< Fourier, keeping the revolution's mean slope (follows crank-speed changes; default)
  periodic,          ///< Fourier, strictly periodic (rejects a constant α offset; misses speed changes within a turn)
  closed_trapezoid,  ///< trapezoid round the turn, closing error removed (periodic, second order)
  trapezoid,         ///< thesis eq. 7.2.1-8: running trapezoid in time from the nominal ω at a segment's first sample (drifts)
};

const char* to_string(ConversionMethod m);
const char* to_string(IntegrationMethod m);

/// The FFT filter applied to α per sample. Unset values follow the recording.
struct FilterSettings {
  BandType band = BandType::bandpass;
  /// Default (analysis_defaults.hpp): kLowCornerPerCrankHz (0.5) × the mean crank frequency.
  std::optional<double> low_hz;
  /// Default (analysis_defaults.hpp): kHighCornerCapHz (1000 Hz), at most
  /// kHighCornerMaxPerSampleRate (0.4) × the sample rate.
  std::optional<double> high_hz;
  double mains_hz = 0;                  ///< mains comb (notches at k × this, up to Nyquist); 0: none
  double mains_width_hz = 1;            ///< full width of each notch
  WindowSpec window{WindowType::kaiser, 8.0};
  /// Transition width of the windowed-sinc kernel. Default (analysis_defaults.hpp):
  /// kTransitionPerCrankHz (0.15) × the mean crank frequency, widened (with a
  /// warning) when the kernel would be longer than twice the longest
  /// pulse-train segment (shorter segments are left out with a warning).
  /// 0: the ideal bin-wise filter of each chunk (rectangular window only; the thesis's).
  std::optional<double> transition_hz;
};

struct AnalyzeOptions {
  /// Crank angles per revolution N; 0: analysis_defaults::kGridPoints (720),
  /// grown in steps of kGridPointsStep (360) until it holds the pass band
  /// (upper edge ≤ kGridMaxOrdersPerPoint (0.4)·N orders at the fastest revolution).
  std::size_t grid_points_per_rev = 0;
  /// The part of the recording to analyse (--start-s/--end-s; over the manifest's start_s/end_s).
  TimeRange range;
  FilterSettings filter;
  ConversionMethod conversion = ConversionMethod::full;
  IntegrationMethod integration = IntegrationMethod::spectral;
  /// Revolutions left out of the averages at each end of a pulse-train segment.
  std::size_t guard_revolutions = 0;
  /// Keep every revolution's grids in the result (memory: revolutions × N × 4 doubles).
  bool keep_revolutions = false;
  /// Samples per spectrum segment (Hann window, 50 % overlap); 0: the
  /// smallest power of two ≥ 8 revolutions, shortened to fit the longest segment.
  std::size_t spectrum_segment = 0;
  /// Revolutions per processing chunk; 0: automatic (analysis_defaults.hpp):
  /// with a windowed filter as many as fit, with their overlaps, an FFT of
  /// kChunkFftFrames (2^20) frames (doubled while shorter than 8 overlaps);
  /// with the ideal filter about kIdealChunkFrames (2^19) frames, the chunk
  /// being one period. Results do not depend on it.
  std::size_t chunk_revolutions = 0;
  /// Chunks analysed at once, each on a thread of its own while acquire
  /// reads on (chunked_analysis.hpp); 1: everything in the calling thread.
  /// The result does not depend on it: bit for bit the same.
  unsigned threads = 1;
  bool progress = true;  ///< progress bar on stderr when it is a terminal
  /// Run the set-up check (setup_check.hpp) on the finished analysis.
  bool setup_check = true;
  /// Revolutions of raw signal kept in acquisition.excerpt (AcquireOptions); 0: none.
  std::size_t excerpt_revolutions = 0;

  /// The thesis's processing (§7.2): thesis conversion, ideal (bin-wise,
  /// rectangular) band-pass, running trapezoid. For comparison.
  static AnalyzeOptions thesis_method();
};

/// The normal (centripetal) channel of a link: an independent estimate of ω².
struct NormalCheck {
  std::string channel;
  /// AC-coupled: the sensor lost the mean, which then comes from the
  /// nominal model, so only the variation of ω² is measured.
  bool ac_coupled = false;
  AngleAverage omega_sq_rad2_s2;                  ///< ω² from the normal channel, per grid angle
  std::vector<double> omega_abs_rad_s;            ///< √(mean ω²) from the normal channel (0 where the mean is negative)
  std::vector<double> omega_sq_integrated_rad2_s2;  ///< mean over the revolutions of (integrated ω)², per angle
  double rel_rms_difference = 0;                  ///< RMS(normal − integrated) / RMS(integrated) over the grid
};

/// α and ω of one link (coupler: α3, ω3; rocker: α4, ω4).
struct LinkResult {
  SensedLink link = SensedLink::coupler;
  std::string channel;                      ///< its tangential channel
  AngleAverage alpha_rad_s2, omega_rad_s;   ///< mean and std over the averaged revolutions, per grid angle
  double alpha_rms_rad_s2 = 0, omega_rms_rad_s = 0;  ///< RMS of the mean curves
  double alpha_std_rms_rad_s2 = 0, omega_std_rms_rad_s = 0;  ///< RMS over the grid of the spread
  std::vector<double> alpha_grid, omega_grid;  ///< revolutions × N, row-major (keep_revolutions)
  std::vector<double> alpha_amplitude;      ///< amplitude spectrum of the converted α before the filter (rad/s²)
  TurnRepeat alpha_repeat;                  ///< whether the averaged turns of α repeat every few turns (turn_repeat.hpp)
  std::optional<NormalCheck> normal;
};

/// The spectra's common axes.
struct SpectrumAxes {
  std::vector<double> frequency_hz, order;  ///< order = frequency / mean crank frequency
  std::vector<double> filter_gain;          ///< the α filter's zero-phase response at each frequency
  std::size_t segment_length = 0, segments = 0;
};

struct RecordingAnalysis {
  std::filesystem::path recording, manifest_file, rig_file;
  AcquisitionReport acquisition;            ///< pulses, speed statistics, channel statistics, acquire's warnings; grid_points_per_rev = N
  std::shared_ptr<const Rig> rig;           ///< from the manifest
  double clearance_m = 0;                   ///< from the manifest
  bool clearance_from_rig = false;          ///< the manifest gives no clearance_mm: the rig file's
  AnalyzeOptions options;                   ///< as given
  FilterSpec filter, normal_filter;         ///< as used (defaults resolved); the normal channels' has no low corner
  std::size_t kernel_taps = 0;              ///< of the α filter (0: ideal)
  std::size_t chunk_revolutions = 0;        ///< as used

  std::size_t grid_points_per_rev = 0;           ///< N
  std::vector<double> crank_deg;            ///< the N grid angles: θ2 = pulse angle + direction·360°·k/N
  double crank_direction = 1;               ///< +1 counter-clockwise, −1 clockwise
  std::size_t revolutions = 0;              ///< in the averages
  std::size_t revolutions_clipped = 0;      ///< left out of the averages: a sample hit the input range
  std::vector<std::size_t> revolution_numbers;  ///< acquire's number of each row of the kept grids
  AngleAverage crank_speed_rad_s;           ///< ω2 per grid angle over the averaged revolutions
  double mean_crank_speed_rad_s = 0;        ///< mean ω2 of the averaged revolutions (negative: clockwise)

  std::optional<LinkResult> coupler, rocker;  ///< present when the manifest has the link's tangential channel
  SpectrumAxes spectra;
  std::vector<std::string> warnings;        ///< acquire's and analyze's
  /// The set-up check (options.setup_check); its findings are not in `warnings`.
  std::optional<SetupCheck> setup_check;
  /// One pulse per turn: how much an unseen in-turn speed change of 0.1 %
  /// would put into the first link's averaged α and ω (unseen_speed_change.hpp).
  std::optional<UnseenSpeedSensitivity> unseen_speed;
  SensedLink unseen_speed_link = SensedLink::coupler;
};

/// One analysed revolution, as it is finished (time order).
struct AnalyzedRevolution {
  std::size_t number = 0;                   ///< acquire's revolution number
  bool averaged = false;                    ///< false: a guard or clipped revolution
  std::span<const double> crank_speed_rad_s;  ///< N values
  std::span<const double> alpha3_rad_s2, omega3_rad_s, alpha4_rad_s2, omega4_rad_s;  ///< N each; empty when absent
};

class RevolutionObserver {
 public:
  virtual ~RevolutionObserver() = default;
  /// Called once before the first revolution with the resolved settings (N,
  /// crank_deg, filters) and acquire's report so far (pulses, speed statistics).
  virtual void on_start(const RecordingAnalysis&) {}
  virtual void on_revolution(const AnalyzedRevolution&) = 0;
};

/// Checks the options that need no recording (window parameters, corners
/// given as non-positive, N < 4 …). InputError naming the option.
void validate_options(const AnalyzeOptions& options);

/// Acquires and analyses `recording` with its manifest (`manifest` empty:
/// the sidecar REC.toml). `observer` (optional) receives every revolution.
RecordingAnalysis analyze_recording(const std::filesystem::path& recording, const std::filesystem::path& manifest,
                                    const AnalyzeOptions& options, RevolutionObserver* observer = nullptr);

}  // namespace fourbar
