// ChunkedAnalysis, the driver (chunked_analysis.hpp): turns acquire's plan
// into the analysis settings (analysis_settings.hpp, chunk_plan.hpp), makes
// the filter blocks, spectra and averagers, lays out the result, and takes
// the clipping flags of the revolutions. The buffering, the per-chunk
// transform and the results are in chunk_stitching.cpp, chunk_transform.cpp
// and revolution_results.cpp.
#include "analyze/chunked_analysis.hpp"

#include <algorithm>

#include "analyze/analysis_settings.hpp"
#include "analyze/chunk_plan.hpp"
#include "common/units.hpp"

namespace fourbar {

ChunkedAnalysis::ChunkedAnalysis(RecordingAnalysis& result, const Manifest& manifest, AnalysisChannels channels,
                                 RevolutionObserver* observer)
    : result_(result), manifest_(manifest), channels_(std::move(channels)), observer_(observer) {
  for (const LinkChannels& l : channels_.links) {
    for (const auto* ch : {&l.tangential, &l.normal})
      if (*ch) used_.push_back((*ch)->index);
    has_normal_ = has_normal_ || l.normal.has_value();
  }
  samples_.resize(used_.size());
}

ChunkedAnalysis::~ChunkedAnalysis() {
  in_flight_.clear();  // waits for the chunks still running (after an error in acquire)
}

void ChunkedAnalysis::on_plan(const AcquisitionReport& report) {
  result_.acquisition = report;  // so far: pulses, speed statistics (complete after acquire)
  resolve_settings(report);
  planned_ = true;
  if (observer_) observer_->on_start(result_);
}

void ChunkedAnalysis::resolve_settings(const AcquisitionReport& report) {
  const AnalyzeOptions& o = result_.options;
  fs_ = report.recording.sample_rate_hz;
  direction_ = manifest_.crank_direction;
  offset_rad_ = manifest_.pulse_channel().crank_offset_rad;
  mean_speed_rad_s_ = direction_ * units::rpm_to_rad_s(report.speed.mean_rpm);
  const double mean_crank_hz = report.speed.mean_rpm / 60.0, fastest_crank_hz = report.speed.max_rpm / 60.0;
  const double frames_per_rev = report.frames_per_rev;
  const double longest_frames = longest_segment_frames(report.pulses, fs_);

  filter_ = resolve_filter(o.filter, fs_, mean_crank_hz, longest_frames, result_.warnings);
  normal_filter_ = without_low_corner(filter_);
  const std::size_t taps = filter_kernel_taps(filter_, fs_);
  half_kernel_ = taps / 2;
  overlap_ = chunk_overlap_frames(taps, frames_per_rev);
  grid_ = {resolve_grid_points(o.grid_points_per_rev, filter_, fs_, fastest_crank_hz, result_.warnings), offset_rad_,
           direction_};

  const double slowest_rev_frames = slowest_revolution_frames(fs_, report.speed.min_rpm);
  chunk_revs_ = plan_chunk_revolutions(o.chunk_revolutions, taps, overlap_, slowest_rev_frames, frames_per_rev);
  if (taps > 0)
    filter_block_frames_ = filter_block_frames(chunk_revs_, slowest_rev_frames, overlap_, longest_frames, half_kernel_);
  threads_ = std::max(1u, o.threads);
  give_back(make_workspace());  // the filter blocks made now, before the long pass
  make_spectra(resolve_spectrum_segment_frames(o.spectrum_segment, frames_per_rev, longest_frames));
  make_averagers();
  lay_out_result(taps);
}

void ChunkedAnalysis::make_spectra(std::size_t segment_frames) {
  result_.spectra.segment_length = segment_frames;
  spectra_.clear();
  for (std::size_t j = 0; j < channels_.links.size(); ++j)
    spectra_.push_back(
        std::make_unique<SpectrumAverager>(fs_, WelchOptions{segment_frames, segment_frames / 2, {WindowType::hann, 0}}));
  result_.spectra.frequency_hz = spectra_.front()->frequency_hz();
  result_.spectra.order = order_axis(result_.spectra.frequency_hz, mean_speed_rad_s_);
  result_.spectra.filter_gain = zero_phase_response(filter_, fs_, segment_frames);
}

void ChunkedAnalysis::make_averagers() {
  const std::size_t N = grid_.grid_points_per_rev;
  tables_ = std::make_shared<const RigTables>(*manifest_.rig);
  speed_avg_ = std::make_unique<SynchronousAverager>(N);
  const std::size_t links = channels_.links.size();
  alpha_avg_.assign(links, SynchronousAverager(N));
  omega_avg_.assign(links, SynchronousAverager(N));
  normal_avg_.assign(links, SynchronousAverager(N));
  omega_sq_avg_.assign(links, SynchronousAverager(N));
  alpha_repeat_.assign(links, TurnRepeatAccumulator(N));
  repeat_held_.clear();
  repeat_last_added_.reset();
  omega_carry_.assign(links, std::nullopt);
}

void ChunkedAnalysis::lay_out_result(std::size_t taps) {
  const std::size_t N = grid_.grid_points_per_rev;
  result_.filter = filter_;
  result_.normal_filter = normal_filter_;
  result_.kernel_taps = taps;
  result_.chunk_revolutions = chunk_revs_;
  result_.grid_points_per_rev = N;
  result_.crank_direction = direction_;
  result_.crank_deg.resize(N);
  for (std::size_t k = 0; k < N; ++k)
    result_.crank_deg[k] = units::rad_to_deg(offset_rad_) + direction_ * 360.0 * double(k) / double(N);
  for (const LinkChannels& l : channels_.links) {
    LinkResult r;
    r.link = l.link;
    r.channel = l.tangential->mount.channel;
    if (l.normal) r.normal = NormalCheck{l.normal->mount.channel, l.normal->mount.high_pass_corner_hz > 0, {}, {}, {}, 0.0};
    (l.link == SensedLink::coupler ? result_.coupler : result_.rocker) = std::move(r);
  }
}

void ChunkedAnalysis::on_revolution(const Revolution& r) {
  if (clipped_.size() <= r.number) clipped_.resize(r.number + 1, false);
  clipped_[r.number] = r.clipped;
}

}  // namespace fourbar
