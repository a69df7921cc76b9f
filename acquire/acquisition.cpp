#include "acquire/acquisition.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "acquire/crank_angle.hpp"
#include "acquire/edge_detector.hpp"
#include "common/progress.hpp"
#include "acquire/revolution_builder.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

std::string time_list(const std::vector<double>& times, std::size_t max_shown = 5) {
  std::string s;
  for (std::size_t i = 0; i < std::min(times.size(), max_shown); ++i) s += (i ? ", " : "") + format_number(times[i]) + " s";
  if (times.size() > max_shown) s += ", …";
  return s;
}

/// Streaming min/max/mean/rms.
struct Accumulator {
  double min = INFINITY, max = -INFINITY, sum = 0, sum_sq = 0;
  std::uint64_t n = 0, clipped = 0;
  double first_clip_s = 0;
  void add(double v) {
    min = std::min(min, v), max = std::max(max, v), sum += v, sum_sq += v * v, ++n;
  }
  ChannelStats stats() const {
    ChannelStats s;
    if (n == 0) return s;
    s.min = min, s.max = max, s.mean = sum / static_cast<double>(n);
    s.rms = std::sqrt(sum_sq / static_cast<double>(n));
    s.clipped_samples = clipped, s.first_clip_s = first_clip_s;
    return s;
  }
};

/// Reads the whole recording once, block by block.
template <class PerBlock>
void for_each_block(Reader& reader, std::size_t block_frames, Progress& progress, std::uint64_t done_before,
                    PerBlock&& per_block) {
  const auto channels = static_cast<std::size_t>(reader.info().channels);
  std::vector<double> block(block_frames * channels);
  reader.rewind();
  std::uint64_t first = 0;
  for (;;) {
    const std::size_t got = reader.read(block);
    if (got == 0) break;
    per_block(std::span<const double>(block.data(), got * channels), got, first);
    first += got;
    progress.update(done_before + first);
  }
  if (first != reader.info().frames)
    throw InputError(reader.info().file.string() + ": the recording ended at frame " + std::to_string(first) +
                     " but announced " + std::to_string(reader.info().frames) + " (truncated); copy it again");
}

}  // namespace

OpenedRecording open_with_manifest(const std::filesystem::path& recording, const std::filesystem::path& manifest_file) {
  std::filesystem::path mf = manifest_file;
  if (mf.empty()) {
    mf = sidecar_manifest_path(recording);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(mf, ec))
      throw InputError(recording.string() + ": no manifest: expected the sidecar " + mf.string() +
                       " (or give one with --manifest); it says what each channel is");
  }
  OpenedRecording o{load_manifest(mf), nullptr};
  o.reader = open_recording(recording, o.manifest.reader_options());
  bind_channels(o.manifest, o.reader->info());
  return o;
}

