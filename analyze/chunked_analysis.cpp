#include "analyze/chunked_analysis.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/analysis_settings.hpp"
#include "analyze/chunk_plan.hpp"
#include "analyze/integration.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/statistics.hpp"
#include "common/units.hpp"

namespace fourbar {

struct ChunkedAnalysis::Pending {
  std::size_t number = 0;
  bool leading_guard = false;
  std::vector<double> speed;
  std::vector<std::vector<double>> alpha, omega, omega_sq;  // per link; omega_sq empty without a normal channel
};

ChunkedAnalysis::ChunkedAnalysis(RecordingAnalysis& result, const Manifest& manifest, AnalysisChannels channels,
                                 RevolutionObserver* observer)
    : result_(result), manifest_(manifest), channels_(std::move(channels)), observer_(observer) {
  for (const LinkChannels& l : channels_.links)
    for (const auto* ch : {&l.tangential, &l.normal})
      if (*ch) used_.push_back((*ch)->index);
  samples_.resize(used_.size());
}

ChunkedAnalysis::~ChunkedAnalysis() = default;

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
  const double frames_per_rev = report.samples_per_turn;
  const double longest_frames = longest_segment_frames(report.pulses, fs_);

  filter_ = resolve_filter(o.filter, fs_, mean_crank_hz, longest_frames, result_.warnings);
  normal_filter_ = without_low_corner(filter_);
  const std::size_t taps = filter_kernel_taps(filter_, fs_);
  half_kernel_ = taps / 2;
  overlap_ = chunk_overlap_frames(taps, frames_per_rev);
  grid_ = {resolve_grid_points(o.points_per_rev, filter_, fs_, fastest_crank_hz, result_.warnings), offset_rad_,
           direction_};

  const double slowest_rev_frames = slowest_revolution_frames(fs_, report.speed.min_rpm);
  chunk_revs_ = plan_chunk_revolutions(o.chunk_revolutions, taps, overlap_, slowest_rev_frames, frames_per_rev);
  if (taps > 0)
    make_filter_blocks(filter_block_frames(chunk_revs_, slowest_rev_frames, overlap_, longest_frames, half_kernel_));
  make_spectra(resolve_spectrum_segment_frames(o.spectrum_segment, frames_per_rev, longest_frames));
  make_averagers();
  lay_out_result(taps);
}

void ChunkedAnalysis::make_filter_blocks(std::size_t block_frames) {
  alpha_filter_ = std::make_unique<FftFilter>(filter_, fs_, block_frames, Boundary::zero);
  if (channels_.links.front().normal || channels_.links.back().normal)
    normal_filter_block_ =
        std::make_unique<FftFilter>(normal_filter_, fs_, block_frames, Boundary::zero, alpha_filter_->transform());
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
  const std::size_t N = grid_.points_per_rev;
  tables_ = std::make_shared<const RigTables>(*manifest_.rig);
  speed_avg_ = std::make_unique<SynchronousAverager>(N);
  const std::size_t links = channels_.links.size();
  alpha_avg_.assign(links, SynchronousAverager(N));
  omega_avg_.assign(links, SynchronousAverager(N));
  normal_avg_.assign(links, SynchronousAverager(N));
  omega_sq_avg_.assign(links, SynchronousAverager(N));
  omega_carry_.assign(links, std::nullopt);
}

void ChunkedAnalysis::lay_out_result(std::size_t taps) {
  const std::size_t N = grid_.points_per_rev;
  result_.filter = filter_;
  result_.normal_filter = normal_filter_;
  result_.kernel_taps = taps;
  result_.chunk_revolutions = chunk_revs_;
  result_.points_per_rev = N;
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

std::size_t ChunkedAnalysis::rev_start(std::size_t rev) const { return starts_[rev - first_rev_]; }

void ChunkedAnalysis::on_samples(const SampleBlock& b) {
  if (!planned_) throw RunError("analyze: samples arrived before the acquisition plan");
  const double gap = 1.5 / fs_;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double t = b.time_s[i];
    const auto rev = b.revolution[i];
    if (in_segment_ && t - last_time_ > gap) end_segment();  // acquire dropped revolutions: a new segment
    if (!in_segment_) {
      in_segment_ = true;
      base_ = end_ = 0;
      starts_.clear();
      first_rev_ = next_rev_ = static_cast<std::size_t>(rev);
      last_rev_.reset();
      revs_in_segment_ = 0;
    }
    if (!last_rev_ || rev != *last_rev_) {
      starts_.push_back(end_);
      last_rev_ = rev;
    }
    // Continuous crank angle: θ2 of the sample plus the turns before it.
    theta_.push_back(b.crank_rad[i] + direction_ * units::kTwoPi * static_cast<double>(rev));
    speed_.push_back(b.omega2_rad_s[i]);
    accel_.push_back(b.alpha2_rad_s2[i]);
    for (std::size_t c = 0; c < used_.size(); ++c) samples_[c].push_back(b.channels_m_s2[used_[c]][i]);
    ++end_;
    last_time_ = t;
  }
  process_ready();
}

