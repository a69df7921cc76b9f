#pragma once
// How acquire reads each recorded channel: which channels are accelerometers
// and the factor that turns their recorded numbers into m/s², the pulse
// channel and its volts per recorded unit, and the input range at which a
// recorded value counts as clipped. Shared by the scan and sample passes.

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "acquire/manifest.hpp"
#include "acquire/reader.hpp"
#include "acquire/revolution.hpp"

namespace fourbar {

/// One accelerometer channel as recorded.
struct AccelerometerInput {
  std::size_t index = 0;      ///< channel in the recording
  double m_s2_per_unit = 0;   ///< m/s² per recorded unit, axis sign included
};

/// The accelerometer channels, in manifest order.
struct Accelerometers {
  std::vector<AcquiredChannel> channels;   ///< as reported
  std::vector<AccelerometerInput> inputs;  ///< same order
};
Accelerometers accelerometers(const Manifest& manifest);

/// The crank-pulse channel as recorded.
struct PulseInput {
  std::size_t index = 0;      ///< channel in the recording
  double volts_per_unit = 1;  ///< the manifest's full_scale_V
};
PulseInput pulse_input(const Manifest& manifest);

/// "pulse channel 'NAME' (index I)", for messages.
std::string pulse_channel_label(const ChannelSpec& pulse);

/// "channel 'NAME' (ROLE, index I)", for messages.
std::string channel_label(const ChannelSpec& c);

/// Recorded values at or beyond these limits are clipped: integer samples at
/// the rails; float and text samples beyond the manifest's adc_range_V. With
/// neither, nothing is checked (±∞).
struct ClipRange {
  double low = -INFINITY, high = INFINITY;  ///< recorded units
  bool checked = false;
  bool clipped(double raw) const { return raw >= high || raw <= low; }
};
ClipRange clip_range(const RecordingInfo& recording, const Manifest& manifest);

}  // namespace fourbar