AcquisitionReport acquire(Reader& reader, const Manifest& manifest, const AcquireOptions& options,
                          AcquisitionSink& sink) {
  const RecordingInfo& info = reader.info();
  AcquisitionReport report;
  report.recording = info;
  const auto nch = static_cast<std::size_t>(info.channels);
  const double fs = info.sample_rate_hz, t0 = info.start_time_s;
  if (!(fs > 0)) throw InputError(info.file.string() + ": sample rate 0; give sample_rate_hz in the manifest");
  const std::size_t block_frames = std::max<std::size_t>(options.block_frames, 64);

  // Channels: the accelerometers with their calibration, and the pulse.
  struct Cal {
    std::size_t index;
    double scale;  // m/s² per recorded unit, axis sign included
  };
  std::vector<Cal> cal;
  const ChannelSpec& pulse = manifest.pulse_channel();
  const auto pulse_index = static_cast<std::size_t>(*pulse.index);
  report.pulse_channel = pulse.name;
  for (const auto& c : manifest.channels) {
    if (!is_accelerometer(c.role)) continue;
    report.channels.push_back({c.name, c.role, *c.index, c.position_m, c.offset_m, c.ac_coupled, c.highpass_hz});
    cal.push_back({static_cast<std::size_t>(*c.index), c.axis_sign * manifest.full_scale_V / c.volts_per_m_s2});
  }
  const std::size_t nacc = cal.size();

  // Clipping: integer samples at the rails; float and text beyond adc_range_V.
  double clip_hi = INFINITY, clip_lo = -INFINITY;
  if (info.integer_bits > 0) {
    const double top = std::ldexp(1.0, info.integer_bits - 1);
    clip_hi = (top - 1) / top, clip_lo = -1.0;
    report.clipping_checked = true;
  } else if (manifest.adc_range_V) {
    clip_hi = *manifest.adc_range_V / manifest.full_scale_V * (1 - 1e-6), clip_lo = -clip_hi;
    report.clipping_checked = true;
  }
  auto is_clipped = [&](double raw) { return raw >= clip_hi || raw <= clip_lo; };

  Progress progress("acquire", 3 * info.frames, options.progress);

  auto clock_start = std::chrono::steady_clock::now();
  auto lap = [&](int pass) {
    const auto now = std::chrono::steady_clock::now();
    report.pass_seconds[static_cast<std::size_t>(pass)] = std::chrono::duration<double>(now - clock_start).count();
    clock_start = now;
  };

  // Pass 1: statistics, clipping, NaN, the pulse channel's levels.
  std::vector<Accumulator> acc(nacc);
  Accumulator pulse_acc;
  LevelHistogram histogram;
  progress.set_label("acquire: scan   ");
  for_each_block(reader, block_frames, progress, 0, [&](std::span<const double> block, std::size_t frames,
                                                        std::uint64_t first) {
    for (std::size_t f = 0; f < frames; ++f) {
      const double* frame = block.data() + f * nch;
      for (std::size_t c = 0; c < nch; ++c)
        if (!std::isfinite(frame[c]))
          throw InputError(info.file.string() + ": channel " + std::to_string(c) + " holds a non-finite value at frame " +
                           std::to_string(first + f) + " (t = " + format_number(t0 + static_cast<double>(first + f) / fs) +
                           " s); the recording is damaged");
      for (std::size_t a = 0; a < nacc; ++a) {
        const double raw = frame[cal[a].index];
        acc[a].add(raw * cal[a].scale);
        if (is_clipped(raw) && acc[a].clipped++ == 0) acc[a].first_clip_s = t0 + static_cast<double>(first + f) / fs;
      }
      const double v = frame[pulse_index] * manifest.full_scale_V;
      pulse_acc.add(v);
      histogram.add(v);
    }
  });
  lap(0);
  for (const auto& a : acc) report.channel_stats.push_back(a.stats());
  report.pulse_stats = pulse_acc.stats();

  // Thresholds: from the manifest, else from the two levels.
  const std::string pulse_label = "pulse channel '" + pulse.name + "' (index " + std::to_string(pulse_index) + ")";
  const auto automatic = automatic_thresholds(histogram);
  if (pulse.threshold_low_V) {
    report.thresholds.low = *pulse.threshold_low_V;
    report.thresholds.high = *pulse.threshold_high_V;
    report.thresholds.automatic = false;
    if (automatic) {
      report.thresholds.bottom_level = automatic->bottom_level, report.thresholds.top_level = automatic->top_level;
      report.thresholds.noise = automatic->noise;
    }
  } else if (automatic) {
    report.thresholds = *automatic;
  } else {
    throw InputError(info.file.string() + ": no crank pulses: " + pulse_label +
                     " has no two distinct levels (it spans " + format_number(pulse_acc.min) + " to " + format_number(pulse_acc.max) +
                     " V); check the channel index in " + manifest.file.string() +
                     " and the pickup, or set threshold_low_V/threshold_high_V");
  }
  // Pulses are short: the level the channel spends most time at is idle. The
  // marking edge should be the pulse's leading edge.
  if (const auto levels = histogram.two_levels(); automatic && levels) {
    const bool idle_high = levels->high.count > levels->low.count;
    if (idle_high == (pulse.polarity == PulsePolarity::rising))
      report.warnings.push_back(pulse_label + ": the pulses go " + (idle_high ? "down from a high" : "up from a low") +
                                " idle level, so polarity = \"" +
                                (pulse.polarity == PulsePolarity::rising ? "rising" : "falling") +
                                "\" times their trailing edge; if the leading edge marks the crank angle, set "
                                "polarity = \"" + (idle_high ? "falling" : "rising") + "\"");
  }
  if (automatic && automatic->noise > 0.1 * (automatic->top_level - automatic->bottom_level))
    report.warnings.push_back(pulse_label + " is noisy (noise " + format_number(automatic->noise) + " V against a swing of " +
                              format_number(automatic->top_level - automatic->bottom_level) + " V); hysteresis widened");

  // Pass 2: edges.
  EdgeDetector detector(report.thresholds, pulse.polarity, fs, t0, pulse.debounce_s);
  progress.set_label("acquire: pulses ");
  for_each_block(reader, block_frames, progress, info.frames,
                 [&](std::span<const double> block, std::size_t frames, std::uint64_t) {
                   std::vector<double> volts(frames);
                   for (std::size_t f = 0; f < frames; ++f) volts[f] = block[f * nch + pulse_index] * manifest.full_scale_V;
                   detector.push(volts.data(), frames, 1);
                 });
  lap(1);
  report.edges_debounced = detector.debounced();
  report.edge_level_V = detector.mid_level();
  const std::vector<double> edges = detector.edges();
  if (edges.empty())
    throw InputError(info.file.string() + ": no crank pulses: " + pulse_label + " never crosses from " +
                     format_number(report.thresholds.low) + " V to " + format_number(report.thresholds.high) + " V (" +
                     (pulse.polarity == PulsePolarity::rising ? "rising" : "falling") +
                     " edges); check the channel, its polarity and thresholds in " + manifest.file.string());

  // The pulse train and the crank motion through it.
  report.pulses = clean_pulse_train(edges, options.pulses);
  const PulseTrain& train = report.pulses;
  report.revolutions = train.revolutions();
  if (report.revolutions < 2)
    throw InputError(info.file.string() + ": " + std::to_string(report.revolutions) +
                     " complete revolution" + (report.revolutions == 1 ? "" : "s") + " between the " +
                     std::to_string(edges.size()) + " crank pulse edges of " + pulse_label +
                     "; need at least 2: record longer or check the pulse channel");
  std::vector<CrankAngleModel> models;
  std::vector<RevolutionPlan> plan;
  for (std::size_t s = 0; s < train.segments.size(); ++s) {
    std::vector<double> times;
    for (const auto& p : train.segments[s]) times.push_back(p.time_s);
    models.emplace_back(times);
    for (std::size_t k = 0; k + 1 < times.size(); ++k) {
      RevolutionPlan r;
      r.segment = s;
      r.curve = models.back().revolution(k);
      r.t_start = times[k], r.t_end = times[k + 1];
      r.repaired = train.segments[s][k].inserted || train.segments[s][k + 1].inserted;
      report.revolutions_repaired += r.repaired;
      plan.push_back(r);
    }
  }
  report.samples_per_turn = train.typical_period_s * fs;
  const int n_grid = options.samples_per_revolution > 0
                         ? options.samples_per_revolution
                         : 360 * static_cast<int>(std::ceil(std::max(1.0, report.samples_per_turn) / 360.0));
  report.samples_per_revolution = n_grid;

  // Speed statistics over the kept revolutions.
  {
    double sum = 0, sum_sq = 0, mn = INFINITY, mx = 0;
    for (const auto& r : plan) {
      const double rpm = 60.0 / (r.t_end - r.t_start);
      sum += rpm, sum_sq += rpm * rpm, mn = std::min(mn, rpm), mx = std::max(mx, rpm);
    }
    const double n = static_cast<double>(plan.size());
    report.speed = {sum / n, std::sqrt(std::max(0.0, sum_sq / n - (sum / n) * (sum / n))), mn, mx};
  }

  // Pass 3: tag samples, resample revolutions.
  sink.on_plan(report);
  RevolutionBuilder builder(std::move(plan),
                            {n_grid, manifest.crank_direction, pulse.crank_offset_rad, fs, t0, info.frames}, nacc, sink);
  std::vector<double> calibrated(nacc);
  progress.set_label("acquire: angles ");
  for_each_block(reader, block_frames, progress, 2 * info.frames, [&](std::span<const double> block,
                                                                      std::size_t frames, std::uint64_t first) {
    for (std::size_t f = 0; f < frames; ++f) {
      const double* frame = block.data() + f * nch;
      bool clipped = false;
      for (std::size_t a = 0; a < nacc; ++a) {
        calibrated[a] = frame[cal[a].index] * cal[a].scale;
        clipped |= is_clipped(frame[cal[a].index]);
      }
      builder.push(static_cast<std::int64_t>(first + f), calibrated.data(), clipped);
    }
    builder.flush_samples();
  });
  builder.finish();
  report.revolutions_clipped = builder.revolutions_clipped();
  progress.finish();
  lap(2);

  // Warnings.
  for (std::size_t a = 0; a < nacc; ++a)
    if (report.channel_stats[a].clipped_samples > 0)
      report.warnings.push_back("channel '" + report.channels[a].name + "' clipped: " +
                                std::to_string(report.channel_stats[a].clipped_samples) +
                                " samples at the input range, first at " +
                                format_number(report.channel_stats[a].first_clip_s) + " s; " +
                                std::to_string(report.revolutions_clipped) +
                                " revolutions are marked clipped (lower the gain)");
  if (!train.removed_s.empty())
    report.warnings.push_back(std::to_string(train.removed_s.size()) +
                              " spurious pulse edges removed (echoes, doubled marks or noise) at " +
                              time_list(train.removed_s));
  if (!train.inserted_s.empty())
    report.warnings.push_back(std::to_string(train.inserted_s.size()) + " missing pulses inserted at " +
                              time_list(train.inserted_s));
  for (const auto& g : train.gaps) {
    const auto lost = static_cast<std::size_t>(std::max(1.0, std::round(g.periods)));
    report.revolutions_in_gaps += lost;
    report.warnings.push_back("pulse train broken between " + format_number(g.from_s) + " s and " + format_number(g.to_s) + " s (" +
                              format_number(g.periods, 3) + " periods, no whole number): about " + std::to_string(lost) +
                              " revolutions dropped");
  }
  if (!train.orphan_s.empty())
    report.warnings.push_back(std::to_string(train.orphan_s.size()) +
                              " isolated pulses without a neighbour one period away, at " + time_list(train.orphan_s));
  if (report.samples_per_turn < 64)
    report.warnings.push_back("only " + format_number(report.samples_per_turn, 3) +
                              " samples per revolution: too coarse for impact bursts; record faster");
  return report;
}

Acquisition acquire_revolutions(const std::filesystem::path& recording, const std::filesystem::path& manifest_file,
                                const AcquireOptions& options) {
  OpenedRecording o = open_with_manifest(recording, manifest_file);
  struct Collect : AcquisitionSink {
    std::vector<Revolution> revolutions;
    void on_revolution(const Revolution& r) override { revolutions.push_back(r); }
  } collect;
  Acquisition a;
  a.report = acquire(*o.reader, o.manifest, options, collect);
  a.manifest = std::move(o.manifest);
  a.revolutions = std::move(collect.revolutions);
  return a;
}

}  // namespace fourbar
