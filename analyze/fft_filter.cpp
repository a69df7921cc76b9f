#include "analyze/fft_filter.hpp"

#include <algorithm>
#include <cassert>
#include <sstream>

#include "common/error.hpp"

namespace fourbar {

namespace {

// Real response of a centred kernel h[−M..M] on an n-point DFT grid:
// H_k = Σ h[i]·cos(2πki/n), computed by FFT of the kernel wrapped modulo n.
std::vector<double> kernel_response(const std::vector<double>& kernel, RealFft& fft) {
  const std::size_t n = fft.size(), m = kernel.size() / 2;
  auto t = fft.time();
  std::fill(t.begin(), t.end(), 0.0);
  for (std::size_t i = 0; i < kernel.size(); ++i) t[(i + n - m) % n] += kernel[i];
  fft.forward();
  std::vector<double> h(fft.bins());
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = fft.spectrum()[k].real();  // imaginary part is rounding
  return h;
}

std::size_t transform_size(const FilterSpec& spec, double fs, std::size_t length, Boundary boundary) {
  validate_filter(spec, fs);
  if (length == 0) throw InputError("filter: the record is empty");
  const std::size_t period = boundary == Boundary::reflect ? 2 * length : length;
  if (spec.transition_hz == 0) {
    if (boundary == Boundary::zero)
      throw InputError(
          "filter: the ideal (bin-wise) filter acts on the record as one period; for zero boundaries give a "
          "transition width (transition_hz > 0)");
    return period;
  }
  const std::size_t half = kernel_taps(spec, fs) / 2;
  if (boundary == Boundary::zero) return fast_fft_size(length + half);
  if (2 * half + 1 > period) {
    std::ostringstream os;
    os << "filter: the kernel (" << 2 * half + 1 << " taps for a " << spec.transition_hz
       << " Hz transition) is longer than the record (" << length
       << " samples); widen the transition or use zero boundaries / overlap-save";
    throw InputError(os.str());
  }
  return period;
}

}  // namespace

std::vector<double> zero_phase_response(const FilterSpec& spec, double fs, std::size_t n) {
  validate_filter(spec, fs);
  if (spec.transition_hz > 0) {
    RealFft fft(n);
    return kernel_response(design_kernel(spec, fs), fft);
  }
  const std::vector<Band> bands = pass_bands(spec, fs);
  std::vector<double> h(n / 2 + 1);
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = passes(bands, fs * k / n) ? 1.0 : 0.0;
  return h;
}

FftFilter::FftFilter(const FilterSpec& spec, double fs, std::size_t length, Boundary boundary,
                     std::shared_ptr<RealFft> shared)
    : length_(length), reflect_(boundary == Boundary::reflect), zero_(boundary == Boundary::zero) {
  const std::size_t n = transform_size(spec, fs, length, boundary);
  fft_ = shared && shared->size() == n ? std::move(shared) : std::make_shared<RealFft>(n);
  if (spec.transition_hz == 0) {
    response_ = zero_phase_response(spec, fs, n);
  } else {
    response_ = kernel_response(design_kernel(spec, fs), *fft_);
  }
}

void FftFilter::apply(std::span<const double> in, std::span<double> out) {
  assert(out.size() == in.size() && (in.size() == length_ || (zero_ && in.size() <= length_)));
  const std::size_t len = in.size();
  auto t = fft_->time();
  std::copy(in.begin(), in.end(), t.begin());
  if (reflect_) std::reverse_copy(in.begin(), in.end(), t.begin() + len);
  else std::fill(t.begin() + len, t.end(), 0.0);
  filter_buffer();
  std::copy(t.begin(), t.begin() + len, out.begin());
}

void FftFilter::apply_between(std::span<const double> before, std::span<const double> x,
                              std::span<const double> after, std::span<double> out) {
  assert(zero_ && before.size() + x.size() + after.size() <= length_ && out.size() == x.size());
  auto t = fft_->time();
  auto at = std::copy(before.begin(), before.end(), t.begin());
  at = std::copy(x.begin(), x.end(), at);
  at = std::copy(after.begin(), after.end(), at);
  std::fill(at, t.end(), 0.0);
  filter_buffer();
  const auto from = t.begin() + static_cast<std::ptrdiff_t>(before.size());
  std::copy(from, from + static_cast<std::ptrdiff_t>(x.size()), out.begin());
}

void FftFilter::filter_buffer() {
  fft_->forward();
  auto s = fft_->spectrum();
  const double scale = 1.0 / static_cast<double>(fft_->size());
  for (std::size_t k = 0; k < s.size(); ++k) s[k] *= response_[k] * scale;
  fft_->inverse();
}

namespace {
std::size_t overlap_block(const FilterSpec& spec, double fs, std::size_t block) {
  validate_filter(spec, fs);
  if (spec.transition_hz == 0)
    throw InputError("filter: overlap-save needs a windowed kernel; give a transition width (transition_hz > 0)");
  const std::size_t taps = kernel_taps(spec, fs);
  if (block == 0) {
    block = 1024;
    while (block < 4 * (taps - 1)) block *= 2;
  }
  if (block < taps) {
    std::ostringstream os;
    os << "filter: overlap-save block " << block << " is shorter than the kernel (" << taps << " taps)";
    throw InputError(os.str());
  }
  return block;
}
}  // namespace

OverlapSaveFilter::OverlapSaveFilter(const FilterSpec& spec, double fs, std::size_t fft_block)
    : half_(0), fft_(overlap_block(spec, fs, fft_block)) {
  const std::vector<double> kernel = design_kernel(spec, fs);
  half_ = kernel.size() / 2;
  response_ = kernel_response(kernel, fft_);
  window_.assign(half_, 0.0);  // the record is preceded by zeros
  window_.reserve(fft_.size());
}

// Filters the window (zero-filled to the block length); its outputs at
// window positions half_ … are the record outputs emitted_, emitted_ + 1, …
void OverlapSaveFilter::run_block(std::size_t emit, std::vector<double>& out) {
  const std::size_t n = fft_.size();
  auto t = fft_.time();
  std::copy(window_.begin(), window_.end(), t.begin());
  std::fill(t.begin() + window_.size(), t.end(), 0.0);
  fft_.forward();
  auto s = fft_.spectrum();
  const double scale = 1.0 / n;
  for (std::size_t k = 0; k < s.size(); ++k) s[k] *= response_[k] * scale;
  fft_.inverse();
  out.insert(out.end(), t.begin() + half_, t.begin() + half_ + emit);
  emitted_ += emit;
}

void OverlapSaveFilter::push(std::span<const double> in, std::vector<double>& out) {
  const std::size_t n = fft_.size(), hop = n - 2 * half_;
  received_ += in.size();
  while (!in.empty()) {
    const std::size_t take = std::min(in.size(), n - window_.size());
    window_.insert(window_.end(), in.begin(), in.begin() + take);
    in = in.subspan(take);
    if (window_.size() == n) {
      run_block(hop, out);
      window_.erase(window_.begin(), window_.begin() + hop);  // keep the last 2M samples
    }
  }
}

void OverlapSaveFilter::finish(std::vector<double>& out) {
  const std::size_t n = fft_.size(), hop = n - 2 * half_;
  while (emitted_ < received_) {
    // The window holds inputs for outputs emitted_ … ; beyond the record: zeros.
    const std::size_t emit = std::min(hop, received_ - emitted_);
    run_block(emit, out);
    const std::size_t drop = std::min(hop, window_.size());
    window_.erase(window_.begin(), window_.begin() + drop);
  }
  window_.assign(half_, 0.0);
  received_ = emitted_ = 0;
}

}  // namespace fourbar
