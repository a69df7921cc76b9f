#include "acquire/crank_smoothing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "common/error.hpp"
#include "common/format.hpp"
#include "common/statistics.hpp"
#include "common/units.hpp"

namespace fourbar {

std::size_t smoothing_knot_spacing(double period_turns, double edges_per_turn) {
  return std::max<std::size_t>(2, static_cast<std::size_t>(std::lround(period_turns * edges_per_turn / kSmoothingKnotsPerPeriod)));
}

double edge_timing_jitter(std::span<const double> t, std::span<const double> phi) {
  const std::size_t n = t.size();
  if (n < 5) return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> d;
  d.reserve(n - 4);
  for (std::size_t k = 0; k + 4 < n; ++k) {
    // 4th divided difference weights c_j = 1/∏_{i≠j}(φ_j − φ_i), normalised
    // so that white jitter of σ gives σ; any cubic t(φ) gives 0.
    double c[5], norm = 0, sum = 0;
    for (std::size_t j = 0; j < 5; ++j) {
      double p = 1;
      for (std::size_t i = 0; i < 5; ++i)
        if (i != j) p *= phi[k + j] - phi[k + i];
      c[j] = 1 / p, norm += c[j] * c[j];
    }
    for (std::size_t j = 0; j < 5; ++j) sum += c[j] * t[k + j];
    d.push_back(std::abs(sum) / std::sqrt(norm));
  }
  // A robust start (median |N(0, σ)| = 0.6745 σ), then the RMS of the
  // differences within 4 of it: as efficient as the plain RMS for Gaussian
  // jitter (the median alone needs 2.7 times the edges for the same
  // spread), yet a step or an outlier edge, a few large differences, is left out.
  const double start = median(d) / 0.6744897501960817;
  double sq = 0;
  std::size_t kept = 0;
  for (double x : d)
    if (x <= 4 * start) sq += x * x, ++kept;
  // Truncation at 4σ keeps 99.994 % of a Gaussian and 99.893 % of its variance.
  return kept > 0 ? std::sqrt(sq / static_cast<double>(kept) / 0.99893) : start;
}

SmoothedSegment smooth_segment(std::span<const double> times_s, std::span<const double> phases_rad,
                               std::size_t knot_spacing, std::size_t unsmoothed_knot_spacing) {
  SmoothedSegment s;
  s.track = std::make_shared<const AngleTrack>(times_s, phases_rad, knot_spacing);
  const AngleTrack& track = *s.track;
  const std::size_t n = times_s.size();
  SmoothingFit& f = s.fit;
  f.edges = n;
  f.jitter_s = edge_timing_jitter(times_s, phases_rad);
  if (!std::isfinite(f.jitter_s)) f.jitter_s = 0;
  const double dof = 1 - std::min(1.0, static_cast<double>(track.coefficients()) / static_cast<double>(n));
  f.expected_rms_s = f.jitter_s * std::sqrt(dof);
  // Blocks of at least two knot spacings (and kSmoothingMinBlockEdges).
  const std::size_t block = std::max(kSmoothingMinBlockEdges, 2 * knot_spacing);
  const std::size_t blocks = std::max<std::size_t>(1, n / block);
  double total = 0;
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t from = b * n / blocks, to = (b + 1) * n / blocks;
    double sq = 0, speed = 0;
    for (std::size_t k = from; k < to; ++k) {
      const double r = times_s[k] - track.knot(k).time_s;
      sq += r * r, speed += track.knot(k).speed_rad_s;
    }
    total += sq;
    const double count = static_cast<double>(to - from);
    const double rms = std::sqrt(sq / count);
    const double ratio = f.expected_rms_s > 0 ? rms / f.expected_rms_s : (rms > 0 ? INFINITY : 0.0);
    if (b == 0 || ratio > f.worst_ratio) {
      f.worst_ratio = ratio, f.worst_rms_s = rms;
      f.worst_rms_deg = units::rad_to_deg(rms * speed / count);
      f.worst_from_s = times_s[from], f.worst_to_s = times_s[to - 1];
    }
  }
  f.residual_rms_s = std::sqrt(total / static_cast<double>(n));
  // How far the smoothing moves the track from the unsmoothed one.
  std::optional<AngleTrack> unsmoothed;
  if (unsmoothed_knot_spacing > 0) unsmoothed.emplace(times_s, phases_rad, unsmoothed_knot_spacing);
  for (std::size_t k = 0; k < n; ++k) {
    const double d = track.knot(k).time_s - (unsmoothed ? unsmoothed->knot(k).time_s : times_s[k]);
    f.shift_sq_s2 += d * d;
  }
  const double m_unsmoothed = unsmoothed ? static_cast<double>(unsmoothed->coefficients()) : static_cast<double>(n);
  f.shift_noise_dof = std::max(0.0, m_unsmoothed - static_cast<double>(track.coefficients()));
  f.shift_noise_sq_s2 = f.jitter_s * f.jitter_s * f.shift_noise_dof;
  return s;
}

