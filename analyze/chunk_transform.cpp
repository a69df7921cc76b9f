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

namespace fourbar {

ChunkedAnalysis::ChunkOutcome ChunkedAnalysis::transform(const ChunkJob& job, ChunkWorkspace& w) const {
  const std::size_t n = job.theta.size(), c0 = job.c0, c1 = job.c1;
  const Rig& rig = *manifest_.rig;
  const CrankTrack crank{job.theta, job.speed, job.accel};
  auto channel = [&](const AnalysisChannel& ch) {
    const std::size_t slot = static_cast<std::size_t>(std::find(used_.begin(), used_.end(), ch.index) - used_.begin());
    return job.samples[slot];
  };

  RecordAnalyzer analyzer(rig, crank, fs_, grid_, tables_);
  const RevolutionResampler& grid = analyzer.grid();
  const std::size_t links = channels_.links.size();
  ChunkOutcome out;
  out.rev_begin = job.rev_begin, out.rev_end = job.rev_end, out.segment_end = job.segment_end;
  out.first_revolution = grid.first_revolution();
  out.revolutions = grid.revolutions();
  out.speed = analyzer.crank_speed_grid();
  out.grids.resize(links);
  out.normal_grid.resize(links);
  out.spectrum_samples.resize(links);
  const AnalyzeOptions& o = result_.options;
  const bool trapezoid = o.integration == IntegrationMethod::trapezoid;
  if (trapezoid) {
    out.omega_samples.resize(links);
    out.nominal_start_omega.resize(links);
    out.c0 = c0, out.c1 = c1;
    out.resampler = grid;
  }
  for (std::size_t j = 0; j < links; ++j) {
    const LinkChannels& lc = channels_.links[j];
    const auto reading = channel(*lc.tangential);
    // α per sample, the samples of its spectrum (the chunk's own), filtered.
    // (Working arrays are the workspace's: reused, not allocated, chunk by chunk.)
    w.alpha.resize(n);
    const std::span<double> alpha(w.alpha);
    if (o.conversion == ConversionMethod::full)
      analyzer.converted(lc.tangential->mount, reading, {}, alpha);
    else
      thesis_angular_acceleration(rig, lc.link, 1, mean_speed_rad_s_, crank.angle_rad, reading, alpha);
    out.spectrum_samples[j].assign(alpha.begin() + static_cast<std::ptrdiff_t>(c0),
                                   alpha.begin() + static_cast<std::ptrdiff_t>(c1));
    out.spectrum_powers.push_back(spectra_[j]->segment_powers(out.spectrum_samples[j], job.stream_at));
    // The normal channel's offset term takes α before the band-pass: its
    // low-pass then filters that term as the rest of ω², and each sample
    // needs α only there (no second overlap for the α filter).
    if (lc.normal) w.unfiltered.assign(alpha.begin(), alpha.end());
    filter(false, crank.angle_rad, alpha, job.at_start, job.segment_end, w);
    // ω: per revolution on the grid, or the running trapezoid in time (its
    // start carries from the previous chunk: shifted and resampled in deliver()).
    if (trapezoid) {
      out.omega_samples[j].resize(n);
      cumulative_trapezoid(alpha, 1.0 / fs_, 0.0, out.omega_samples[j]);
      out.nominal_start_omega[j] = (*tables_)[lc.link].motion(crank.at(c0)).omega_rad_s;
      out.grids[j].alpha_grid = grid.resample(alpha);
    } else {
      out.grids[j] = analyzer.on_grid(lc.link, alpha,
                                      o.integration == IntegrationMethod::closed_trapezoid
                                          ? PeriodicMethod::closed_trapezoid
                                          : PeriodicMethod::spectral,
                                      o.integration == IntegrationMethod::spectral);
    }
    // The normal channel's ω².
    if (lc.normal) {
      w.w2.resize(n);
      analyzer.converted(lc.normal->mount, channel(*lc.normal), w.unfiltered, w.w2);
      filter(true, crank.angle_rad, w.w2, job.at_start, job.segment_end, w);
      out.normal_grid[j] = grid.resample(w.w2);
    }
  }
  return out;
}

void ChunkedAnalysis::deliver(ChunkOutcome&& c) {
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
    c.grids[j].omega_grid = c.resampler->resample(omega);
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
    p.leading_guard = revs_in_segment_++ < o.guard_revolutions;
    p.speed = row(c.speed);
    for (std::size_t j = 0; j < links; ++j) {
      p.alpha.push_back(row(c.grids[j].alpha_grid));
      p.omega.push_back(row(c.grids[j].omega_grid));
      p.omega_sq.push_back(c.normal_grid[j].empty() ? std::vector<double>{} : row(c.normal_grid[j]));
    }
    accept(std::move(p));
  }
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
