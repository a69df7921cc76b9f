#include "analyze/fftw_plan.hpp"

#include <algorithm>
#include <list>
#include <mutex>
#include <new>

namespace fourbar {

namespace {
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}
}  // namespace

struct RealFft::Plans {
  std::size_t n;
  unsigned flags;
  fftw_plan forward, inverse;
  ~Plans() {
    std::lock_guard lock(planner_mutex());
    fftw_destroy_plan(forward);
    fftw_destroy_plan(inverse);
  }
};

namespace {

// The plans of the last few lengths made, shared by every RealFft of that
// length and flags (executed on each one's own buffers, which fftw_alloc
// aligns alike): FFTW_ESTIMATE planning of a million points costs about
// three transforms (its twiddle factors), and records, chunks and repeated
// analyses in one process reuse a handful of lengths.
class PlanCache {
 public:
  // The planner's mutex is made first, so that it outlives the cache (the
  // plans lock it when the cache is destroyed at exit).
  PlanCache() { planner_mutex(); }
  std::shared_ptr<RealFft::Plans> get(std::size_t n, unsigned flags, double* real, fftw_complex* spec) {
    std::lock_guard lock(mutex_);
    for (auto it = plans_.begin(); it != plans_.end(); ++it)
      if ((*it)->n == n && (*it)->flags == flags) {
        plans_.splice(plans_.begin(), plans_, it);  // most recently used first
        return plans_.front();
      }
    std::shared_ptr<RealFft::Plans> p;
    {
      std::lock_guard plan_lock(planner_mutex());
      const int len = static_cast<int>(n);
      p = std::shared_ptr<RealFft::Plans>(new RealFft::Plans{n, flags, fftw_plan_dft_r2c_1d(len, real, spec, flags),
                                                             fftw_plan_dft_c2r_1d(len, spec, real, flags)});
    }
    plans_.push_front(p);
    if (plans_.size() > kCapacity) plans_.pop_back();
    return p;
  }

 private:
  static constexpr std::size_t kCapacity = 8;
  std::mutex mutex_;
  std::list<std::shared_ptr<RealFft::Plans>> plans_;
};

PlanCache& plan_cache() {
  static PlanCache cache;
  return cache;
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
  plans_ = plan_cache().get(n, flags, real_, spec_);
  // FFTW_MEASURE scribbles on the buffers while planning.
  std::fill(real_, real_ + n, 0.0);
}

RealFft::~RealFft() {
  fftw_free(real_);
  fftw_free(spec_);
}

void RealFft::forward() { fftw_execute_dft_r2c(plans_->forward, real_, spec_); }

void RealFft::inverse() { fftw_execute_dft_c2r(plans_->inverse, spec_, real_); }

std::size_t fast_fft_size(std::size_t n) {
  for (std::size_t m = std::max<std::size_t>(n, 1);; ++m) {
    std::size_t r = m;
    for (std::size_t p : {2, 3, 5, 7})
      while (r % p == 0) r /= p;
    if (r == 1) return m;
  }
}

}  // namespace fourbar
