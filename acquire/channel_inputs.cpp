#include "acquire/channel_inputs.hpp"

namespace fourbar {

namespace {

/// A float sample written at adc_range_V may come back a rounding below it;
/// this fraction of the range still counts as clipped.
constexpr double kAdcRangeMargin = 1e-6;

}  // namespace

Accelerometers accelerometers(const Manifest& manifest) {
  Accelerometers a;
  for (const auto& c : manifest.channels) {
    if (!is_accelerometer(c.role)) continue;
    a.channels.push_back({c.name, c.role, *c.index, c.position_m, c.offset_m, c.ac_coupled, c.highpass_hz});
    a.inputs.push_back({static_cast<std::size_t>(*c.index), c.axis_sign * manifest.full_scale_V / c.volts_per_m_s2});
  }
  return a;
}

PulseInput pulse_input(const Manifest& manifest) {
  return {static_cast<std::size_t>(*manifest.pulse_channel().index), manifest.full_scale_V};
}

std::string pulse_channel_label(const ChannelSpec& pulse) {
  return "pulse channel '" + pulse.name + "' (index " + std::to_string(static_cast<std::size_t>(*pulse.index)) + ")";
}

std::string channel_label(const ChannelSpec& c) {
  return "channel '" + c.name + "' (" + to_string(c.role) + ", index " + std::to_string(c.index.value_or(0)) + ")";
}

ClipRange clip_range(const RecordingInfo& recording, const Manifest& manifest) {
  ClipRange r;
  if (recording.integer_bits > 0) {
    const double top = std::ldexp(1.0, recording.integer_bits - 1);
    r.high = (top - 1) / top, r.low = -1.0;
    r.checked = true;
  } else if (manifest.adc_range_V) {
    r.high = *manifest.adc_range_V / manifest.full_scale_V * (1 - kAdcRangeMargin), r.low = -r.high;
    r.checked = true;
  }
  return r;
}

}  // namespace fourbar