void ChunkedAnalysis::on_revolution(const Revolution& r) {
  if (clipped_.size() <= r.number) clipped_.resize(r.number + 1, false);
  clipped_[r.number] = r.clipped;
}

void ChunkedAnalysis::process_ready() {
  for (;;) {
    const std::size_t rb = next_rev_ + chunk_revs_;
    if (rb - first_rev_ >= starts_.size()) return;   // revolution rb has not begun
    if (end_ - rev_start(rb) < overlap_) return;     // nor half a kernel beyond it
    process_chunk(rb, false);
  }
}

void ChunkedAnalysis::process_chunk(std::size_t rb, bool segment_end) {
  const std::size_t sa = rev_start(next_rev_), sb = segment_end ? end_ : rev_start(rb);
  const std::size_t begin = std::max(base_, sa >= overlap_ ? sa - overlap_ : 0);
  const std::size_t stop = segment_end ? end_ : std::min(end_, sb + overlap_);
  const std::size_t n = stop - begin, off = begin - base_, c0 = sa - begin, c1 = sb - begin;
  const Rig& rig = *manifest_.rig;
  const CrankTrack crank{std::span(theta_).subspan(off, n), std::span(speed_).subspan(off, n),
                         std::span(accel_).subspan(off, n)};
  auto channel = [&](const AnalysisChannel& ch) {
    const std::size_t slot = static_cast<std::size_t>(std::find(used_.begin(), used_.end(), ch.index) - used_.begin());
    return std::span<const double>(samples_[slot]).subspan(off, n);
  };

  RecordAnalyzer analyzer(rig, crank, fs_, grid_, tables_);
  const RevolutionResampler& grid = analyzer.grid();
  const std::size_t links = channels_.links.size();
  std::vector<LinkGrids> grids(links);
  std::vector<std::vector<double>> normal_grid(links);
  const AnalyzeOptions& o = result_.options;
  for (std::size_t j = 0; j < links; ++j) {
    const LinkChannels& lc = channels_.links[j];
    const auto reading = channel(*lc.tangential);
    // α per sample, its spectrum over the chunk's own samples, filtered.
    // (Working arrays are members: reused, not allocated, chunk by chunk.)
    work_alpha_.resize(n);
    const std::span<double> alpha(work_alpha_);
    if (o.conversion == ConversionMethod::full)
      analyzer.converted(lc.tangential->mount, reading, {}, alpha);
    else
      thesis_angular_acceleration(rig, lc.link, 1, mean_speed_rad_s_, crank.angle_rad, reading, alpha);
    spectra_[j]->push(alpha.subspan(c0, c1 - c0));
    // The normal channel's offset term takes α before the band-pass: its
    // low-pass then filters that term as the rest of ω², and each sample
    // needs α only there (no second overlap for the α filter).
    if (lc.normal) work_unfiltered_.assign(alpha.begin(), alpha.end());
    filter(false, crank.angle_rad, alpha, begin == 0, segment_end);
    // ω: per revolution on the grid, or the running trapezoid in time.
    if (o.integration == IntegrationMethod::trapezoid) {
      std::vector<double> omega(n);
      cumulative_trapezoid(alpha, 1.0 / fs_, 0.0, omega);
      const double start =
          omega_carry_[j] ? *omega_carry_[j] : (*tables_)[lc.link].motion(crank.at(c0)).omega_rad_s;
      const double shift = start - omega[c0];
      for (double& w : omega) w += shift;
      if (!segment_end) omega_carry_[j] = omega[c1];
      grids[j].alpha_grid = grid.resample(alpha);
      grids[j].omega_grid = grid.resample(omega);
    } else {
      grids[j] = analyzer.on_grid(lc.link, alpha,
                                  o.integration == IntegrationMethod::closed_trapezoid ? PeriodicMethod::closed_trapezoid
                                                                                       : PeriodicMethod::spectral,
                                  o.integration == IntegrationMethod::spectral);
    }
    // The normal channel's ω².
    if (lc.normal) {
      work_w2_.resize(n);
      analyzer.converted(lc.normal->mount, channel(*lc.normal), work_unfiltered_, work_w2_);
      filter(true, crank.angle_rad, work_w2_, begin == 0, segment_end);
      normal_grid[j] = grid.resample(work_w2_);
    }
  }

  // The chunk's own revolutions, in order.
  const std::size_t N = grid_.points_per_rev;
  const std::vector<double>& speed = analyzer.crank_speed_grid();
  for (std::size_t r = 0; r < grid.revolutions(); ++r) {
    const long number = grid.first_revolution() + static_cast<long>(r);
    if (number < static_cast<long>(next_rev_) || number >= static_cast<long>(rb)) continue;
    auto row = [&](const std::vector<double>& v) {
      return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(r * N),
                                 v.begin() + static_cast<std::ptrdiff_t>((r + 1) * N));
    };
    Pending p;
    p.number = static_cast<std::size_t>(number);
    p.leading_guard = revs_in_segment_++ < o.guard_revolutions;
    p.speed = row(speed);
    for (std::size_t j = 0; j < links; ++j) {
      p.alpha.push_back(row(grids[j].alpha_grid));
      p.omega.push_back(row(grids[j].omega_grid));
      p.omega_sq.push_back(normal_grid[j].empty() ? std::vector<double>{} : row(normal_grid[j]));
    }
    accept(std::move(p));
  }
  next_rev_ = rb;
  if (segment_end) return;

  // Keep what the next chunk needs: from half a kernel before revolution rb.
  const std::size_t keep = std::max(base_, rev_start(rb) >= overlap_ ? rev_start(rb) - overlap_ : 0);
  const auto drop = static_cast<std::ptrdiff_t>(keep - base_);
  for (auto* v : {&theta_, &speed_, &accel_}) v->erase(v->begin(), v->begin() + drop);
  for (auto& v : samples_) v.erase(v.begin(), v.begin() + drop);
  base_ = keep;
  while (first_rev_ < rb) starts_.pop_front(), ++first_rev_;
}

