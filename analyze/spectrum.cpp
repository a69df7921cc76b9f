#include "analyze/spectrum.hpp"

#include <cassert>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>

#include "analyze/fftw_plan.hpp"
#include "common/error.hpp"
#include "common/units.hpp"

namespace fourbar {

namespace {

void check_rate(double fs) {
  if (!(fs > 0) || !std::isfinite(fs)) {
    std::ostringstream os;
    os << "spectrum: sample rate " << fs << " Hz must be positive";
    throw InputError(os.str());
  }
}

std::vector<double> frequencies(std::size_t n, double fs) {
  std::vector<double> f(n / 2 + 1);
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = fs * k / n;
  return f;
}

}  // namespace

Spectrum amplitude_spectrum(std::span<const double> x, double fs, const WindowSpec& window) {
  check_rate(fs);
  validate_window(window, "spectrum window");
  if (x.size() < 2) throw InputError("spectrum: need at least 2 samples");
  const std::size_t n = x.size();
  const std::vector<double> w = make_window(window, n, WindowSymmetry::periodic);
  const double gain = std::accumulate(w.begin(), w.end(), 0.0);  // coherent gain × n
  RealFft fft(n);
  auto t = fft.time();
  for (std::size_t i = 0; i < n; ++i) t[i] = x[i] * w[i];
  fft.forward();
  Spectrum s{frequencies(n, fs), std::vector<double>(fft.bins())};
  for (std::size_t k = 0; k < s.value.size(); ++k) {
    const bool edge = k == 0 || (n % 2 == 0 && k == n / 2);  // DC and Nyquist have no mirror bin
    s.value[k] = std::abs(fft.spectrum()[k]) * (edge ? 1.0 : 2.0) / gain;
  }
  return s;
}

Spectrum welch_psd(std::span<const double> x, double fs, const WelchOptions& o) {
  check_rate(fs);
  validate_window(o.window, "Welch window");
  const std::size_t m = o.segment_length;
  if (m < 2 || m > x.size()) {
    std::ostringstream os;
    os << "Welch: segment length " << m << " must be between 2 and the record length " << x.size();
    throw InputError(os.str());
  }
  if (o.overlap >= m) {
    std::ostringstream os;
    os << "Welch: overlap " << o.overlap << " must be below the segment length " << m;
    throw InputError(os.str());
  }
  const std::vector<double> w = make_window(o.window, m, WindowSymmetry::periodic);
  double power = 0;
  for (double v : w) power += v * v;
  RealFft fft(m);
  Spectrum s{frequencies(m, fs), std::vector<double>(fft.bins(), 0.0)};
  const std::size_t step = m - o.overlap;
  std::size_t segments = 0;
  for (std::size_t at = 0; at + m <= x.size(); at += step, ++segments) {
    const auto seg = x.subspan(at, m);
    const double mean = std::accumulate(seg.begin(), seg.end(), 0.0) / m;
    auto t = fft.time();
    for (std::size_t i = 0; i < m; ++i) t[i] = (seg[i] - mean) * w[i];
    fft.forward();
    for (std::size_t k = 0; k < s.value.size(); ++k) s.value[k] += std::norm(fft.spectrum()[k]);
  }
  // One-sided density: |X|²/(fs·Σw²), doubled except at DC and Nyquist.
  for (std::size_t k = 0; k < s.value.size(); ++k) {
    const bool edge = k == 0 || (m % 2 == 0 && k == m / 2);
    s.value[k] *= (edge ? 1.0 : 2.0) / (fs * power * segments);
  }
  return s;
}

SpectrumAverager::SpectrumAverager(double fs, const WelchOptions& o)
    : fs_(fs), m_(o.segment_length), step_(o.segment_length - o.overlap) {
  check_rate(fs);
  validate_window(o.window, "spectrum window");
  if (m_ < 2 || o.overlap >= m_) {
    std::ostringstream os;
    os << "spectrum: segment length " << m_ << " must be at least 2 and above the overlap " << o.overlap;
    throw InputError(os.str());
  }
  window_ = make_window(o.window, m_, WindowSymmetry::periodic);
  for (double v : window_) gain_ += v, power_ += v * v;
  fft_ = std::make_unique<RealFft>(m_);
  sum_.assign(fft_->bins(), 0.0);
  pending_.reserve(m_);
}

SpectrumAverager::~SpectrumAverager() = default;

void SpectrumAverager::push(std::span<const double> x) {
  SegmentPowers none;
  none.at = position_;
  push(x, none);
}

void SpectrumAverager::push(std::span<const double> x, const SegmentPowers& powers) {
  if (powers.at != position_)
    throw std::logic_error("spectrum: segment powers of the piece at sample " + std::to_string(powers.at) +
                           " pushed at sample " + std::to_string(position_));
  position_ += x.size();
  while (!x.empty()) {
    const std::size_t take = std::min(x.size(), m_ - pending_.size());
    pending_.insert(pending_.end(), x.begin(), x.begin() + static_cast<std::ptrdiff_t>(take));
    x = x.subspan(take);
    if (pending_.size() == m_) {
      run_segment(&powers);
      pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(step_));
    }
  }
}

