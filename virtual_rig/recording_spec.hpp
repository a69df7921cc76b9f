#pragma once
// The scene's `[recording]` table: what the virtual rig records and how
// (docs/virtual-rig.md lists every key).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "sim/scene.hpp"
#include "virtual_rig/link_ringing.hpp"
#include "virtual_rig/wheel_signal.hpp"

namespace fourbar {

struct PulseSpec {
  std::string name = "crank_pulse";
  double angle_rad = 0;          ///< crank angle at the leading edge's mid-level crossing
  double low_V = 0, high_V = 5;  ///< idle and pulse levels (swapped for falling polarity)
  PulsePolarity polarity = PulsePolarity::rising;
  double width_rad = 0;          ///< crank angle between leading and trailing edge
  double rise_s = 0;             ///< duration of each edge's linear ramp
  double jitter_s = 0;           ///< standard deviation of each pulse's time
  double noise_V = 0;            ///< standard deviation of white noise on the channel
  std::vector<long long> missing;  ///< pulse numbers left out (0 = first pulse after t = 0)
  std::vector<long long> echo;     ///< pulse numbers followed by an echo pulse
  double echo_delay_s = 0.001;
};

struct RecordingSpec {
  double sample_rate_hz = 0;
  std::optional<double> duration_s;   ///< one of these two
  std::optional<double> revolutions;
  std::optional<std::string> sample_format;  ///< pcm16, pcm24, pcm32, float, double (audio only)
  double full_scale_V = 10;           ///< DAQ input range ±full_scale_V
  std::optional<int> quantisation_bits;  ///< ADC resolution for float/text outputs
  std::optional<double> noise_snr_db; ///< white noise per accelerometer channel
  double hum_frequency_hz = 50;
  double hum_V = 0;                   ///< amplitude of the mains fundamental
  std::vector<double> hum_harmonics{1.0};  ///< relative amplitudes of 1×, 2×, 3×, … the mains frequency
  double speed_fluctuation = 0;       ///< ε
  std::optional<double> speed_fluctuation_period_s;  ///< default: 10 mean revolutions
  std::vector<double> speed_harmonics;  ///< relative speed change at 1×, 2×, … the mean turn rate
  /// `sampling = "multiplexed"`: one ADC scans the channels in order,
  /// channel i sampled i·skew after channel 0 (`skew_us`; default the scan
  /// spread over the sample period, 1/(fs·channels)). The manifest states it.
  bool multiplexed = false;
  std::optional<double> skew_s;
  /// The DAQ's anti-alias filter on the accelerometer channels (`daq_filter…`);
  /// the sensors' mounted resonances are in `sensors` (sensor_resonance_Hz/_Q).
  DaqFilter daq_filter;
  WheelSpec wheel;                    ///< a tooth wheel or encoder in place of the pulse (`[recording.wheel]`)
  std::uint64_t seed = 1;
  std::vector<ChannelSpec> sensors;   ///< accelerometers, in channel order
  PulseSpec pulse;                    ///< the last channel
  std::string notes;
  /// Clearance scenes: crank turns simulated before the recording starts, so
  /// that it shows the running mechanism rather than the start from rest.
  int warmup_revolutions = 20;
  /// The links' bending modes rung by the bearing impulses
  /// (`[[recording.link_mode]]`, clearance scenes only; link_ringing.hpp).
  std::vector<LinkMode> link_modes;
};

/// How long before t = 0 the recording asks for the motion: the filters'
/// run-in (twelve decay times of the AC coupling's high-pass, the mounted
/// resonance, the anti-alias filter) plus a linear-phase filter's delay.
double recording_run_in_s(const RecordingSpec& spec);

/// Parses `scene.recording`; InputError naming the scene file, line and key
/// (an unknown key too). InputError when the scene has no [recording].
RecordingSpec read_recording_spec(const Scene& scene);

}  // namespace fourbar