void ChunkedAnalysis::filter(bool normal, std::span<const double> angle, std::span<double> x, bool at_start,
                             bool at_end) {
  const FilterSpec& spec = normal ? normal_filter_ : filter_;
  if (half_kernel_ == 0) {  // ideal: the chunk as one period
    FftFilter(spec, fs_, x.size(), Boundary::periodic).apply(x, x);
    return;
  }
  const std::size_t pre = at_start ? half_kernel_ : 0, post = at_end ? half_kernel_ : 0;
  const std::vector<double> before = pre ? crank_periodic_extension(angle, x, pre, direction_, true) : std::vector<double>{};
  const std::vector<double> after = post ? crank_periodic_extension(angle, x, post, direction_, false) : std::vector<double>{};
  FftFilter& block = normal ? *normal_filter_block_ : *alpha_filter_;
  if (pre + x.size() + post <= block.length()) {
    block.apply_between(before, x, after, x);
    return;
  }
  // A chunk longer than planned (a revolution slower than acquire's slowest).
  FftFilter(spec, fs_, pre + x.size() + post, Boundary::zero).apply_between(before, x, after, x);
}

void ChunkedAnalysis::accept(Pending&& rev) {
  const std::size_t guard = result_.options.guard_revolutions;
  if (guard == 0) return commit(rev, true);
  guard_queue_.push_back(std::make_unique<Pending>(std::move(rev)));
  if (guard_queue_.size() > guard) {
    commit(*guard_queue_.front(), !guard_queue_.front()->leading_guard);
    guard_queue_.pop_front();
  }
}

void ChunkedAnalysis::commit(Pending& rev, bool averaged) {
  const bool clipped = rev.number < clipped_.size() && clipped_[rev.number];
  if (averaged && clipped) ++result_.revolutions_clipped;
  averaged = averaged && !clipped;
  AnalyzedRevolution out;
  out.number = rev.number;
  out.averaged = averaged;
  out.crank_speed_rad_s = rev.speed;
  if (averaged) speed_avg_->add(rev.speed);
  if (result_.options.keep_revolutions) result_.revolution_numbers.push_back(rev.number);
  for (std::size_t j = 0; j < channels_.links.size(); ++j) {
    const bool coupler = channels_.links[j].link == SensedLink::coupler;
    LinkResult& lr = coupler ? *result_.coupler : *result_.rocker;
    (coupler ? out.alpha3_rad_s2 : out.alpha4_rad_s2) = rev.alpha[j];
    (coupler ? out.omega3_rad_s : out.omega4_rad_s) = rev.omega[j];
    if (result_.options.keep_revolutions) {
      lr.alpha_grid.insert(lr.alpha_grid.end(), rev.alpha[j].begin(), rev.alpha[j].end());
      lr.omega_grid.insert(lr.omega_grid.end(), rev.omega[j].begin(), rev.omega[j].end());
    }
    if (!averaged) continue;
    alpha_avg_[j].add(rev.alpha[j]);
    omega_avg_[j].add(rev.omega[j]);
    if (!rev.omega_sq[j].empty()) {
      normal_avg_[j].add(rev.omega_sq[j]);
      std::vector<double> sq(rev.omega[j].size());
      for (std::size_t k = 0; k < sq.size(); ++k) sq[k] = rev.omega[j][k] * rev.omega[j][k];
      omega_sq_avg_[j].add(sq);
    }
  }
  if (observer_) observer_->on_revolution(out);
}

