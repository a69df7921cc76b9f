#include "analyze/fftw_plan.hpp"

#include <algorithm>
#include <mutex>
#include <new>

namespace fourbar {

namespace {
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

RealFft::RealFft(std::size_t n, unsigned flags) : n_(n) {
  real_ = fftw_alloc_real(n);
  spec_ = fftw_alloc_complex(n / 2 + 1);
  if (real_ == nullptr || spec_ == nullptr) {
    fftw_free(real_);
    fftw_free(spec_);
    throw std::bad_alloc();
  }
  std::lock_guard lock(planner_mutex());
  const int len = static_cast<int>(n);
  forward_ = fftw_plan_dft_r2c_1d(len, real_, spec_, flags);
  inverse_ = fftw_plan_dft_c2r_1d(len, spec_, real_, flags);
  // FFTW_MEASURE scribbles on the buffers while planning.
  std::fill(real_, real_ + n, 0.0);
}

RealFft::~RealFft() {
  {
    std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(forward_);
    fftw_destroy_plan(inverse_);
  }
  fftw_free(real_);
  fftw_free(spec_);
}

std::size_t fast_fft_size(std::size_t n) {
  for (std::size_t m = std::max<std::size_t>(n, 1);; ++m) {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

}  // namespace fourbar
