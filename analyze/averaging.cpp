#include "analyze/averaging.hpp"

#include <cassert>
#include <cmath>
#include <sstream>

#include "common/error.hpp"

namespace fourbar {

SynchronousAverager::SynchronousAverager(std::size_t n) : n_(n), mean_(n, 0.0), m2_(n, 0.0) {}

void SynchronousAverager::add(std::span<const double> rev) {
  assert(rev.size() == n_);
  ++count_;
  const double inv = 1.0 / static_cast<double>(count_);
  for (std::size_t k = 0; k < n_; ++k) {
    const double d = rev[k] - mean_[k];
    mean_[k] += d * inv;
    m2_[k] += d * (rev[k] - mean_[k]);
  }
}

AngleAverage SynchronousAverager::result() const {
  AngleAverage a;
  a.revolutions = count_;
  a.mean = mean_;
  a.std.assign(n_, 0.0);
  if (count_ > 1)
    for (std::size_t k = 0; k < n_; ++k) a.std[k] = std::sqrt(m2_[k] / static_cast<double>(count_ - 1));
  return a;
}

AngleAverage synchronous_average(std::span<const double> revs, std::size_t n) {
  if (n == 0 || revs.size() % n != 0 || revs.empty()) {
    std::ostringstream os;
    os << "averaging: " << revs.size() << " values are not a whole number of revolutions of " << n << " angles";
    throw InputError(os.str());
  }
  SynchronousAverager avg(n);
  for (std::size_t r = 0; r < revs.size() / n; ++r) avg.add(revs.subspan(r * n, n));
  return avg.result();
}

}  // namespace fourbar
