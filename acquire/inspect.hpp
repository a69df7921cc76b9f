#pragma once
// `fourbar inspect`: what a recording holds, from the file alone (no
// manifest): per channel the range, mean (DC), RMS and AC RMS, samples at
// the digital rails or flat at the channel's extremes (clipping), whether it
// is a pulse train (its rate → crank speed at one pulse per turn) and a
// guess of its role. Two streaming passes; memory does not grow with the
// recording (only the pulse times are kept).

#include <cstdint>
#include <string>
#include <vector>

#include "acquire/reader.hpp"

namespace fourbar {

/// A channel that switches between two levels at a steady rate.
struct PulseTrainGuess {
  std::uint64_t pulses = 0;        ///< leading edges found
  double rate_hz = 0;              ///< from the median interval between them
  double rpm = 0;                  ///< 60 · rate: the crank speed at one pulse per turn
  double low_level = 0, high_level = 0;
  double high_fraction = 0;        ///< share of the time at the high level
  bool short_state_high = true;    ///< the pulse is the short high state (rising edge leads)
  double regular_fraction = 0;     ///< share of intervals within ±25 % of the median (missing pulses lower it)
};

struct ChannelInspection {
  int index = 0;
  std::string name;                ///< column / variable name, empty for audio files
  std::string unit;                ///< as the export states it, or empty
  double min = 0, max = 0, mean = 0, rms = 0, ac_rms = 0;  ///< recorded units; mean = DC
  std::uint64_t rail_samples = 0;  ///< integer formats: samples at digital full scale
  std::uint64_t flat_extreme_samples = 0;  ///< samples in runs of ≥ 3 equal values at the channel's min or max
  bool constant = false;
  std::optional<PulseTrainGuess> pulse;  ///< set when the channel looks like a pulse train
  std::string role;                ///< guessed manifest role, empty when the data cannot tell
  std::string reason;              ///< one line: why that role (or what the channel looks like)

  bool clipped() const { return rail_samples > 0 || (!pulse && flat_extreme_samples > 0); }
};

struct RecordingInspection {
  RecordingInfo info;
  std::vector<ChannelInspection> channels;
  int pulse_channel = -1;          ///< the most regular pulse train, −1 when none
};

/// Reads `reader` twice (it is rewound first). InputError as the reader's.
RecordingInspection inspect_recording(Reader& reader);

/// The role a channel's name suggests ("coupler_t" → coupler_tangential), or empty.
std::string role_from_name(const std::string& name);

}  // namespace fourbar