void CrankSmoothingReport::add(const SmoothingFit& f) {
  residual_sq_s2_ += f.residual_rms_s * f.residual_rms_s * static_cast<double>(f.edges);
  shift_sq_s2_ += f.shift_sq_s2, shift_noise_sq_s2_ += f.shift_noise_sq_s2, shift_noise_dof += f.shift_noise_dof;
  edges_ += f.edges;
  const auto n = static_cast<double>(std::max<std::size_t>(edges_, 1));
  residual_rms_s = std::sqrt(residual_sq_s2_ / n);
  shift_rms_s = std::sqrt(shift_sq_s2_ / n);
  shift_ratio = shift_noise_sq_s2_ > 0 ? std::sqrt(shift_sq_s2_ / shift_noise_sq_s2_) : 0.0;
  // A misfitting block outranks any that fits; among equals, the larger ratio.
  const bool replace = fit.edges == 0 || (f.misfit() && !fit.misfit()) ||
                       (f.misfit() == fit.misfit() && f.worst_ratio > fit.worst_ratio);
  if (replace) fit = f;
}

std::string smoothing_warning(const CrankSmoothingReport& r) {
  if (r.period_turns <= 0 || r.shift_noise_dof < kSmoothingWarnMinDof || !(r.shift_ratio > kSmoothingWarnRatio))
    return {};
  return "crank_smoothing = \"spline\" with smoothing_period_turns = " + format_number(r.period_turns, 4) +
         " moves the crank edges' times by " + format_number(r.shift_rms_s * 1e6, 3) + " µs RMS, " +
         format_number(r.shift_ratio, 3) + " times what their timing jitter of " +
         format_number(r.fit.jitter_s * 1e6, 3) +
         " µs explains: the run changes speed within that period, and the smoothed crank angle is no closer to the "
         "truth than the unsmoothed one (speed and acceleration may still be); lower smoothing_period_turns or set "
         "crank_smoothing = \"none\"";
}

void require_smoothing_fits(const CrankSmoothingReport& report, const Manifest& manifest,
                            const std::filesystem::path& recording) {
  const SmoothingFit& f = report.fit;
  if (report.period_turns <= 0 || !f.misfit()) return;
  const ChannelSpec& main = manifest.pulse_channel();
  const auto us = [](double s) { return s < 1e-3 ? format_number(s * 1e6, 3) + " µs" : format_number(s * 1e3, 3) + " ms"; };
  const std::string period = format_number(report.period_turns, 4);
  throw InputError(
      recording.string() + ": crank_smoothing = \"spline\" with smoothing_period_turns = " + period +
      " on channel '" + main.name + "' in " + manifest.file.string() + " does not fit the crank edges between " +
      format_number(f.worst_from_s, 4) + " s and " + format_number(f.worst_to_s, 4) + " s: they stray from the " +
      "smoothing spline by " + us(f.worst_rms_s) + " RMS (" + format_number(f.worst_rms_deg, 3) + "° of crank), " +
      format_number(f.worst_ratio, 3) + " times what their timing jitter of " + us(f.jitter_s) +
      " leaves; the crank speed changes there within fewer than " + period +
      " turns (a speed step, a run-up, a fluctuation), and the smoothed angle and speed would be off by "
      "that much. Lower smoothing_period_turns, cut the recording to its steady part, or set "
      "crank_smoothing = \"none\"");
}

}  // namespace fourbar
