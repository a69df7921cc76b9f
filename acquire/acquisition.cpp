#include "acquire/acquisition.hpp"

#include <algorithm>
#include <array>
#include <chrono>
#include <iterator>

#include "acquire/acquisition_warnings.hpp"
#include "acquire/channel_inputs.hpp"
#include "acquire/pulse_pass.hpp"
#include "acquire/pulse_thresholds.hpp"
#include "acquire/sample_tagging.hpp"
#include "acquire/speed_angle.hpp"
#include "acquire/streaming_pass.hpp"
#include "acquire/wheel_decode.hpp"
#include "acquire/wheel_pass.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"

namespace fourbar {

namespace {

/// Reads shorter than this make the per-block overhead dominate.
constexpr std::size_t kMinBlockFrames = 64;

/// Wall time of each pass into the report, each lap from the end of the last.
class PassClock {
 public:
  explicit PassClock(std::array<double, kAcquirePasses>& seconds) : seconds_(seconds) {}
  void lap(AcquirePass pass) {
    const auto now = std::chrono::steady_clock::now();
    seconds_[static_cast<std::size_t>(pass)] = std::chrono::duration<double>(now - start_).count();
    start_ = now;
  }

 private:
  std::array<double, kAcquirePasses>& seconds_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

template <class T>
void append(std::vector<T>& to, std::vector<T> from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
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
  if (!(info.sample_rate_hz > 0))
    throw InputError(info.file.string() + ": sample rate 0; give sample_rate_hz in the manifest");
  const Accelerometers accel = accelerometers(manifest);
  report.channels = accel.channels;
  report.pulse_channel = manifest.pulse_channel().name;
  const ClipRange clip = clip_range(info, manifest);
  report.clipping_checked = clip.checked;

  Progress progress("acquire", kAcquirePasses * info.frames, options.progress);
  const bool threaded = options.threads > 1;
  const BlockStream stream{reader, std::max(options.block_frames, kMinBlockFrames), progress, threaded, threaded};
  PassClock clock(report.pass_seconds);

  ScanResult scan = scan_pass(stream, accel.inputs, clip, pulse_input(manifest));
  clock.lap(AcquirePass::scan);
  report.channel_stats = std::move(scan.channel_stats);
  report.pulse_stats = scan.pulse_stats;
  const ChannelSpec* speed = manifest.speed_channel();
  const ChannelSpec* speed_zero = speed ? manifest.channel_with(ChannelRole::crank_pulse) : nullptr;
  if (!speed || speed_zero) {  // a speed track alone has no thresholds
    ThresholdChoice thresholds = pulse_thresholds(scan.pulse_histogram, scan.pulse_stats, manifest, info.file,
                                                  &scan.pulse_local);
    report.thresholds = thresholds.thresholds;
    append(report.warnings, std::move(thresholds.warnings));
  }

  RevolutionSchedule schedule;
  SignalExcerpt excerpt;
  TimeRange& range = report.range;
  range.start_s = options.range.start_s ? options.range.start_s : manifest.start_s;
  range.end_s = options.range.end_s ? options.range.end_s : manifest.end_s;
  if (speed) {
    std::vector<double> pulse_s;
    if (speed_zero) {
      const EdgePassResult edges = edge_pass(stream, manifest, report.thresholds, &scan.pulse_local);
      report.edges_debounced = edges.edges_debounced;
      report.edge_level_V = edges.edge_level_V;
      const PulseTrain train = pulse_train_from_edges(edges, options.pulses, manifest, info.file);
      for (const auto& seg : train.segments)
        for (const Pulse& p : seg)
          if (!p.inserted) pulse_s.push_back(p.time_s);
    }
    const std::vector<double> rpm = speed_track_pass(stream, manifest, *speed);
    clock.lap(AcquirePass::pulses);
    SpeedAngle angle = speed_angle_edges(rpm, info.sample_rate_hz, info.start_time_s, *speed, speed_zero, pulse_s,
                                         range, manifest.file);
    append(report.warnings, std::move(angle.warnings));
    trim_numbered_edges(angle.edges, range);
    WheelSchedule wheel = plan_wheel_revolutions(angle.edges, manifest, info.sample_rate_hz, options.grid_points_per_rev);
    wheel.report.source = angle.source;
    report.pulses = std::move(wheel.turns);
    report.wheel = std::move(wheel.report);
    append(report.warnings, std::move(wheel.warnings));
    schedule = std::move(wheel.schedule);
    if (options.excerpt_revolutions > 0)
      excerpt = excerpt_window(report.pulses, options.excerpt_revolutions, info.sample_rate_hz, info.start_time_s, info.frames);
  } else if (manifest.multi_edge_angle()) {
    const WheelEdges edges = wheel_edge_pass(stream, manifest, report.thresholds);
    clock.lap(AcquirePass::pulses);
    NumberedEdges numbered = number_edges(edges, manifest, info.file);
    trim_numbered_edges(numbered, range);
    WheelSchedule wheel = plan_wheel_revolutions(numbered, manifest, info.sample_rate_hz, options.grid_points_per_rev);
    report.pulses = std::move(wheel.turns);
    report.wheel = std::move(wheel.report);
    append(report.warnings, std::move(wheel.warnings));
    schedule = std::move(wheel.schedule);
    if (options.excerpt_revolutions > 0) {
      excerpt = excerpt_window(report.pulses, options.excerpt_revolutions, info.sample_rate_hz, info.start_time_s, info.frames);
      for (const auto* main : {&edges.teeth_s, &edges.a_rise_s, &edges.a_fall_s})  // the main channel's edges
        for (double t : *main)
          if (t >= excerpt.start_s && t <= excerpt.end_s) excerpt.wheel_edge_s.push_back(t);
      std::sort(excerpt.wheel_edge_s.begin(), excerpt.wheel_edge_s.end());
    }
  } else {
    const EdgePassResult edges = edge_pass(stream, manifest, report.thresholds, &scan.pulse_local);
    clock.lap(AcquirePass::pulses);
    report.edges_debounced = edges.edges_debounced;
    report.edge_level_V = edges.edge_level_V;
    report.pulses = pulse_train_from_edges(edges, options.pulses, manifest, info.file);
    trim_pulse_train(report.pulses, range);
    report.pulse_width_deg = median_width_deg(edges.widths_s, report.pulses.typical_period_s);
    schedule = plan_revolutions(report.pulses, info.sample_rate_hz, options.grid_points_per_rev,
                                manifest.pulse_channel().smoothing_period_turns);
    if (options.excerpt_revolutions > 0)
      excerpt = excerpt_window(report.pulses, options.excerpt_revolutions, info.sample_rate_hz, info.start_time_s, info.frames);
  }
  report.revolutions = report.pulses.revolutions();
  if (report.revolutions < 2)
    throw InputError(info.file.string() + ": " + std::to_string(report.revolutions) +
                     " complete turns in the crank-angle channels" +
                     (range.active() ? " between " + describe_range(range) : std::string()) +
                     "; need at least 2: record longer, widen the range, or check them");
  {
    const double file_end_s = info.start_time_s + static_cast<double>(info.frames) / info.sample_rate_hz;
    append(report.warnings, range_warnings(schedule.plan, info.start_time_s, file_end_s, range));
  }

  require_smoothing_fits(schedule.smoothing, manifest, info.file);
  report.smoothing = schedule.smoothing;
  if (std::string w = smoothing_warning(report.smoothing); !w.empty()) report.warnings.push_back(std::move(w));
  report.revolutions_repaired = schedule.revolutions_repaired;
  report.frames_per_rev = schedule.frames_per_rev;
  report.grid_points_per_rev = sink.wants_grid() ? schedule.grid_points_per_rev : 0;
  report.speed = schedule.speed;
  sink.on_plan(report);
  const GridSettings grid{report.grid_points_per_rev, manifest.crank_direction,
                          manifest.pulse_channel().crank_offset_rad, info.sample_rate_hz, info.start_time_s,
                          info.frames};
  std::optional<ExcerptRecorder> recorder;
  if (excerpt.frames > 0) recorder.emplace(std::move(excerpt), manifest, info.sample_rate_hz, info.start_time_s);
  report.revolutions_clipped =
      tag_pass(stream, std::move(schedule.plan), grid, accel.inputs, clip, sink, recorder ? &*recorder : nullptr);
  if (recorder) report.excerpt = recorder->finish();
  progress.finish();
  clock.lap(AcquirePass::samples);

  for (const auto& g : report.pulses.gaps) report.revolutions_in_gaps += revolutions_lost(g);
  append(report.warnings, collect_warnings(report));
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
