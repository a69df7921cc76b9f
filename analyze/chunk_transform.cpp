// ChunkedAnalysis's per-chunk transform (chunked_analysis.hpp): one chunk's
// samples to α per sample (its spectrum's samples kept before the filter, the
// spectrum segments that lie inside the chunk transformed),
// the zero-phase filter with the segment ends continued periodically, ω by
// integration, the normal channel's ω² (its AC-coupling offset term from the
// unfiltered α), all resampled onto the crank-angle grid. transform() reads
// only its job, the settings and its workspace (chunks may run at once);
// deliver() then takes what carries over from chunk to chunk, in order: the
// spectra, the running trapezoid's start value, the revolutions.
#include "analyze/chunked_analysis.hpp"

#include <algorithm>

#include "analyze/integration.hpp"
#include "common/reused_vector.hpp"

namespace fourbar {

void ChunkedAnalysis::transform(const ChunkJob& job, ChunkWorkspace& w, ChunkOutcome& out) const {
  const std::size_t n = job.theta.size(), c0 = job.c0, c1 = job.c1;
  const Rig& rig = *manifest_.rig;
  const CrankTrack crank{job.theta, job.speed, job.accel};
  auto channel = [&](const AnalysisChannel& ch) {
    const std::size_t slot = static_cast<std::size_t>(std::find(used_.begin(), used_.end(), ch.index) - used_.begin());
    return job.samples[slot];
  };

  // The workspace's analyzer planned for this chunk; `out` is an earlier
  // chunk's outcome (or new): every field is set here, in memory reused.
  if (w.analyzer) w.analyzer->reset(crank);
  else w.analyzer.emplace(rig, crank, fs_, grid_, tables_);
  RecordAnalyzer& analyzer = *w.analyzer;
  const RevolutionResampler& grid = analyzer.grid();
  const std::size_t links = channels_.links.size();
  out.rev_begin = job.rev_begin, out.rev_end = job.rev_end, out.segment_end = job.segment_end;
  out.first_revolution = grid.first_revolution();
  out.revolutions = grid.revolutions();
  const std::vector<double>& speed = analyzer.crank_speed_grid();
  assign_reusing(out.speed, speed.begin(), speed.end());
  out.grids.resize(links);
  out.normal_grid.resize(links);
  out.spectrum_samples.resize(links);
  out.spectrum_powers.resize(links);
  const AnalyzeOptions& o = result_.options;
  const bool trapezoid = o.integration == IntegrationMethod::trapezoid;
  if (trapezoid) {
    out.omega_samples.resize(links);
    out.nominal_start_omega.resize(links);
    out.c0 = c0, out.c1 = c1;
    out.resampler = grid;
  }
  const std::size_t segment = spectra_.front()->segment_length();
  if (!w.spectrum_fft || w.spectrum_fft->size() != segment) w.spectrum_fft = std::make_unique<RealFft>(segment);
  for (std::size_t j = 0; j < links; ++j) {
    const LinkChannels& lc = channels_.links[j];
    const auto reading = channel(*lc.tangential);
    // α per sample, the samples of its spectrum (the chunk's own), filtered.
    // (Working arrays are the workspace's: reused, not allocated, chunk by chunk.)
    resize_reusing(w.alpha, n);
    const std::span<double> alpha(w.alpha);
    if (o.conversion == ConversionMethod::full)
      analyzer.converted(lc.tangential->mount, reading, {}, alpha);
    else
      thesis_angular_acceleration(rig, lc.link, 1, mean_speed_rad_s_, crank.angle_rad, reading, alpha);
    assign_reusing(out.spectrum_samples[j], alpha.begin() + static_cast<std::ptrdiff_t>(c0),
                   alpha.begin() + static_cast<std::ptrdiff_t>(c1));
    spectra_[j]->segment_powers(out.spectrum_samples[j], job.stream_at, *w.spectrum_fft, out.spectrum_powers[j]);
    // The normal channel's offset term takes α before the band-pass: its
    // low-pass then filters that term as the rest of ω², and each sample
    // needs α only there (no second overlap for the α filter).
    if (lc.normal) assign_reusing(w.unfiltered, alpha.begin(), alpha.end());
    filter(false, crank.angle_rad, alpha, job.at_start, job.segment_end, w);
    // ω: per revolution on the grid, or the running trapezoid in time (its
    // start carries from the previous chunk: shifted and resampled in deliver()).
    if (trapezoid) {
      resize_reusing(out.omega_samples[j], n);
      cumulative_trapezoid(alpha, 1.0 / fs_, 0.0, out.omega_samples[j]);
      out.nominal_start_omega[j] = (*tables_)[lc.link].motion(crank.at(c0)).omega_rad_s;
      grid.resample(alpha, out.grids[j].alpha_grid);
    } else {
      analyzer.on_grid(lc.link, alpha,
                       o.integration == IntegrationMethod::closed_trapezoid ? PeriodicMethod::closed_trapezoid
                                                                            : PeriodicMethod::spectral,
                       o.integration == IntegrationMethod::spectral, out.grids[j]);
    }
    // The normal channel's ω².
    if (lc.normal) {
      resize_reusing(w.w2, n);
      analyzer.converted(lc.normal->mount, channel(*lc.normal), w.unfiltered, w.w2);
      filter(true, crank.angle_rad, w.w2, job.at_start, job.segment_end, w);
      grid.resample(w.w2, out.normal_grid[j]);
    } else {
      out.normal_grid[j].clear();
    }
  }
}

void ChunkedAnalysis::deliver(std::unique_ptr<ChunkOutcome> outcome) {
  ChunkOutcome& c = *outcome;
  const std::size_t links = channels_.links.size();
  for (std::size_t j = 0; j < links; ++j) spectra_[j]->push(c.spectrum_samples[j], c.spectrum_powers[j]);
  // The running trapezoid: ω from the previous chunk's end (or the nominal
  // ω at a segment's first sample), then onto the grid.
  for (std::size_t j = 0; j < c.omega_samples.size(); ++j) {
    std::vector<double>& omega = c.omega_samples[j];
    const double start = omega_carry_[j] ? *omega_carry_[j] : c.nominal_start_omega[j];
    const double shift = start - omega[c.c0];
    for (double& wv : omega) wv += shift;
    if (!c.segment_end) omega_carry_[j] = omega[c.c1];
    c.resampler->resample(omega, c.grids[j].omega_grid);
  }

  // The chunk's own revolutions, in order.
  const std::size_t N = grid_.grid_points_per_rev;
  const AnalyzeOptions& o = result_.options;
  for (std::size_t r = 0; r < c.revolutions; ++r) {
    const long number = c.first_revolution + static_cast<long>(r);
    if (number < static_cast<long>(c.rev_begin) || number >= static_cast<long>(c.rev_end)) continue;
    auto row = [&](const std::vector<double>& v) {
      return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(r * N),
                                 v.begin() + static_cast<std::ptrdiff_t>((r + 1) * N));
    };
    Pending p;
    p.number = static_cast<std::size_t>(number);
    p.index_in_segment = revs_in_segment_;
    p.leading_guard = revs_in_segment_++ < o.guard_revolutions;
    p.speed = row(c.speed);
    for (std::size_t j = 0; j < links; ++j) {
      p.alpha.push_back(row(c.grids[j].alpha_grid));
      p.omega.push_back(row(c.grids[j].omega_grid));
      p.omega_sq.push_back(c.normal_grid[j].empty() ? std::vector<double>{} : row(c.normal_grid[j]));
    }
    accept(std::move(p));
  }
  const std::lock_guard lock(workspace_mutex_);
  spare_outcomes_.push_back(std::move(outcome));
}

void ChunkedAnalysis::filter(bool normal, std::span<const double> angle, std::span<double> x, bool at_start,
                             bool at_end, ChunkWorkspace& w) const {
  const FilterSpec& spec = normal ? normal_filter_ : filter_;
  if (half_kernel_ == 0) {  // ideal: the chunk as one period
    FftFilter(spec, fs_, x.size(), Boundary::periodic).apply(x, x);
    return;
  }
  const std::size_t pre = at_start ? half_kernel_ : 0, post = at_end ? half_kernel_ : 0;
  const std::vector<double> before = pre ? crank_periodic_extension(angle, x, pre, direction_, true) : std::vector<double>{};
  const std::vector<double> after = post ? crank_periodic_extension(angle, x, post, direction_, false) : std::vector<double>{};
  FftFilter& block = normal ? *w.normal_filter : *w.alpha_filter;
  if (pre + x.size() + post <= block.length()) {
    block.apply_between(before, x, after, x);
    return;
  }
  // A chunk longer than planned (a revolution slower than acquire's slowest).
  FftFilter(spec, fs_, pre + x.size() + post, Boundary::zero).apply_between(before, x, after, x);
}

}  // namespace fourbar
