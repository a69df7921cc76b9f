// ChunkedAnalysis's per-chunk transform (chunked_analysis.hpp): one chunk's
// samples to α per sample (its spectrum taken before the filter), the
// zero-phase filter with the segment ends continued periodically, ω by
// integration, the normal channel's ω² (its AC-coupling offset term from the
// unfiltered α), all resampled onto the crank-angle grid; then the chunk's
// own revolutions are handed on in order.
#include "analyze/chunked_analysis.hpp"

#include <algorithm>

#include "analyze/integration.hpp"

namespace fourbar {

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
  const std::size_t N = grid_.grid_points_per_rev;
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
  if (!segment_end) keep_from(rb);
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

}  // namespace fourbar