void SpectrumAverager::restart() {
  pending_.clear();
  position_ = since_restart_ = 0;
}

void SpectrumAverager::transform_segment(std::span<const double> segment, RealFft& fft) const {
  const double mean = std::accumulate(segment.begin(), segment.end(), 0.0) / static_cast<double>(m_);
  auto t = fft.time();
  for (std::size_t i = 0; i < m_; ++i) t[i] = (segment[i] - mean) * window_[i];
  fft.forward();
}

SpectrumAverager::SegmentPowers SpectrumAverager::segment_powers(std::span<const double> x, std::size_t at) const {
  SegmentPowers out;
  RealFft fft(m_);
  segment_powers(x, at, fft, out);
  return out;
}

void SpectrumAverager::segment_powers(std::span<const double> x, std::size_t at, RealFft& fft, SegmentPowers& out) const {
  assert(fft.size() == m_);
  out.at = at;
  out.first = (at + step_ - 1) / step_;
  std::size_t count = 0;
  for (std::size_t k = out.first; k * step_ + m_ <= at + x.size(); ++k) {
    transform_segment(x.subspan(k * step_ - at, m_), fft);
    const auto s = fft.spectrum();
    if (out.power.size() <= count) out.power.emplace_back();
    std::vector<double>& p = out.power[count++];
    p.resize(s.size());
    for (std::size_t b = 0; b < p.size(); ++b) p[b] = std::norm(s[b]);
  }
  out.power.resize(count);
}

void SpectrumAverager::run_segment(const SegmentPowers* powers) {
  const std::size_t k = since_restart_++;
  ++segments_;
  if (powers && k >= powers->first && k - powers->first < powers->power.size()) {
    const std::vector<double>& p = powers->power[k - powers->first];
    for (std::size_t b = 0; b < sum_.size(); ++b) sum_[b] += p[b];
    return;
  }
  transform_segment(pending_, *fft_);
  const auto s = fft_->spectrum();
  for (std::size_t b = 0; b < sum_.size(); ++b) sum_[b] += std::norm(s[b]);
}

std::vector<double> SpectrumAverager::frequency_hz() const { return frequencies(m_, fs_); }

namespace {
// One-sided factor: 2 except at DC and (even length) Nyquist.
double one_sided(std::size_t k, std::size_t m) { return k == 0 || (m % 2 == 0 && k == m / 2) ? 1.0 : 2.0; }
}  // namespace

std::vector<double> SpectrumAverager::amplitude() const {
  std::vector<double> a(sum_.size(), 0.0);
  if (segments_ == 0) return a;
  for (std::size_t k = 0; k < a.size(); ++k)
    a[k] = std::sqrt(sum_[k] / static_cast<double>(segments_)) * one_sided(k, m_) / gain_;
  return a;
}

std::vector<double> SpectrumAverager::psd() const {
  std::vector<double> p(sum_.size(), 0.0);
  if (segments_ == 0) return p;
  for (std::size_t k = 0; k < p.size(); ++k)
    p[k] = sum_[k] * one_sided(k, m_) / (fs_ * power_ * static_cast<double>(segments_));
  return p;
}

std::vector<double> order_axis(std::span<const double> frequency_hz, double crank_speed_rad_s) {
  const double f_crank = std::abs(crank_speed_rad_s) / units::kTwoPi;
  if (!(f_crank > 0) || !std::isfinite(f_crank)) {
    std::ostringstream os;
    os << "order axis: crank speed " << crank_speed_rad_s << " rad/s must be non-zero";
    throw InputError(os.str());
  }
  std::vector<double> o(frequency_hz.size());
  for (std::size_t k = 0; k < o.size(); ++k) o[k] = frequency_hz[k] / f_crank;
  return o;
}

}  // namespace fourbar
