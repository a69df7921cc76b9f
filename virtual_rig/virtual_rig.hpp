#pragma once
// The virtual rig: from a simulated motion, the recording that the lab's
// sensors and DAQ would have produced, its manifest, and the truth beside it.
//
// Per sample (t = i/fs): the motion source gives every link's state; each
// accelerometer sees the specific force at its position along its axis
// (sensor_signal.hpp), times its axis sign; an AC-coupled sensor passes it
// through a first-order high-pass (bilinear transform, run in from twelve
// time constants before t = 0 so the recording starts settled); then
// volts = value·volts_per_unit, plus white noise at the chosen SNR (against
// the signal's RMS about its mean over one mean revolution) and mains hum
// (fundamental and harmonics, common to all accelerometer channels), clipped
// at ±full_scale_V and quantised (integer sample formats by their bit depth,
// float/text by quantisation_bits when given).
// The pulse channel is idle at low_V and rises to high_V (falling polarity:
// the reverse) for width_deg of crank angle from each crossing of angle_deg;
// each edge is a linear ramp of rise_us centred on the crossing time, which
// gets Gaussian jitter; echo pulses and missing pulses can be injected.
// With [recording.wheel] a tooth wheel or a quadrature encoder (and an index)
// takes the pulse channel's place, their edges from the crank drive itself
// (wheel_signal.hpp); the crank speed may change within the turn
// (speed_harmonics_pct, CrankDrive::harmonics).
// With [[recording.link_mode]] (a clearance motion) each tangential sensor
// also sees its link's bending modes rung by the bearing impulses
// (link_ringing.hpp), added to the specific force before the sensor's filter.

#include <filesystem>
#include <string>
#include <vector>

#include "common/provenance.hpp"
#include "sim/scene.hpp"
#include "virtual_rig/motion_source.hpp"
#include "virtual_rig/recording_spec.hpp"

namespace fourbar {

struct VirtualRigOptions {
  bool write_truth = true;
  bool progress = true;  ///< progress bar on stderr when it is a terminal
  bool csv_comments = false;  ///< also `#` provenance lines above the CSV headers (truth, a CSV recording)
};

struct VirtualRigResult {
  std::filesystem::path recording, manifest, truth;
  std::uint64_t frames = 0;
  int channels = 0;
  double sample_rate_hz = 0;
  std::vector<double> pulse_times_s;  ///< leading-edge times of the pulses written (jitter included)
  std::uint64_t clipped_samples = 0;  ///< accelerometer samples clipped at ±full_scale_V
  std::vector<double> noise_V;        ///< per sensor, standard deviation used
  /// Per sensor, with [[recording.link_mode]]: RMS of the links' ringing
  /// over the RMS of the rigid signal (about its mean), both over the recording.
  std::vector<double> ringing_rms_share;
};

/// The crank drive the scene and its [recording] describe (mean speed,
/// start angle, fluctuation).
CrankDrive crank_drive(const Scene& scene, const RecordingSpec& spec);

/// Writes `out` (format by extension), `out` with extension .toml (the
/// manifest) and `<stem>.truth.csv` beside it (unless !write_truth); each
/// CSV with its provenance in NAME.csv.json beside it. All files appear
/// together or not at all.
VirtualRigResult make_virtual_recording(const Scene& scene, const RecordingSpec& spec, const CrankDrive& drive,
                                        const MotionSource& motion, const std::filesystem::path& out,
                                        const Provenance& provenance, const VirtualRigOptions& options = {});

/// `REC.truth.csv` for `REC.wav`.
std::filesystem::path truth_path(const std::filesystem::path& recording);

}  // namespace fourbar
