#include "analyze/filter_design.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

[[noreturn]] void bad(const std::string& key, double value, const std::string& fix) {
  std::ostringstream os;
  os << "filter " << key << " = " << value << ": " << fix;
  throw InputError(os.str());
}

void check_corner(const char* key, double f, double nyquist) {
  if (!std::isfinite(f)) bad(key, f, "not a number");
  if (f <= 0) bad(key, f, "a corner must be positive");
  if (f >= nyquist) {
    std::ostringstream os;
    os << "the band lies above the Nyquist frequency " << nyquist << " Hz (half the sample rate); give a corner below it";
    bad(key, f, os.str());
  }
}

// Σ over the band edges of ±sin(2π·f_e·i/fs) for i = 0 … m (the ideal
// kernel is that divided by π·i): each edge's sine by a rotation recurrence,
// re-seeded from std::sin/cos every 64 taps so the rounding cannot grow.
std::vector<double> edge_sine_sums(const std::vector<Band>& bands, double fs, std::size_t m) {
  std::vector<double> sum(m + 1, 0.0);
  for (const Band& b : bands)
    for (const auto& [f, sign] : {std::pair{b.hi_hz, 1.0}, std::pair{b.lo_hz, -1.0}}) {
      const double step = units::kTwoPi * f / fs;
      const double cs = std::cos(step), sn = std::sin(step);
      double c = 1, s = 0;
      for (std::size_t i = 0; i <= m; ++i) {
        if (i % 64 == 0) c = std::cos(step * i), s = std::sin(step * i);
        sum[i] += sign * s;
        const double c_next = c * cs - s * sn;
        s = s * cs + c * sn;
        c = c_next;
      }
    }
  return sum;
}

}  // namespace

void validate_filter(const FilterSpec& s, double fs) {
  if (!(fs > 0) || !std::isfinite(fs)) bad("sample_rate_hz", fs, "the sample rate must be positive");
  const double nyq = 0.5 * fs;
  if (uses_low(s.band)) check_corner("low_hz", s.low_hz, nyq);
  if (uses_high(s.band)) check_corner("high_hz", s.high_hz, nyq);
  if ((s.band == BandType::bandpass || s.band == BandType::bandstop) && !(s.low_hz < s.high_hz))
    bad("low_hz", s.low_hz, "must be below high_hz = " + std::to_string(s.high_hz));
  if (s.mains_hz != 0) {
    check_corner("mains_hz", s.mains_hz, nyq);
    if (!(s.mains_width_hz > 0) || !(s.mains_width_hz < s.mains_hz))
      bad("mains_width_hz", s.mains_width_hz, "a notch width must be positive and below the mains frequency");
  }
  validate_window(s.window, "filter window");
  if (!(s.transition_hz >= 0) || !std::isfinite(s.transition_hz) || s.transition_hz >= nyq)
    bad("transition_hz", s.transition_hz, "must be >= 0 and below the Nyquist frequency");
  if (s.transition_hz == 0 && s.window.type != WindowType::rectangular)
    bad("transition_hz", 0.0,
        "the " + to_string(s.window) +
            " window shapes a transition band, so give its width (> 0), or use the rectangular window for the "
            "ideal bin-wise filter");
}

std::vector<Band> pass_bands(const FilterSpec& s, double fs) {
  validate_filter(s, fs);
  const double nyq = 0.5 * fs;
  std::vector<Band> bands;
  switch (s.band) {
    case BandType::all_pass: bands = {{0, nyq}}; break;
    case BandType::lowpass: bands = {{0, s.high_hz}}; break;
    case BandType::highpass: bands = {{s.low_hz, nyq}}; break;
    case BandType::bandpass: bands = {{s.low_hz, s.high_hz}}; break;
    case BandType::bandstop: bands = {{0, s.low_hz}, {s.high_hz, nyq}}; break;
  }
  if (s.mains_hz == 0) return bands;
  // Cut each notch (k·f_mains ± width/2) out of the bands.
  for (int k = 1; k * s.mains_hz - 0.5 * s.mains_width_hz < nyq; ++k) {
    const double lo = k * s.mains_hz - 0.5 * s.mains_width_hz, hi = k * s.mains_hz + 0.5 * s.mains_width_hz;
    std::vector<Band> cut;
    for (const Band& b : bands) {
      if (hi <= b.lo_hz || lo >= b.hi_hz) {
        cut.push_back(b);
        continue;
      }
      if (lo > b.lo_hz) cut.push_back({b.lo_hz, lo});
      if (hi < b.hi_hz) cut.push_back({hi, b.hi_hz});
    }
    bands = std::move(cut);
  }
  return bands;
}

bool passes(const std::vector<Band>& bands, double f) {
  const double a = std::abs(f);
  return std::any_of(bands.begin(), bands.end(), [a](const Band& b) { return a >= b.lo_hz && a <= b.hi_hz; });
}

std::size_t kernel_taps(const FilterSpec& s, double fs) {
  validate_filter(s, fs);
  if (s.transition_hz == 0) throw InputError("filter transition_hz = 0: a kernel needs a transition width > 0");
  const auto half = static_cast<std::size_t>(std::ceil(0.5 * main_lobe_width_bins(s.window) * fs / s.transition_hz));
  return 2 * std::max<std::size_t>(half, 1) + 1;
}

std::vector<double> design_kernel(const FilterSpec& s, double fs) {
  const std::size_t taps = kernel_taps(s, fs);
  const std::vector<Band> bands = pass_bands(s, fs);
  const std::vector<double> w = make_window(s.window, taps, WindowSymmetry::symmetric);
  const long m = static_cast<long>(taps / 2);
  std::vector<double> h(taps);
  // Ideal kernel of the bands: Σ [sin(2π·hi·i/fs) − sin(2π·lo·i/fs)]/(π·i),
  // and Σ 2(hi − lo)/fs at i = 0; symmetric, h[−i] = h[i].
  const std::vector<double> sines = edge_sine_sums(bands, fs, static_cast<std::size_t>(m));
  double centre = 0;
  for (const Band& b : bands) centre += 2.0 * (b.hi_hz - b.lo_hz) / fs;
  h[m] = centre * w[m];
  for (long i = 1; i <= m; ++i) h[m + i] = h[m - i] = sines[i] / (units::kPi * i) * w[m + i];
  return h;
}

std::string describe(const FilterSpec& s) {
  std::ostringstream os;
  switch (s.band) {
    case BandType::all_pass: os << "all-pass"; break;
    case BandType::lowpass: os << "low-pass " << s.high_hz << " Hz"; break;
    case BandType::highpass: os << "high-pass " << s.low_hz << " Hz"; break;
    case BandType::bandpass: os << "band-pass " << s.low_hz << "-" << s.high_hz << " Hz"; break;
    case BandType::bandstop: os << "band-stop " << s.low_hz << "-" << s.high_hz << " Hz"; break;
  }
  if (s.mains_hz != 0) os << ", mains comb " << s.mains_hz << " Hz x k (width " << s.mains_width_hz << " Hz)";
  if (s.transition_hz == 0) os << ", ideal (bin-wise, rectangular)";
  else os << ", window " << to_string(s.window) << ", transition " << s.transition_hz << " Hz";
  return os.str();
}

}  // namespace fourbar
