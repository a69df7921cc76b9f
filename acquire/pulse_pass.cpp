#include "acquire/pulse_pass.hpp"

#include <algorithm>
#include <cmath>

#include "acquire/channel_inputs.hpp"
#include "acquire/edge_detector.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

EdgePassResult edge_pass(const BlockStream& stream, const Manifest& manifest, const PulseThresholds& thresholds) {
  const RecordingInfo& info = stream.reader.info();
  const auto channels = static_cast<std::size_t>(info.channels);
  const ChannelSpec& pulse = manifest.pulse_channel();
  const PulseInput input = pulse_input(manifest);
  EdgeDetector detector(thresholds, pulse.polarity, info.sample_rate_hz, info.start_time_s, pulse.debounce_s);
  for_each_block(stream, AcquirePass::pulses, [&](std::span<const double> block, std::size_t frames, std::uint64_t) {
    std::vector<double> volts(frames);
    for (std::size_t f = 0; f < frames; ++f) volts[f] = block[f * channels + input.index] * input.volts_per_unit;
    detector.push(volts.data(), frames, 1);
  });
  EdgePassResult result{detector.edges(), detector.debounced(), detector.mid_level()};
  if (result.edges_s.empty())
    throw InputError(info.file.string() + ": no crank pulses: " + pulse_channel_label(pulse) + " never crosses from " +
                     format_number(thresholds.low) + " V to " + format_number(thresholds.high) + " V (" +
                     (pulse.polarity == PulsePolarity::rising ? "rising" : "falling") +
                     " edges); check the channel, its polarity and thresholds in " + manifest.file.string());
  return result;
}

PulseTrain pulse_train_from_edges(std::span<const double> edges_s, const PulseTrainOptions& options,
                                  const Manifest& manifest, const std::filesystem::path& recording_file) {
  PulseTrain train = clean_pulse_train(edges_s, options);
  const std::size_t revolutions = train.revolutions();
  if (revolutions < 2)
    throw InputError(recording_file.string() + ": " + std::to_string(revolutions) + " complete revolution" +
                     (revolutions == 1 ? "" : "s") + " between the " + std::to_string(edges_s.size()) +
                     " crank pulse edges of " + pulse_channel_label(manifest.pulse_channel()) +
                     "; need at least 2: record longer or check the pulse channel");
  return train;
}

std::size_t revolutions_lost(const PulseGap& gap) {
  return static_cast<std::size_t>(std::max(1.0, std::round(gap.periods)));
}

}  // namespace fourbar
