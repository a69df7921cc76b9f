// Resolution of the filter, grid and spectrum settings (analysis_settings.hpp).
#include "analyze/analysis_settings.hpp"

#include <algorithm>
#include <cmath>

#include "analyze/analysis_defaults.hpp"
#include "analyze/window.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

namespace fourbar {

double longest_segment_frames(const PulseTrain& pulses, double sample_rate_hz) {
  double longest_frames = 0;  // pulse-train segments, in samples
  for (const auto& seg : pulses.segments) {
    if (seg.size() < 2) continue;
    const double len = (seg.back().time_s - seg.front().time_s) * sample_rate_hz;
    longest_frames = std::max(longest_frames, len);
  }
  return longest_frames;
}

FilterSpec resolve_filter(const FilterSettings& s, double sample_rate_hz, double mean_crank_hz, double longest_frames,
                          std::vector<std::string>& warnings) {
  namespace defaults = analysis_defaults;
  // The α filter, defaults following the crank speed and the sample rate.
  FilterSpec f;
  f.band = s.band;
  if (uses_low(f.band)) f.low_hz = s.low_hz.value_or(defaults::kLowCornerPerCrankHz * mean_crank_hz);
  if (uses_high(f.band))
    f.high_hz = s.high_hz.value_or(
        std::min(defaults::kHighCornerCapHz, defaults::kHighCornerMaxPerSampleRate * sample_rate_hz));
  f.mains_hz = s.mains_hz;
  f.mains_width_hz = s.mains_width_hz;
  f.window = s.window;
  f.transition_hz = s.transition_hz.value_or(defaults::kTransitionPerCrankHz * mean_crank_hz);
  try {
    validate_filter(f, sample_rate_hz);
  } catch (const InputError& e) {
    throw InputError(std::string("analyze: ") + e.what() + " (sample rate " + format_number(sample_rate_hz) + " Hz)");
  }
  if (f.transition_hz > 0 && kernel_taps(f, sample_rate_hz) / 2 + 1 > static_cast<std::size_t>(longest_frames)) {
    // The kernel must not be longer than twice the longest segment (shorter
    // segments are left out, with a warning, in end_segment).
    const std::string where = "the longest pulse-train segment (" + format_number(longest_frames / sample_rate_hz) + " s)";
    if (s.transition_hz)
      throw InputError("analyze: a " + format_number(f.transition_hz) + " Hz transition needs a kernel of " +
                       std::to_string(kernel_taps(f, sample_rate_hz)) + " taps, longer than twice " + where +
                       "; give a wider --transition-hz, or --window rectangular --transition-hz 0 (ideal filter)");
    const double wider = 0.5 * main_lobe_width_bins(f.window) * sample_rate_hz / (longest_frames - 2.0) * 1.01;
    if (!(wider <= 0.8 * mean_crank_hz) || longest_frames < 4)
      throw InputError("analyze: " + where + " is too short for a windowed filter that keeps the crank frequency (" +
                       format_number(mean_crank_hz) + " Hz); record longer, or use --window rectangular --transition-hz 0 (ideal filter)");
    warnings.push_back("filter transition widened from " + format_number(f.transition_hz) + " Hz to " +
                       format_number(wider) + " Hz so that its kernel fits " + where);
    f.transition_hz = wider;
  }
  return f;
}

// ω² has a mean: the normal channels keep everything below the upper corner.
FilterSpec without_low_corner(FilterSpec f) {
  if (f.band == BandType::bandpass) f.band = BandType::lowpass;
  else if (f.band == BandType::highpass) f.band = BandType::all_pass;
  if (!uses_low(f.band)) f.low_hz = 0;
  return f;
}

std::size_t filter_kernel_taps(const FilterSpec& f, double sample_rate_hz) {
  return f.transition_hz > 0 ? kernel_taps(f, sample_rate_hz) : 0;
}

std::size_t resolve_grid_points(std::size_t requested_points, const FilterSpec& f, double sample_rate_hz,
                                double fastest_crank_hz, std::vector<std::string>& warnings) {
  namespace defaults = analysis_defaults;
  // The grid: N crank angles that hold the pass band at the fastest revolution.
  const double upper = uses_high(f.band) ? f.high_hz + 0.5 * f.transition_hz : 0.5 * sample_rate_hz;
  const auto needed =
      static_cast<std::size_t>(std::ceil(upper / (defaults::kGridMaxOrdersPerPoint * fastest_crank_hz)));
  std::size_t N = requested_points;
  if (N == 0) {
    N = defaults::kGridPoints;
    while (N < needed) N += defaults::kGridPointsStep;
  } else if (N < needed) {
    warnings.push_back("grid of " + std::to_string(N) + " crank angles holds " + format_number(0.5 * N) + " orders (" +
                       format_number(0.5 * N * fastest_crank_hz) + " Hz at the fastest revolution) but the filter passes up to " +
                       format_number(upper) + " Hz: the grid aliases; give --points " + std::to_string(needed) + " or more");
  }
  return N;
}

std::size_t resolve_spectrum_segment_frames(std::size_t requested_frames, double frames_per_rev,
                                            double longest_frames) {
  // Spectrum segments: a power of two ≥ 8 revolutions, within the longest segment.
  std::size_t seg = requested_frames;
  if (seg == 0) {
    seg = 16;
    while (double(seg) < 8 * frames_per_rev) seg *= 2;
    while (double(seg) > longest_frames && seg > 16) seg /= 2;
  }
  return seg;
}

}  // namespace fourbar