void ChunkedAnalysis::end_segment() {
  if (!in_segment_) return;
  const bool too_short = half_kernel_ > 0 && end_ <= half_kernel_;  // never a chunk yet: end_ is the segment's length
  if (too_short)
    result_.warnings.push_back("pulse-train segment of " + format_number(double(end_) / fs_) + " s (revolutions " +
                               std::to_string(first_rev_) + " to " + std::to_string(*last_rev_) +
                               ") is shorter than half the filter kernel (" + format_number(double(half_kernel_) / fs_) +
                               " s): not analysed");
  else if (last_rev_ && static_cast<std::int64_t>(next_rev_) <= *last_rev_)
    process_chunk(static_cast<std::size_t>(*last_rev_) + 1, true);
  // The segment's last revolutions were guard revolutions.
  for (auto& p : guard_queue_) commit(*p, false);
  guard_queue_.clear();
  for (auto& s : spectra_) s->restart();
  for (auto& c : omega_carry_) c.reset();
  for (auto* v : {&theta_, &speed_, &accel_}) v->clear();
  for (auto& v : samples_) v.clear();
  starts_.clear();
  in_segment_ = false;
}

void ChunkedAnalysis::finish() {
  if (!planned_) return;
  end_segment();
  RecordingAnalysis& r = result_;
  r.revolutions = speed_avg_->revolutions();
  if (r.revolutions == 0)
    throw InputError("analyze: no revolution left to average (" + std::to_string(r.options.guard_revolutions) +
                     " guard revolutions at each segment end, " + std::to_string(r.revolutions_clipped) +
                     " clipped); give fewer --guard-revolutions or record longer");
  r.crank_speed_rad_s = speed_avg_->result();
  r.mean_crank_speed_rad_s = 0;
  for (double w : r.crank_speed_rad_s.mean) r.mean_crank_speed_rad_s += w / double(r.points_per_rev);
  r.spectra.segments = spectra_.front()->segments();
  if (r.spectra.segments == 0)
    r.warnings.push_back("no spectrum: every pulse-train segment is shorter than one spectrum segment of " +
                         std::to_string(r.spectra.segment_length) + " samples");
  if (r.revolutions_clipped > 0)
    r.warnings.push_back(std::to_string(r.revolutions_clipped) +
                         " clipped revolutions left out of the averages (a sample hit the input range)");
  for (std::size_t j = 0; j < channels_.links.size(); ++j) {
    LinkResult& lr = channels_.links[j].link == SensedLink::coupler ? *r.coupler : *r.rocker;
    lr.alpha_rad_s2 = alpha_avg_[j].result();
    lr.omega_rad_s = omega_avg_[j].result();
    lr.alpha_rms_rad_s2 = rms(lr.alpha_rad_s2.mean);
    lr.omega_rms_rad_s = rms(lr.omega_rad_s.mean);
    lr.alpha_std_rms_rad_s2 = rms(lr.alpha_rad_s2.std);
    lr.omega_std_rms_rad_s = rms(lr.omega_rad_s.std);
    lr.alpha_amplitude = spectra_[j]->amplitude();
    if (lr.normal) {
      lr.normal->omega_sq_rad2_s2 = normal_avg_[j].result();
      for (double w2 : lr.normal->omega_sq_rad2_s2.mean) lr.normal->omega_abs_rad_s.push_back(std::sqrt(std::max(0.0, w2)));
      lr.normal->omega_sq_integrated_rad2_s2 = omega_sq_avg_[j].result().mean;
      std::vector<double> diff(r.points_per_rev);
      for (std::size_t k = 0; k < diff.size(); ++k)
        diff[k] = lr.normal->omega_sq_rad2_s2.mean[k] - lr.normal->omega_sq_integrated_rad2_s2[k];
      lr.normal->rel_rms_difference = rms(diff) / rms(lr.normal->omega_sq_integrated_rad2_s2);
    }
  }
}

}  // namespace fourbar
