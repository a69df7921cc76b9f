#include "acquire/wheel_pass.hpp"

#include <algorithm>
#include <memory>

#include "acquire/edge_detector.hpp"
#include "acquire/channel_inputs.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

namespace {

struct Source {
  const ChannelSpec* spec;
  PulseThresholds thresholds;
};

/// Manual thresholds from the manifest or automatic ones from the histogram.
/// An index high for one encoder state per turn (a Z gated to A/B: 1/4096 of
/// a 1024-line turn, a sample or two) is too rare for its histogram to show
/// two levels: it is read with the main channel's thresholds (encoder
/// outputs share one logic level), and said so.
PulseThresholds thresholds_of(const ChannelSpec& c, const LevelHistogram& h, const Manifest& m,
                              const PulseThresholds& main, std::vector<std::string>& warnings) {
  auto automatic = automatic_thresholds(h);
  const ChannelSpec& primary = m.pulse_channel();
  if (!automatic && !c.threshold_low_V && c.role == ChannelRole::crank_index && h.count() > 0) {
    automatic = main;
    warnings.push_back(channel_label(c) + " is high too briefly for its own levels to show (an index gated to one "
                       "encoder state); it is read with the thresholds of '" + primary.name + "' (" +
                       format_number(main.low) + " V to " + format_number(main.high) +
                       " V); set threshold_low_V/threshold_high_V on it if its levels differ");
  }
  PulseThresholds t;
  if (automatic) t = *automatic;
  if (c.threshold_low_V) {
    t.low = *c.threshold_low_V, t.high = *c.threshold_high_V, t.automatic = false;
  } else if (!automatic) {
    throw InputError(m.file.string() + ": " + channel_label(c) +
                     " has no two distinct levels (no edges); check its index and the sensor, or set "
                     "threshold_low_V/threshold_high_V");
  }
  return t;
}

}  // namespace

WheelEdges wheel_edge_pass(const BlockStream& stream, const Manifest& manifest, const PulseThresholds& main) {
  const RecordingInfo& info = stream.reader.info();
  const auto channels = static_cast<std::size_t>(info.channels);
  const double vpu = manifest.full_scale_V;
  const ChannelSpec& primary = manifest.pulse_channel();
  std::vector<const ChannelSpec*> aux;
  for (ChannelRole r : {ChannelRole::encoder_b, ChannelRole::crank_index})
    if (const ChannelSpec* c = manifest.channel_with(r)) aux.push_back(c);

  // Thresholds of the channels beside the main one, from their levels.
  WheelEdges e;
  std::vector<Source> sources{{&primary, main}};
  if (!aux.empty()) {
    std::vector<LevelHistogram> hist(aux.size());
    for_each_block(stream, AcquirePass::pulses, [&](std::span<const double> block, std::size_t frames, std::uint64_t) {
      for (std::size_t a = 0; a < aux.size(); ++a) {
        const auto idx = static_cast<std::size_t>(*aux[a]->index);
        for (std::size_t f = 0; f < frames; ++f) hist[a].add(block[f * channels + idx] * vpu);
      }
    });
    for (std::size_t a = 0; a < aux.size(); ++a)
      sources.push_back({aux[a], thresholds_of(*aux[a], hist[a], manifest, main, e.warnings)});
  }

  // One detector per channel and edge direction wanted.
  struct Detector {
    std::size_t index;
    std::unique_ptr<EdgeDetector> d;
    std::vector<double>* out;
  };
  std::vector<Detector> det;
  auto add = [&](const Source& s, PulsePolarity pol, std::vector<double>* out) {
    det.push_back({static_cast<std::size_t>(*s.spec->index),
                   std::make_unique<EdgeDetector>(s.thresholds, pol, info.sample_rate_hz, info.start_time_s,
                                                  s.spec->debounce_s),
                   out});
  };
  for (const Source& s : sources) {
    switch (s.spec->role) {
      case ChannelRole::crank_pulse: add(s, s.spec->polarity, &e.teeth_s); break;
      case ChannelRole::crank_index: add(s, s.spec->polarity, &e.index_s); break;
      case ChannelRole::encoder_a:
        add(s, PulsePolarity::rising, &e.a_rise_s), add(s, PulsePolarity::falling, &e.a_fall_s);
        break;
      case ChannelRole::encoder_b:
        add(s, PulsePolarity::rising, &e.b_rise_s), add(s, PulsePolarity::falling, &e.b_fall_s);
        break;
      default: break;
    }
  }
  std::vector<double> volts;
  for_each_block(stream, AcquirePass::pulses, [&](std::span<const double> block, std::size_t frames, std::uint64_t) {
    volts.resize(frames);
    for (std::size_t k = 0; k < det.size(); ++k) {
      // Both detectors of a channel read the same volts.
      if (k == 0 || det[k].index != det[k - 1].index)
        for (std::size_t f = 0; f < frames; ++f) volts[f] = block[f * channels + det[k].index] * vpu;
      det[k].d->push(volts.data(), frames, 1);
    }
  });
  for (std::size_t k = 0; k < det.size(); ++k) {
    *det[k].out = det[k].d->edges();
    if (det[k].out->empty()) {
      const Source& s = *std::find_if(sources.begin(), sources.end(),
                                      [&](const Source& x) { return static_cast<std::size_t>(*x.spec->index) == det[k].index; });
      throw InputError(info.file.string() + ": " + channel_label(*s.spec) + " never crosses from " +
                       format_number(s.thresholds.low) + " V to " + format_number(s.thresholds.high) +
                       " V: no edges; check the channel index and thresholds in " + manifest.file.string());
    }
  }
  return e;
}

}  // namespace fourbar
